// Test helpers: reading the committed reference tables of tests/data/.
#ifndef GRADCONTACT_TESTS_ANALYTIC_REFERENCE_TABLE_H
#define GRADCONTACT_TESTS_ANALYTIC_REFERENCE_TABLE_H

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gradcontact::testing
{
  inline std::string data_path(const std::string &file) { return std::string(GRADCONTACT_DATA_DIR) + "/" + file; }

  /// The rows of a CSV file (header skipped), split at commas.
  inline std::vector<std::vector<std::string>> read_csv(const std::string &file)
  {
    std::ifstream in(data_path(file));
    if (!in)
      throw std::runtime_error("cannot open reference table " + data_path(file));
    std::vector<std::vector<std::string>> rows;
    std::string line;
    std::getline(in, line); // header
    while (std::getline(in, line))
      {
        if (line.empty())
          continue;
        std::vector<std::string> fields;
        std::stringstream s(line);
        std::string field;
        while (std::getline(s, field, ','))
          fields.push_back(field);
        rows.push_back(fields);
      }
    return rows;
  }

  /// Relative error |value/reference - 1|, or the absolute error where the reference is 0.
  inline double relative_error(const double value, const double reference)
  {
    return reference == 0. ? std::abs(value) : std::abs(value - reference) / std::abs(reference);
  }
} // namespace gradcontact::testing

#endif
