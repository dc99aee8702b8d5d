#include "scene/expression.h"

#include <boost/math/special_functions/beta.hpp>
#include <boost/math/special_functions/digamma.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/special_functions/hypergeometric_pFq.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>

namespace gradcontact::cases
{
  namespace
  {
    using Arguments = const double *;

    /// Gauss's hypergeometric function 2F1(a, b; c; z) for real z <= 1. z < 0 goes through Pfaff's transformation
    /// 2F1(a, b; c; z) = (1 - z)^(-a) 2F1(a, c - b; c; z / (z - 1)) (Abramowitz & Stegun 15.3.4), which maps it
    /// into [0, 1) where the series converges; z = 1 is Gauss's sum Gamma(c) Gamma(c - a - b) /
    /// (Gamma(c - a) Gamma(c - b)) (A&S 15.1.20), valid for c - a - b > 0.
    double hyp2f1(const double a, const double b, const double c, const double z)
    {
      if (c <= 0 && c == std::floor(c))
        throw std::domain_error("hyp2f1: c = " + std::to_string(c) + " is a non-positive integer");
      if (z > 1)
        throw std::domain_error("hyp2f1: z = " + std::to_string(z) + " > 1, where 2F1 is complex");
      if (z == 1)
        {
          if (c - a - b <= 0)
            throw std::domain_error("hyp2f1 at z = 1 diverges unless c - a - b > 0");
          const auto reciprocal_gamma = [](const double x) {
            return x <= 0 && x == std::floor(x) ? 0.0 : 1 / boost::math::tgamma(x);
          };
          return boost::math::tgamma(c) * boost::math::tgamma(c - a - b) * reciprocal_gamma(c - a) *
                 reciprocal_gamma(c - b);
        }
      if (z < 0)
        return std::pow(1 - z, -a) *
               boost::math::hypergeometric_pFq({a, c - b}, {c}, z / (z - 1));
      return boost::math::hypergeometric_pFq({a, b}, {c}, z);
    }

    struct Function
    {
      const char *name;
      unsigned int least, most; // the number of arguments
      double (*f)(Arguments, unsigned int);
      const char *help;
    };

#define GRADCONTACT_UNARY(name, expression) \
  { \
#name, 1, 1, [](Arguments x, unsigned int) { return static_cast<double>(expression); }, nullptr \
  }

