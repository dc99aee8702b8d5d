#include "scene_files.h"

#include <fstream>
#include <iterator>
#include <random>
#include <unistd.h>

namespace gradcontact::cases::testing
{
  namespace fs = std::filesystem;

  TemporaryFolder::TemporaryFolder(const std::string &stem)
  {
    std::random_device seed;
    folder = fs::temp_directory_path() /
             (stem + "-" + std::to_string(::getpid()) + "-" + std::to_string(std::uniform_int_distribution<>(0, 1 << 30)(seed)));
    fs::remove_all(folder);
    fs::create_directories(folder);
  }

  TemporaryFolder::~TemporaryFolder()
  {
    std::error_code ignored;
    fs::remove_all(folder, ignored);
  }

  Scene scene_with(const std::vector<std::string> &overrides)
  {
    const TemporaryFolder folder("gradcontact-scene");
    const fs::path file = folder.path() / "defaults.prm";
    std::ofstream(file) << "# every entry at its default\n";
    std::vector<Override> parsed;
    for (const std::string &o : overrides)
      parsed.push_back(parse_override(o));
    return read_scene(file.string(), parsed);
  }

  std::string read_text(const fs::path &file)
  {
    std::ifstream in(file);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }

  std::vector<std::vector<std::string>> read_csv(const fs::path &file)
  {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
      {
        std::vector<std::string> fields(1);
        bool quoted = false;
        for (const char c : line)
          if (c == '"')
            quoted = !quoted;
          else if (c == ',' && !quoted)
            fields.emplace_back();
          else
            fields.back() += c;
        rows.push_back(fields);
      }
    return rows;
  }
} // namespace gradcontact::cases::testing
