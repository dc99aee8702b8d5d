// gradcontact/cases: the expression language of a scene's candidate closed forms.
//
// A candidate is written as a formula of its variables (r, a, d, F, c, Fx, FA, ...), of named constants (the
// chapter's coefficients, the user's own) and of functions, the special functions of graded contact among them:
// the gamma and beta functions that build the chapter's coefficients (9.5, 9.79), the regularised incomplete beta
// function and Gauss's hypergeometric function 2F1 that the pressure and displacement integrals of a rounded or
// power-law profile lead to, and the complete elliptic integrals of the classical limit.
//
// The grammar, loosest binding first:
//   c ? x : y      conditional
//   x || y         or;  x && y   and            (a number is true when it is not 0; a truth is 1 or 0)
//   == != < <= > >=                              comparison
//   + -            sum;  * /  product
//   -x  +x  !x     unary signs and not
//   x ^ y          power, right-associative: -x^2 = -(x^2), 2^3^2 = 2^9, x^-1 allowed
//   number, name, name(argument, ...), (x)
// A name followed by '(' is a function, any other name a variable or a constant, so beta (the constant of 9.5)
// and beta(p, q) (the function) do not collide. Every error names the column where it starts (1-based).
//
// The functions are evaluated in double precision by the standard library and Boost.Math. A value that is not a
// finite number (sqrt(-1), a domain error of a special function, an overflow) is an error naming the expression
// and the point, never a silent NaN.
#ifndef GRADCONTACT_CASES_EXPRESSION_H
#define GRADCONTACT_CASES_EXPRESSION_H

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// Levenshtein distance of two names, case-insensitive: what "did you mean" messages choose by.
  std::size_t edit_distance(const std::string &a, const std::string &b);

  /// A syntax or name error: what went wrong and the 1-based column where it starts.
  class ExpressionError : public std::invalid_argument
  {
  public:
    ExpressionError(const std::string &what, unsigned int column);
    unsigned int column() const { return column_; }

  private:
    unsigned int column_;
  };

  /// A compiled expression. Immutable after construction, so one object may be evaluated from many threads.
  class Expression
  {
  public:
    /// Parses `text` over `variables` (the order of the arguments of value) and `constants`, whose values are
    /// bound at construction. A variable hides a constant of the same name. Throws ExpressionError.
    Expression(const std::string &text, const std::vector<std::string> &variables,
               const std::map<std::string, double> &constants);

    /// The value at `x` (one number per variable). Throws std::domain_error naming the point when the result, or
    /// a function on the way, is not a finite number.
    double value(const std::vector<double> &x) const;
    double value(const double *x) const;

    const std::string &text() const { return text_; }
    const std::vector<std::string> &variables() const { return variables_; }

    /// One line per function: its signature and what it is, for --help-scene and for error messages.
    static std::string function_list();
    /// The functions' names, comma-separated.
    static std::string function_names();

    /// One node of the expression's tree; the nodes are stored in one vector and refer to their operands by index.
    struct Node
    {
      enum class Kind
      {
        number,
        variable,
        function,
        negate,
        logical_not,
        binary,
        conditional
      };
      explicit Node(const Kind kind)
        : kind(kind)
      {}
      Kind kind;
      double number     = 0;   // number
      unsigned int slot = 0;   // variable: its index; function: its index in the table; binary: the operator
      std::vector<int> operands;
      unsigned int column = 0;
    };

  private:
    double evaluate(int node, const double *x) const;

    std::string text_;
    std::vector<std::string> variables_;
    std::vector<Node> nodes_;
    int root_ = -1;
  };
} // namespace gradcontact::cases

#endif
