#include "scene_files.h"

#include <fstream>
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
} // namespace gradcontact::cases::testing
