// The expression language of candidate closed forms (cases/scene/expression.h): precedence, laziness, errors with their
// column, and the special functions, each checked against an identity that does not go through the function
// itself (elementary closed forms, Gauss's sum, the classical limit of a graded coefficient).
#include <cases/runners/candidate.h>
#include <cases/scene/expression.h>

#include <catch2/catch.hpp>

#include <cmath>

using gradcontact::cases::Expression;
using gradcontact::cases::ExpressionError;
using Catch::Matchers::Contains;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  double at(const std::string &text, const std::vector<double> &x = {}, const std::vector<std::string> &names = {},
            const std::map<std::string, double> &constants = {})
  {
    return Expression(text, names, constants).value(x);
  }

  /// The column of the error `text` raises.
  unsigned int error_column(const std::string &text, const std::vector<std::string> &names = {"x"})
  {
    try
      {
        Expression(text, names, {{"beta", 0.25}});
      }
    catch (const ExpressionError &e)
      {
        return e.column();
      }
    return 0;
  }
} // namespace

TEST_CASE("expressions bind as written mathematics", "[cases][quick]")
{
  CHECK(at("1 + 2 * 3") == 7);
  CHECK(at("-2^2") == -4);          // the power binds tighter than the sign
  CHECK(at("2^3^2") == 512);        // and to the right
  CHECK(at("2^-1") == 0.5);         // an exponent may carry a sign
  CHECK(at("(1 - 3) / 4") == -0.5);
  CHECK(at("8 / 2 / 2") == 2);      // left-associative
  CHECK(at("1.5e-3 * 2E+3") == Approx(3.0).epsilon(1e-15));
  CHECK(at(".5 + 0.25") == 0.75);
  CHECK(at("(3 > 2) * 5 + (3 <= 2)") == 5);
  CHECK(at("1 < 2 && 2 < 1 || !0") == 1);
  CHECK(at("x > 1 ? 10 : x < 0 ? -10 : 0", {-3}, {"x"}) == -10);
  CHECK(at("min(3, 1, 2) + max(3, 1, 2)") == 4);
  CHECK(at("a * r", {2, 5}, {"r", "a"}) == 10);
}

TEST_CASE("a variable hides a constant, a name before '(' is a function", "[cases][quick]")
{
  CHECK(at("k", {0.5}, {"k"}, {{"k", 0.25}}) == 0.5);
  // the constant beta of 9.5 and the function beta(p, q) side by side
  CHECK(at("beta + beta(2, 3)", {}, {}, {{"beta", 1}}) == Approx(1 + 1. / 12).epsilon(1e-15));
}

TEST_CASE("only the chosen branch of if, ?: and && is evaluated", "[cases][quick]")
{
  CHECK(at("if(x < 1, sqrt(1 - x^2), 0)", {2}, {"x"}) == 0);
  CHECK(at("x < 1 ? sqrt(1 - x^2) : 0", {2}, {"x"}) == 0);
  CHECK(at("x < 1 && sqrt(1 - x^2) > 0", {2}, {"x"}) == 0);
  // unguarded, the same expression is an error that names the point, never a NaN
  CHECK_THROWS_WITH(at("(x < 1) * sqrt(1 - x^2)", {2}, {"x"}), Contains("x = 2") && Contains("nan"));
  CHECK_THROWS_WITH(at("1 / x", {0}, {"x"}), Contains("inf"));
  CHECK_THROWS_AS(at("gamma(-1)"), std::domain_error);
}

TEST_CASE("an error names its column and what is known", "[cases][quick]")
{
  CHECK(error_column("1 + * 2") == 5);
  CHECK(error_column("sqrt(x") == 1);
  CHECK(error_column("x)") == 2);
  CHECK(error_column("2 ** x") == 3);
  CHECK(error_column("2x") == 2);
  CHECK(error_column("x = 1") == 3);
  CHECK(error_column("") == 1);
  CHECK(error_column("1 + hyp2f2(1, 2, 3, x)") == 5);
  CHECK(error_column("beta(x)") == 1);
  CHECK_THROWS_WITH(Expression("sqrtt(x)", {"x"}, {}), Contains("did you mean 'sqrt'") &&
                                                             Contains("hyp2f1"));
  CHECK_THROWS_WITH(Expression("1 + y", {"x"}, {{"cN0", 1}}), Contains("unknown name 'y'") &&
                                                                  Contains("cN0"));
  CHECK_THROWS_WITH(Expression("cn0", {"x"}, {{"cN0", 1}}), Contains("did you mean 'cN0'"));
  CHECK_THROWS_WITH(Expression("gamma", {"x"}, {}), Contains("is a function"));
  CHECK_THROWS_WITH(Expression("hyp2f1(1, 2, 3)", {"x"}, {}), Contains("takes 4 arguments, not 3"));
}