    // `if` and the operators ?:, && and || are evaluated lazily by Expression::evaluate, so a guarded branch that
    // would not be finite (if(r < a, sqrt(a^2 - r^2), 0)) is never computed; the entry here holds its help.
    const Function functions[] = {
      {"if", 3, 3, nullptr, "if(c, x, y): x where c is not 0, else y (only the chosen branch is evaluated)"},
      GRADCONTACT_UNARY(sqrt, std::sqrt(x[0])),
      GRADCONTACT_UNARY(cbrt, std::cbrt(x[0])),
      GRADCONTACT_UNARY(exp, std::exp(x[0])),
      GRADCONTACT_UNARY(log, std::log(x[0])),
      GRADCONTACT_UNARY(ln, std::log(x[0])),
      GRADCONTACT_UNARY(log10, std::log10(x[0])),
      GRADCONTACT_UNARY(log2, std::log2(x[0])),
      GRADCONTACT_UNARY(sin, std::sin(x[0])),
      GRADCONTACT_UNARY(cos, std::cos(x[0])),
      GRADCONTACT_UNARY(tan, std::tan(x[0])),
      GRADCONTACT_UNARY(asin, std::asin(x[0])),
      GRADCONTACT_UNARY(acos, std::acos(x[0])),
      GRADCONTACT_UNARY(atan, std::atan(x[0])),
      GRADCONTACT_UNARY(sinh, std::sinh(x[0])),
      GRADCONTACT_UNARY(cosh, std::cosh(x[0])),
      GRADCONTACT_UNARY(tanh, std::tanh(x[0])),
      GRADCONTACT_UNARY(asinh, std::asinh(x[0])),
      GRADCONTACT_UNARY(acosh, std::acosh(x[0])),
      GRADCONTACT_UNARY(atanh, std::atanh(x[0])),
      GRADCONTACT_UNARY(abs, std::abs(x[0])),
      GRADCONTACT_UNARY(sign, (x[0] > 0) - (x[0] < 0)),
      GRADCONTACT_UNARY(floor, std::floor(x[0])),
      GRADCONTACT_UNARY(ceil, std::ceil(x[0])),
      GRADCONTACT_UNARY(round, std::round(x[0])),
      GRADCONTACT_UNARY(erf, boost::math::erf(x[0])),
      GRADCONTACT_UNARY(erfc, boost::math::erfc(x[0])),
      {"atan2", 2, 2, [](Arguments x, unsigned int) { return std::atan2(x[0], x[1]); },
       "atan2(y, x): the angle of the point (x, y)"},
      {"pow", 2, 2, [](Arguments x, unsigned int) { return std::pow(x[0], x[1]); }, "pow(x, y) = x^y"},
      {"hypot", 2, 2, [](Arguments x, unsigned int) { return std::hypot(x[0], x[1]); }, "hypot(x, y) = sqrt(x^2 + y^2)"},
      {"min", 2, 64, [](Arguments x, unsigned int n) { return *std::min_element(x, x + n); },
       "min(x, y, ...): the least argument"},
      {"max", 2, 64, [](Arguments x, unsigned int n) { return *std::max_element(x, x + n); },
       "max(x, y, ...): the largest argument"},
      {"gamma", 1, 1, [](Arguments x, unsigned int) { return boost::math::tgamma(x[0]); },
       "gamma(x): Euler's gamma function"},
      {"lgamma", 1, 1, [](Arguments x, unsigned int) { return boost::math::lgamma(x[0]); },
       "lgamma(x) = log|gamma(x)|"},
      {"digamma", 1, 1, [](Arguments x, unsigned int) { return boost::math::digamma(x[0]); },
       "digamma(x) = gamma'(x) / gamma(x)"},
      {"beta", 2, 2, [](Arguments x, unsigned int) { return boost::math::beta(x[0], x[1]); },
       "beta(p, q) = gamma(p) gamma(q) / gamma(p + q); the name alone is the constant beta of 9.5"},
      {"ibeta", 3, 3, [](Arguments x, unsigned int) { return boost::math::ibeta(x[0], x[1], x[2]); },
       "ibeta(p, q, x): the regularised incomplete beta function I_x(p, q), 0 <= x <= 1"},
      {"hyp2f1", 4, 4, [](Arguments x, unsigned int) { return hyp2f1(x[0], x[1], x[2], x[3]); },
       "hyp2f1(a, b, c, z): Gauss's hypergeometric function 2F1(a, b; c; z), z <= 1"},
      {"ellint_1", 1, 2,
       [](Arguments x, unsigned int n) {
         return n == 1 ? boost::math::ellint_1(x[0]) : boost::math::ellint_1(x[0], x[1]);
       },
       "ellint_1(k[, phi]): the elliptic integral of the first kind of modulus k, complete K(k) without phi"},
      {"ellint_2", 1, 2,
       [](Arguments x, unsigned int n) {
         return n == 1 ? boost::math::ellint_2(x[0]) : boost::math::ellint_2(x[0], x[1]);
       },
       "ellint_2(k[, phi]): the elliptic integral of the second kind of modulus k, complete E(k) without phi"},
    };
#undef GRADCONTACT_UNARY

    constexpr unsigned int n_functions = sizeof(functions) / sizeof(functions[0]);

    enum Operator : unsigned int
    {
      add,
      subtract,
      multiply,
      divide,
      power,
      less,
      less_equal,
      greater,
      greater_equal,
      equal,
      not_equal,
      logical_and,
      logical_or
    };

    std::string format(const double x)
    {
      std::ostringstream s;
      s.precision(17);
      s << x;
      return s.str();
    }

    /// Recursive descent over the text, one level per row of the grammar in expression.h; each level appends its
    /// nodes to `nodes` and returns the index of its root.
    class Parser
    {
    public:
      Parser(const std::string &text, const std::vector<std::string> &variables,
             const std::map<std::string, double> &constants, std::vector<Expression::Node> &nodes)
        : text(text)
        , variables(variables)
        , constants(constants)
        , nodes(nodes)
      {}

      int parse()
      {
        skip_space();
        if (at_end())
          throw ExpressionError("the expression is empty", 1);
        const int root = conditional();
        if (!at_end())
          fail("unexpected '" + std::string(1, text[position]) + "'" +
               (text[position] == ')' ? " (a ')' without its '(')" : ""));
        return root;
      }

