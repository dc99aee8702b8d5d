// gradcontact/analytic: argument checks shared by every public function.
//
// Public functions check, detail:: functions compute. A failed check throws
// DomainError whose message names the function, the argument, its value and the valid range,
// e.g. "paraboloid_force: k = 1.5 is outside (-1, 1)". NaN is tested first, then the range.
#ifndef GRADCONTACT_ANALYTIC_ERRORS_H
#define GRADCONTACT_ANALYTIC_ERRORS_H

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace gradcontact
{
  /// A parameter outside the domain where the formula (or the physics) holds.
  class DomainError : public std::domain_error
  {
  public:
    using std::domain_error::domain_error;
  };

  namespace check
  {
    /// The shortest of 15 or 17 significant digits that reads back as the same double.
    /// The keys of a map, comma-separated: the valid choices a message lists.
    template <typename Map>
    std::string keys(const Map &map)
    {
      std::string s;
      for (const auto &entry : map)
        s += (s.empty() ? "" : ", ") + entry.first;
      return s;
    }

    inline std::string format(const double x)
    {
      for (const int digits : {15, 17})
        {
          std::ostringstream s;
          s.precision(digits);
          s << x;
          if (digits == 17 || std::stod(s.str()) == x)
            return s.str();
        }
      return {};
    }

    [[noreturn]] inline void fail(const char *function, const char *name, const double value,
                                  const std::string &range)
    {
      throw DomainError(std::string(function) + ": " + name + " = " + format(value) + " " + range);
    }

    inline void finite(const char *function, const char *name, const double value)
    {
      if (std::isnan(value))
        fail(function, name, value, "is not a number (must be finite)");
      if (!std::isfinite(value))
        fail(function, name, value, "is not finite");
    }

    /// value > 0 and finite
    inline void positive(const char *function, const char *name, const double value)
    {
      finite(function, name, value);
      if (!(value > 0))
        fail(function, name, value, "must be > 0");
    }

    /// value >= 0 and finite
    inline void non_negative(const char *function, const char *name, const double value)
    {
      finite(function, name, value);
      if (!(value >= 0))
        fail(function, name, value, "must be >= 0");
    }

    /// lo < value < hi
    inline void open_interval(const char *function, const char *name, const double value,
                              const double lo, const double hi)
    {
      finite(function, name, value);
      if (!(value > lo && value < hi))
        fail(function, name, value, "is outside (" + format(lo) + ", " + format(hi) + ")");
    }

    /// lo <= value <= hi
    inline void closed_interval(const char *function, const char *name, const double value,
                                const double lo, const double hi)
    {
      finite(function, name, value);
      if (!(value >= lo && value <= hi))
        fail(function, name, value, "is outside [" + format(lo) + ", " + format(hi) + "]");
    }
  } // namespace check
} // namespace gradcontact

#endif
