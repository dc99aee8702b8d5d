// gradcontact/fem: the error of a parameter outside its range, shared by every fem source.
#ifndef GRADCONTACT_FEM_ERRORS_H
#define GRADCONTACT_FEM_ERRORS_H

#include <sstream>
#include <stdexcept>
#include <string>

namespace gradcontact::fem
{
  /// Throws std::invalid_argument "<where>: <what> = <value> outside <range>" (17 digits).
  [[noreturn]] inline void fail(const std::string &where, const std::string &what, const double value,
                                const std::string &range)
  {
    std::ostringstream msg;
    msg.precision(17);
    msg << where << ": " << what << " = " << value << " outside " << range;
    throw std::invalid_argument(msg.str());
  }
} // namespace gradcontact::fem

#endif