    private:
      [[noreturn]] void fail(const std::string &what) const { fail_at(what, position); }
      [[noreturn]] void fail_at(const std::string &what, const std::size_t at) const
      {
        throw ExpressionError(what, static_cast<unsigned int>(at + 1));
      }

      bool at_end() const { return position >= text.size(); }
      void skip_space()
      {
        while (!at_end() && std::isspace(static_cast<unsigned char>(text[position])))
          ++position;
      }
      /// Consumes `token` (and the space after it) when the text continues with it.
      bool accept(const char *token)
      {
        const std::size_t n = std::char_traits<char>::length(token);
        if (text.compare(position, n, token) != 0)
          return false;
        position += n;
        skip_space();
        return true;
      }
      void expect(const char *token, const std::string &what)
      {
        if (!accept(token))
          fail(at_end() ? "the expression ends where " + what + " was expected" : "expected " + what);
      }

      int add(Expression::Node node, const std::size_t at)
      {
        node.column = static_cast<unsigned int>(at + 1);
        nodes.push_back(std::move(node));
        return static_cast<int>(nodes.size()) - 1;
      }
      int binary(const unsigned int op, const int left, const int right, const std::size_t at)
      {
        Expression::Node node(Expression::Node::Kind::binary);
        node.slot     = op;
        node.operands = {left, right};
        return add(std::move(node), at);
      }

      int conditional()
      {
        const std::size_t at     = position;
        const int         choice = logical_or();
        if (!accept("?"))
          return choice;
        const int yes = conditional();
        expect(":", "':' of the conditional c ? x : y");
        const int          no = conditional();
        Expression::Node node(Expression::Node::Kind::conditional);
        node.operands = {choice, yes, no};
        return add(std::move(node), at);
      }

      /// One row of a left-associative level of the grammar: a token and its operator, or a token that is an error
      /// (a misuse the user should be told about, listed before the token it starts with).
      struct Infix
      {
        const char  *token;
        unsigned int op;
        const char  *error = nullptr;
      };

      /// operand (token operand)*, left-associative: the levels ||, &&, comparison, sum and product.
      int left_associative(int (Parser::*operand)(), const std::initializer_list<Infix> operators)
      {
        int left = (this->*operand)();
        for (;;)
          {
            const std::size_t at    = position;
            const Infix      *found = nullptr;
            for (const Infix &infix : operators)
              if (text.compare(position, std::char_traits<char>::length(infix.token), infix.token) == 0)
                {
                  found = &infix;
                  break;
                }
            if (!found)
              return left;
            if (found->error)
              fail_at(found->error, at);
            accept(found->token);
            left = binary(found->op, left, (this->*operand)(), at);
          }
      }

      int logical_or() { return left_associative(&Parser::logical_and, {{"||", Operator::logical_or}}); }
      int logical_and() { return left_associative(&Parser::comparison, {{"&&", Operator::logical_and}}); }
      int comparison()
      {
        // the two-character operators first, so that '<=' is not read as '<' then '='
        return left_associative(&Parser::sum, {{"<=", Operator::less_equal},
                                               {">=", Operator::greater_equal},
                                               {"==", Operator::equal},
                                               {"!=", Operator::not_equal},
                                               {"<", Operator::less},
                                               {">", Operator::greater},
                                               {"=", 0, "'=' is no operator (a comparison is '==')"}});
      }
      int sum() { return left_associative(&Parser::product, {{"+", Operator::add}, {"-", Operator::subtract}}); }
      int product()
      {
        return left_associative(&Parser::unary, {{"**", 0, "'**' is no operator (a power is '^')"},
                                                 {"*", Operator::multiply},
                                                 {"/", Operator::divide}});
      }

      int unary()
      {
        const std::size_t at = position;
        if (accept("-"))
          {
            Expression::Node node(Expression::Node::Kind::negate);
            node.operands = {unary()};
            return add(std::move(node), at);
          }
        if (accept("+"))
          return unary();
        if (!at_end() && text[position] == '!' && text.compare(position, 2, "!=") != 0)
          {
            accept("!");
            Expression::Node node(Expression::Node::Kind::logical_not);
            node.operands = {unary()};
            return add(std::move(node), at);
          }
        return power();
      }

      int power()
      {
        const int         base = primary();
        const std::size_t at   = position;
        if (!accept("^"))
          return base;
        // right-associative, and the exponent may carry its own sign: x^-1, 2^3^2 = 2^9
        return binary(Operator::power, base, unary(), at);
      }

