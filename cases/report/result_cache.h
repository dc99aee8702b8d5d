// gradcontact/cases: a folder of computed results (JSON) keyed by what determines them: the full request text
// (e.g. a scene's resolved parameters and the point asked) and the program's build, so that a rebuilt model
// recomputes. Used by the figures' FE points and the Tabor-parameter map's points (its --map-shard jobs fill
// it, the assembling run reads it).
#ifndef GRADCONTACT_CASES_RESULT_CACHE_H
#define GRADCONTACT_CASES_RESULT_CACHE_H

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace gradcontact::cases
{
  class ResultCache
  {
  public:
    /// `enabled` false: get() finds nothing (every result is recomputed, and stored).
    ResultCache(std::filesystem::path folder, bool enabled = true);

    /// The stored value of `key` (this build's), or nothing. An unreadable entry counts as none.
    std::optional<nlohmann::json> get(const std::string &key) const;
    /// Stores `value` under `key` (written under a temporary name, then renamed).
    void put(const std::string &key, const nlohmann::json &value) const;

    bool enabled() const { return enabled_; }
    const std::filesystem::path &folder() const { return folder_; }

  private:
    std::string           full_key(const std::string &key) const;
    std::filesystem::path file(const std::string &full) const;

    std::filesystem::path folder_;
    bool                  enabled_;
  };
} // namespace gradcontact::cases

#endif
