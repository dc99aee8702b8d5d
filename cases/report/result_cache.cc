#include "report/result_cache.h"

#include "report/report.h"

#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using json = nlohmann::json;

  namespace
  {
    // This program's file, size and modification time: a rebuilt program has another.
    std::string build_id()
    {
      std::error_code ec;
      const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
      if (ec)
        return "unknown build";
      const auto size = fs::file_size(exe, ec);
      const auto time = fs::last_write_time(exe, ec).time_since_epoch().count();
      return exe.string() + " " + std::to_string(size) + " " + std::to_string(time);
    }
  } // namespace

  ResultCache::ResultCache(fs::path folder, const bool enabled) : folder_(std::move(folder)), enabled_(enabled) {}

  std::string ResultCache::full_key(const std::string &key) const { return build_id() + "\n" + key; }

  fs::path ResultCache::file(const std::string &full) const
  {
    std::ostringstream name;
    name << std::hex << std::setw(16) << std::setfill('0') << std::hash<std::string>{}(full) << ".json";
    return folder_ / name.str();
  }

  std::optional<json> ResultCache::get(const std::string &key) const
  {
    if (!enabled_)
      return std::nullopt;
    const std::string full = full_key(key);
    const fs::path    f    = file(full);
    if (!fs::exists(f))
      return std::nullopt;
    try
      {
        std::ifstream in(f);
        const json    j = json::parse(in);
        if (j.at("key") == full) // the full key is stored: a hash collision recomputes
          return j.at("value");
      }
    catch (const json::exception &)
      {
        // an unreadable entry is recomputed and replaced
      }
    return std::nullopt;
  }

  void ResultCache::put(const std::string &key, const json &value) const
  {
    const std::string full = full_key(key);
    fs::create_directories(folder_);
    const fs::path target = file(full), tmp = temporary_sibling(target);
    {
      std::ofstream out(tmp);
      out << json{{"key", full}, {"value", value}}.dump();
      if (!out)
        throw std::runtime_error("cannot write " + tmp.string());
    }
    fs::rename(tmp, target);
  }
} // namespace gradcontact::cases
