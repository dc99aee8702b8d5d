// Scenes for the tests of cases/: a scene file of defaults in a temporary folder, varied by the same
// `Section/key=value` overrides as `gradcontact run --set` (a variant is an override, not a copied file).
#ifndef GRADCONTACT_TESTS_CASES_SCENE_FILES_H
#define GRADCONTACT_TESTS_CASES_SCENE_FILES_H

#include <cases/scene/scene.h>

#include <filesystem>
#include <string>
#include <vector>

namespace gradcontact::cases::testing
{
  /// A fresh empty folder under the system's temporary folder, removed by the destructor.
  class TemporaryFolder
  {
  public:
    explicit TemporaryFolder(const std::string &stem);
    ~TemporaryFolder();
    TemporaryFolder(const TemporaryFolder &) = delete;
    TemporaryFolder &operator=(const TemporaryFolder &) = delete;
    const std::filesystem::path &path() const { return folder; }

  private:
    std::filesystem::path folder;
  };

  /// The scene of every default entry with `overrides` ("Section/key=value") applied.
  Scene scene_with(const std::vector<std::string> &overrides);

  /// The whole text of `file`.
  std::string read_text(const std::filesystem::path &file);

  /// The rows of a CSV file (header included), split at commas outside double quotes.
  std::vector<std::vector<std::string>> read_csv(const std::filesystem::path &file);
} // namespace gradcontact::cases::testing

#endif
