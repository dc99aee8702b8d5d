#include <fem/base/table_file.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  TableFile read_table_file(const std::string &file, const std::string &who, const std::string &x_name,
                            const std::string &y_name)
  {
    std::ifstream in(file);
    if (!in)
      throw std::invalid_argument(who + ": cannot open \"" + file + "\"");
    TableFile   table;
    std::string line;
    bool        header_allowed = true;
    for (unsigned int line_number = 1; std::getline(in, line); ++line_number)
      {
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#')
          continue;
        std::string fields = line;
        std::replace(fields.begin(), fields.end(), ',', ' ');
        std::istringstream row(fields);
        double             x = 0, y = 0;
        std::string        rest;
        const bool         numeric = static_cast<bool>(row >> x >> y) && !(row >> rest);
        if (!numeric)
          {
            if (header_allowed)
              {
                header_allowed = false;
                continue;
              }
            throw std::invalid_argument(who + ": \"" + file + "\" line " + std::to_string(line_number) + ": \"" + line +
                                        "\" is not two numbers " + x_name + ", " + y_name);
          }
        header_allowed = false;
        table.x.push_back(x);
        table.y.push_back(y);
        table.line.push_back(line_number);
      }
    return table;
  }
} // namespace gradcontact::fem