      int primary()
      {
        skip_space();
        const std::size_t at = position;
        if (at_end())
          fail("the expression ends where a number, a name or '(' was expected");
        const char c = text[position];
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
          return number();
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
          return name();
        if (accept("("))
          {
            const int inner = conditional();
            if (at_end())
              fail_at("the '(' here is not closed", at);
            expect(")", "')'");
            return inner;
          }
        fail("unexpected '" + std::string(1, c) + "' where a number, a name or '(' was expected");
      }

      int number()
      {
        const std::size_t at  = position;
        const char *const begin = text.c_str() + position;
        char             *end   = nullptr;
        const double      value = std::strtod(begin, &end);
        if (end == begin)
          fail("a malformed number");
        position += static_cast<std::size_t>(end - begin);
        if (!at_end() && (std::isalpha(static_cast<unsigned char>(text[position])) || text[position] == '_'))
          fail("a number runs into a name (a product is written with '*')");
        skip_space();
        Expression::Node node(Expression::Node::Kind::number);
        node.number = value;
        return add(std::move(node), at);
      }

      int name()
      {
        const std::size_t at = position;
        while (!at_end() && (std::isalnum(static_cast<unsigned char>(text[position])) || text[position] == '_'))
          ++position;
        const std::string name = text.substr(at, position - at);
        skip_space();
        if (!at_end() && text[position] == '(')
          return call(name, at);
        const auto variable = std::find(variables.begin(), variables.end(), name);
        if (variable != variables.end())
          {
            Expression::Node node(Expression::Node::Kind::variable);
            node.slot = static_cast<unsigned int>(variable - variables.begin());
            return add(std::move(node), at);
          }
        if (const auto constant = constants.find(name); constant != constants.end())
          {
            Expression::Node node(Expression::Node::Kind::number);
            node.number = constant->second;
            return add(std::move(node), at);
          }
        fail_at(unknown_name(name), at);
      }

      std::string unknown_name(const std::string &name) const
      {
        std::string nearest;
        std::size_t best = std::numeric_limits<std::size_t>::max();
        const auto  consider = [&](const std::string &candidate) {
          if (const std::size_t d = edit_distance(name, candidate); d < best)
            nearest = candidate, best = d;
        };
        std::string known;
        for (const std::string &v : variables)
          consider(v), known += (known.empty() ? "" : ", ") + v;
        std::string names;
        for (const auto &[constant, value] : constants)
          consider(constant), names += (names.empty() ? "" : ", ") + constant;
        std::string what = "unknown name '" + name + "'";
        if (best <= std::max<std::size_t>(1, name.size() / 3))
          what += " (did you mean '" + nearest + "'?)";
        for (const Function &f : functions)
          if (name == f.name)
            what += " ('" + name + "' is a function: write " + name + "(...))";
        return what + "; the variables are " + known + ", the constants " + names;
      }

      int call(const std::string &name, const std::size_t at)
      {
        unsigned int index = 0;
        while (index < n_functions && name != functions[index].name)
          ++index;
        if (index == n_functions)
          {
            std::string nearest;
            std::size_t best = std::numeric_limits<std::size_t>::max();
            for (const Function &f : functions)
              if (const std::size_t d = edit_distance(name, f.name); d < best)
                nearest = f.name, best = d;
            fail_at("unknown function '" + name + "'" +
                      (best <= std::max<std::size_t>(1, name.size() / 3) ? " (did you mean '" + nearest + "'?)" : "") +
                      "; the functions are " + Expression::function_names(),
                    at);
          }
        expect("(", "'('");
        Expression::Node node(Expression::Node::Kind::function);
        node.slot = index;
        if (!accept(")"))
          {
            do
              node.operands.push_back(conditional());
            while (accept(","));
            if (at_end())
              fail_at("the '(' of " + name + " is not closed", at);
            expect(")", "',' or ')' after an argument of " + name);
          }
        const Function &f = functions[index];
        if (node.operands.size() < f.least || node.operands.size() > f.most)
          fail_at(name + " takes " +
                    (f.least == f.most ? std::to_string(f.least) :
                                         std::to_string(f.least) + " to " + std::to_string(f.most)) +
                    " argument" + (f.most == 1 ? "" : "s") + ", not " + std::to_string(node.operands.size()),
                  at);
        return add(std::move(node), at);
      }