TEST_CASE("the special functions meet their identities", "[cases][quick]")
{
  // Gamma(1/2)^2 = pi, Gamma(5) = 4!, B(2, 3) = 1/12, digamma(1) = -Euler's constant
  CHECK(at("gamma(0.5)^2") == Approx(pi).epsilon(1e-15));
  CHECK(at("gamma(5)") == Approx(24).epsilon(1e-15));
  CHECK(at("lgamma(10)") == Approx(std::log(362880.)).epsilon(1e-15));
  CHECK(at("digamma(1)") == Approx(-0.57721566490153286).epsilon(1e-15));
  CHECK(at("beta(2, 3)") == Approx(1. / 12).epsilon(1e-15));
  // I_x(p, 1) = x^p; I_x(1/2, 1/2) = (2 / pi) asin(sqrt x)
  CHECK(at("ibeta(2.5, 1, 0.3)") == Approx(std::pow(0.3, 2.5)).epsilon(1e-14));
  CHECK(at("ibeta(0.5, 0.5, 0.3)") == Approx(2 / pi * std::asin(std::sqrt(0.3))).epsilon(1e-14));
  // 2F1(1, 1; 2; z) = -ln(1 - z) / z on both sides of 0 (z < 0 goes through Pfaff's transformation)
  for (const double z : {0.3, 0.9, -0.5, -3.0, -40.0})
    CHECK(at("hyp2f1(1, 1, 2, z)", {z}, {"z"}) == Approx(-std::log1p(-z) / z).epsilon(1e-13));
  // 2F1(1/2, 1/2; 3/2; z^2) = asin(z) / z; 2F1(a, b; b; z) = (1 - z)^(-a)
  CHECK(at("hyp2f1(0.5, 0.5, 1.5, 0.49)") == Approx(std::asin(0.7) / 0.7).epsilon(1e-14));
  CHECK(at("hyp2f1(0.3, 1.7, 1.7, -2)") == Approx(std::pow(3., -0.3)).epsilon(1e-14));
  // Gauss's sum at z = 1: 2F1(1/2, 1/2; 2; 1) = Gamma(2) Gamma(1) / Gamma(3/2)^2 = 4 / pi
  CHECK(at("hyp2f1(0.5, 0.5, 2, 1)") == Approx(4 / pi).epsilon(1e-14));
  CHECK_THROWS_WITH(at("hyp2f1(0.5, 0.5, 2, 1.5)"), Contains("complex"));
  CHECK_THROWS_WITH(at("hyp2f1(1, 1, 1.5, 1)"), Contains("diverges"));
  // K(0) = E(0) = pi / 2, E(1) = 1; the incomplete integral of the first kind at k = 0 is phi
  CHECK(at("ellint_1(0)") == Approx(pi / 2).epsilon(1e-15));
  CHECK(at("ellint_2(0)") == Approx(pi / 2).epsilon(1e-15));
  CHECK(at("ellint_2(1)") == Approx(1).epsilon(1e-15));
  CHECK(at("ellint_1(0, 0.7)") == Approx(0.7).epsilon(1e-15));
  CHECK(at("erf(0.5) + erfc(0.5)") == Approx(1).epsilon(1e-15));
  // every function is listed with its help
  const std::string list = Expression::function_list();
  for (const char *name : {"if(c, x, y)", "hyp2f1(a, b, c, z)", "ibeta(p, q, x)", "gamma(x)", "sqrt(x)"})
    CHECK_THAT(list, Contains(name));
}

TEST_CASE("a graded coefficient written with gamma and beta meets its classical value", "[cases][quick]")
{
  // The MDR of a power-law profile A r^n, 9.2: g(x) = kappa A x^n with kappa = n/2 B(n/2, (1 + k)/2); at k = 0
  // this is sqrt(pi) Gamma(n/2 + 1) / Gamma(n/2 + 1/2): for n = 2, kappa = 2 (Hertz: d = a^2 / R for f = r^2/(2R)).
  CHECK(at("n/2 * beta(n/2, (1 + k)/2)", {2, 0}, {"n", "k"}) == Approx(2).epsilon(1e-15));
  CHECK(at("n/2 * beta(n/2, (1 + k)/2)", {1, 0}, {"n", "k"}) == Approx(pi / 2).epsilon(1e-15));
  CHECK(at("n/2 * beta(n/2, (1 + k)/2) - sqrt(pi) * gamma(n/2 + 1) / gamma(n/2 + 1/2)", {1.5, 0}, {"n", "k"},
           {{"pi", pi}}) == Approx(0).margin(1e-14));
}
