#include "report/map_pipeline.h"

#include "report/result_cache.h"

#include <stdexcept>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;

  void MapStrategy::open_panel(std::size_t, SceneResult &, bool) {}

  std::optional<MapPointKey> MapStrategy::point_key(std::size_t, std::size_t) const { return std::nullopt; }

  nlohmann::json MapStrategy::stored(std::size_t, std::size_t) const
  {
    throw std::logic_error("MapStrategy::stored: this map's points have no key, so none is stored");
  }

  void MapStrategy::restore(std::size_t, std::size_t, const nlohmann::json &)
  {
    throw std::logic_error("MapStrategy::restore: this map's points have no key, so none is restored");
  }

  namespace
  {
    /// One point: read from the cache when its key is there, else solved here when it is this job's (and then
    /// stored), else left to another job.
    void run_point(MapStrategy &map, const MapRun &run, const ResultCache &cache, const std::size_t panel,
                   const std::size_t point, const bool mine, MapShard &shard, SceneResult &result)
    {
      const std::optional<MapPointKey> key = map.point_key(panel, point);
      if (!key)
        {
          if (shard.count > 1)
            throw std::invalid_argument("run_map: a map whose points are not cached cannot be split in shards");
          map.solve(panel, point, result, run.verbose);
          ++shard.computed;
          return;
        }
      const std::string text = key->kind + "\n" + run.resolved + "\n" + key->point;
      if (const auto cached = cache.get(text))
        {
          map.restore(panel, point, *cached);
          ++shard.cached;
          return;
        }
      if (!mine)
        {
          ++shard.skipped;
          return;
        }
      map.solve(panel, point, result, run.verbose);
      ++shard.computed;
      cache.put(text, map.stored(panel, point));
    }
  } // namespace

  void run_map(MapStrategy &map, const MapRun &run, MapShard &shard, SceneResult &result)
  {
    if (shard.count == 0 || shard.index >= shard.count)
      throw std::invalid_argument("run_map: shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) +
                                  " is not i/N with 0 <= i < N");
    const ResultCache cache(run.folder.parent_path() / ".map-points");
    std::size_t       index = 0; // of the point in the map's order
    for (std::size_t panel = 0; panel < map.panels(); ++panel)
      {
        map.open_panel(panel, result, run.verbose);
        for (std::size_t point = 0; point < map.points(panel); ++point, ++index)
          run_point(map, run, cache, panel, point, index % shard.count == shard.index, shard, result);
        map.close_panel(panel, run.folder, result, run.verbose);
      }
    // A shard's report is partial and discarded: its points are in the cache, no map or plot is drawn for it.
    if (!map.writes_report() || shard.count > 1)
      return;
    const MapReport report = map.report(run.folder, run.plots);
    write_table_files(run.folder, "map", report.csv, report.md);
    if (run.plots)
      map.plot(run.folder);
  }

  void run_map(MapStrategy &map, const MapRun &run, SceneResult &result)
  {
    MapShard all;
    run_map(map, run, all, result);
  }
} // namespace gradcontact::cases
