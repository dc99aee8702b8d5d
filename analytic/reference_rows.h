// gradcontact/analytic: the rows of a reference table of eval requests (tests/data/references.jsonl: 34-digit
// values of the MDR integrals by an independent mpmath evaluation). A row is a request of analytic/README.md plus
// the table's own columns, which are split off here so that no reader hands them to batch::parse.
#ifndef GRADCONTACT_ANALYTIC_REFERENCE_ROWS_H
#define GRADCONTACT_ANALYTIC_REFERENCE_ROWS_H

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gradcontact::batch
{
  struct ReferenceRow
  {
    nlohmann::json request;   ///< the eval request (with its "id"), without the columns below
    double         reference = 0;    ///< the high-precision value, rounded to double
    double         conditioning = 0; ///< relative change of the reference under half-ulp moves of the inputs
    std::string    group;            ///< the table's group of the row
  };

  /// Every row of `file` (blank lines skipped); std::runtime_error when it cannot be opened.
  inline std::vector<ReferenceRow> read_reference_rows(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("cannot open the reference table '" + file + "'");
    std::vector<ReferenceRow> rows;
    for (std::string line; std::getline(in, line);)
      {
        if (line.empty())
          continue;
        ReferenceRow row;
        row.request      = nlohmann::json::parse(line);
        row.reference    = std::stod(row.request.at("reference").get<std::string>());
        row.conditioning = row.request.value("conditioning", 0.);
        row.group        = row.request.value("group", "");
        for (const char *column : {"reference", "group", "conditioning"})
          row.request.erase(column);
        rows.push_back(std::move(row));
      }
    return rows;
  }
} // namespace gradcontact::batch

#endif