      const std::string                    &text;
      const std::vector<std::string>       &variables;
      const std::map<std::string, double>  &constants;
      std::vector<Expression::Node>        &nodes;
      std::size_t                           position = 0;
    };
  } // namespace

  std::size_t edit_distance(const std::string &a, const std::string &b)
  {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
      row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
      {
        std::size_t diagonal = row[0];
        row[0]               = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
          {
            const std::size_t up   = row[j];
            const bool        same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
            row[j]                 = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
            diagonal               = up;
          }
      }
    return row[b.size()];
  }

  ExpressionError::ExpressionError(const std::string &what, const unsigned int column)
    : std::invalid_argument("column " + std::to_string(column) + ": " + what)
    , column_(column)
  {}

  Expression::Expression(const std::string &text, const std::vector<std::string> &variables,
                         const std::map<std::string, double> &constants)
    : text_(text)
    , variables_(variables)
  {
    root_ = Parser(text_, variables_, constants, nodes_).parse();
  }

  double Expression::value(const std::vector<double> &x) const
  {
    if (x.size() != variables_.size())
      throw std::invalid_argument("Expression::value: " + std::to_string(x.size()) + " values for " +
                                  std::to_string(variables_.size()) + " variables");
    return value(x.data());
  }

  double Expression::value(const double *x) const
  {
    const auto where = [&] {
      std::string point;
      for (std::size_t i = 0; i < variables_.size(); ++i)
        point += (i ? ", " : "") + variables_[i] + " = " + format(x[i]);
      return "'" + text_ + "' at " + (point.empty() ? "no variables" : point);
    };
    double result;
    try
      {
        result = evaluate(root_, x);
      }
    catch (const std::exception &e)
      {
        throw std::domain_error(where() + ": " + e.what());
      }
    if (!std::isfinite(result))
      throw std::domain_error(where() + " is " + format(result) +
                              " (guard a branch that is not defined everywhere with if(c, x, y))");
    return result;
  }

  double Expression::evaluate(const int index, const double *x) const
  {
    const Node &node = nodes_[index];
    const auto  at   = [&](const unsigned int i) { return evaluate(node.operands[i], x); };
    switch (node.kind)
      {
        case Node::Kind::number:
          return node.number;
        case Node::Kind::variable:
          return x[node.slot];
        case Node::Kind::negate:
          return -at(0);
        case Node::Kind::logical_not:
          return at(0) == 0 ? 1 : 0;
        case Node::Kind::conditional:
          return at(0) != 0 ? at(1) : at(2);
        case Node::Kind::function:
          {
            if (node.slot == 0) // if, the first function of the table
              return at(0) != 0 ? at(1) : at(2);
            std::array<double, 64> arguments;
            for (unsigned int i = 0; i < node.operands.size(); ++i)
              arguments[i] = at(i);
            return functions[node.slot].f(arguments.data(), static_cast<unsigned int>(node.operands.size()));
          }
        case Node::Kind::binary:
          break;
      }
    switch (static_cast<Operator>(node.slot))
      {
        case Operator::logical_and:
          return at(0) != 0 && at(1) != 0 ? 1 : 0;
        case Operator::logical_or:
          return at(0) != 0 || at(1) != 0 ? 1 : 0;
        default:
          break;
      }
    const double left = at(0), right = at(1);
    switch (static_cast<Operator>(node.slot))
      {
        case Operator::add:
          return left + right;
        case Operator::subtract:
          return left - right;
        case Operator::multiply:
          return left * right;
        case Operator::divide:
          return left / right;
        case Operator::power:
          return std::pow(left, right);
        case Operator::less:
          return left < right;
        case Operator::less_equal:
          return left <= right;
        case Operator::greater:
          return left > right;
        case Operator::greater_equal:
          return left >= right;
        case Operator::equal:
          return left == right;
        case Operator::not_equal:
          return left != right;
        default:
          return left != 0 || right != 0; // logical_or, handled above
      }
  }

  std::string Expression::function_names()
  {
    std::string names;
    for (const Function &f : functions)
      names += (names.empty() ? "" : ", ") + std::string(f.name);
    return names;
  }

  std::string Expression::function_list()
  {
    std::string list;
    for (const Function &f : functions)
      list += "  " + (f.help ? std::string(f.help) : std::string(f.name) + "(x)") + "\n";
    return list;
  }
} // namespace gradcontact::cases
