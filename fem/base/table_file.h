// Two-column tables read from text files: a measured modulus E(z), a measured indenter profile f(r).
//
// One row per line, two numbers separated by a comma and/or blanks; blank lines and lines starting with '#'
// are skipped, and the first other line may be a header ("z,E", "r_m,f_m", ...). Anything else is an error
// naming the file and the line.
#ifndef GRADCONTACT_FEM_TABLE_FILE_H
#define GRADCONTACT_FEM_TABLE_FILE_H

#include <string>
#include <vector>

namespace gradcontact::fem
{
  struct TableFile
  {
    std::vector<double> x, y;
    std::vector<unsigned int> line; ///< the file's line of each row, for messages
  };

  /// The rows of `file`; `who` starts every error message (e.g. "TabulatedModulus::from_csv"), `x_name` and
  /// `y_name` name the columns in it. Throws std::invalid_argument when the file cannot be read or a line is
  /// not two numbers. The values are not checked beyond that.
  TableFile read_table_file(const std::string &file, const std::string &who, const std::string &x_name,
                            const std::string &y_name);
} // namespace gradcontact::fem

#endif
