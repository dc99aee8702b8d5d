// gradcontact/cases: the one pipeline of every applicability map: plan -> solve (cached) -> rows -> tables -> plots.
//
// A map is a list of panels (an exponent k, a body (k, nu), ...), each a list of points (a ratio a/z0, an indenter
// modulus, a friction coefficient, a Tabor parameter, ...). The map kinds differ in what a panel shares, how a point
// is solved and what its rows, tables and plots are: each kind is a MapStrategy, chosen once from the scene
// (runners/run_scene.cc), and run_map drives every strategy the same way:
//   for every panel: open_panel (what its points share: a mesh, a solver, its sharp checks), every point solved
//   (or read from the point cache, or left to another shard), close_panel (the panel's rows of errors.csv, map.csv
//   and its section of map.md);
//   then map.csv and map.md from the strategy's column spec and document (write_table_files), and its plots.
// The driver knows no scene: the runner hands it the scene's resolved parameters, which key the point cache, and
// whether plots are asked.
#ifndef GRADCONTACT_CASES_MAP_PIPELINE_H
#define GRADCONTACT_CASES_MAP_PIPELINE_H

#include "report/report.h"
#include "report/table.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace gradcontact::cases
{
  /// The points of a map that one job computes: those at positions j (in the map's order: panels, then their points)
  /// with j % count == index; the counts of the run.
  struct MapShard
  {
    unsigned int index = 0, count = 1;
    unsigned int computed = 0, cached = 0, skipped = 0; ///< solved here, read from the point cache, left to others
  };

  /// What names a point in the point cache, beside the scene's resolved parameters and the program's build: the
  /// map's kind and the point (its panel and value, written exactly).
  struct MapPointKey
  {
    std::string kind, point;
  };

  /// A map's table (map.csv, and its panels in map.md) and its whole document (map.md).
  struct MapReport
  {
    Table       csv;
    std::string md;
  };

  /// One kind of map: its plan, its solve of one point, and what its solved points become.
  class MapStrategy
  {
  public:
    virtual ~MapStrategy() = default;

    /// The plan: the panels, and the points of each, in the map's order.
    virtual std::size_t panels() const = 0;
    virtual std::size_t points(std::size_t panel) const = 0;

    /// Before the points of `panel`: what they share, and the panel's sharp checks. Nothing by default.
    virtual void open_panel(std::size_t panel, SceneResult &result, bool verbose);
    /// The key of a point in the point cache; none (the default): the point is solved on every run.
    virtual std::optional<MapPointKey> point_key(std::size_t panel, std::size_t point) const;
    /// Solves one point (a failure the strategy reports in its rows rather than throws).
    virtual void solve(std::size_t panel, std::size_t point, SceneResult &result, bool verbose) = 0;
    /// A solved point as the cache stores it, and a point restored from it: called only for points with a key.
    virtual nlohmann::json stored(std::size_t panel, std::size_t point) const;
    virtual void           restore(std::size_t panel, std::size_t point, const nlohmann::json &value);
    /// After the points of `panel` (solved or read; one left to another shard is neither): its rows of errors.csv and
    /// map.csv and its section of map.md. `folder` takes a panel's tables of its own (write_table_csv).
    virtual void close_panel(std::size_t panel, const std::filesystem::path &folder, SceneResult &result,
                             bool verbose) = 0;

    /// map.csv and map.md; may write the map's further tables of its own into `folder` (`plots`: and their plots).
    virtual MapReport report(const std::filesystem::path &folder, bool plots) = 0;
    /// The plots of the map (map-<quantity>.png, ...).
    virtual void plot(const std::filesystem::path &folder) = 0;
    /// Whether this process writes the report (false: an MPI process other than the root, whose rows are the same).
    virtual bool writes_report() const { return true; }
  };

  /// How a map runs: where, keyed by what, which of its points, and what it writes.
  struct MapRun
  {
    std::filesystem::path folder;   ///< the report's (temporary) folder; the point cache is <its parent>/.map-points
    std::string           resolved; ///< the scene's resolved parameters (the point cache's key)
    bool                  plots   = true;
    bool                  verbose = false;
  };

  /// Runs `map`: every panel and point in order, rows into `result`, and (unless the map's process writes no report
  /// or `shard` is one job of several, whose report would be partial) map.csv, map.md and the plots into run.folder. Points
  /// with a key are read from the point cache when there and stored in it when solved; with shard.count > 1 only
  /// the points j % count == index are solved, the others read from the cache or left out. Throws
  /// std::invalid_argument for a shard that is not i/N with 0 <= i < N, or a shard of a map whose points are not
  /// cached.
  void run_map(MapStrategy &map, const MapRun &run, MapShard &shard, SceneResult &result);
  /// The same with every point solved here (one job).
  void run_map(MapStrategy &map, const MapRun &run, SceneResult &result);
} // namespace gradcontact::cases

#endif
