#include <fem/base/errors.h>
#include <fem/base/gauss_jacobi.h>
#include <fem/modulus/modulus.h>
#include <fem/base/table_file.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace gradcontact::fem
{
  namespace
  {
    // Points of the rules used for layer averages; the regular factor of every field we use is smooth,
    // so this many points per geometric sub-interval give the average to round-off.
    constexpr unsigned int average_points = 24;
    // [z1, z2] with z1 > 0 is split at z1 * 2^j: E varies by a bounded factor on each piece.
    constexpr double average_split_ratio = 2.0;

    // The mean of (x/c)^k over [x2 - length, x2], 0 < length <= x2, c > 0:
    //   (x2/c)^k (1 - t^{1+k}) / ((1+k)(1 - t)),  t = x1/x2,  1 - t = length/x2,
    // with 1 - t^{1+k} = -expm1((1+k) log1p(-length/x2)): short intervals deep down (or far below a
    // shift) do not cancel; the length is passed, not x2 - x1, for the same reason.
    double power_mean(const double c, const double k, const double x2, const double length)
    {
      const double one_minus_t = length / x2;
      const double factor      = (one_minus_t == 1.0) ?
                                   1.0 / (1.0 + k) :
                                   -std::expm1((1.0 + k) * std::log1p(-one_minus_t)) / ((1.0 + k) * one_minus_t);
      return std::pow(x2 / c, k) * factor;
    }

    std::string decimal(const double x)
    {
      std::ostringstream s;
      s.precision(17);
      s << x;
      return s.str();
    }

    void check_average_interval(const std::string &where, const double z1, const double z2)
    {
      if (!(z1 >= 0.0))
        fail(where, "z1", z1, "[0, inf)");
      if (!(z2 > z1))
        fail(where, "z2", z2, "(z1, inf)");
    }

    // E0, c0 and k of the power law (9.1), shared by the fields built on it.
    void check_power_law(const std::string &where, const double E0, const double c0, const double k)
    {
      if (!(E0 > 0.0) || !std::isfinite(E0))
        fail(where, "E0", E0, "(0, inf)");
      if (!(c0 > 0.0) || !std::isfinite(c0))
        fail(where, "c0", c0, "(0, inf)");
      // k = 1 is the Gibson medium (9.42); whether a solver accepts it is decided by Material::validate.
      if (!(k > -1.0 && k <= 1.0))
        fail(where, "k", k, "(-1, 1]");
    }
  } // namespace



  double ModulusField::average(const double z1, const double z2) const
  {
    if (!(z1 >= 0.0))
      fail("ModulusField::average", "z1", z1, "[0, inf)");
    if (!(z2 > z1))
      fail("ModulusField::average", "z2", z2, "(z1, inf)");

    double integral = 0.0;
    double lo       = z1;
    if (z1 == 0.0)
      {
        // mean = \int_0^1 E(z2 x) dx = \int_0^1 x^s [E(z2 x) / x^s] dx, Gauss-Jacobi in x.
        const double                s = surface_exponent();
        const dealii::Quadrature<1> q = gauss_jacobi(average_points, s);
        for (unsigned int i = 0; i < q.size(); ++i)
          {
            const double x = q.point(i)[0];
            integral += q.weight(i) * value(z2 * x) / std::pow(x, s);
          }
        return integral;
      }
    const dealii::QGauss<1> gauss(average_points);
    while (lo < z2)
      {
        const double hi = std::min(z2, lo * average_split_ratio);
        for (unsigned int i = 0; i < gauss.size(); ++i)
          integral += gauss.weight(i) * (hi - lo) * value(lo + (hi - lo) * gauss.point(i)[0]);
        lo = hi;
      }
    return integral / (z2 - z1);
  }



  PowerLawModulus::PowerLawModulus(const double E0, const double c0, const double k)
    : E0(E0)
    , c0(c0)
    , k(k)
  {
    check_power_law("PowerLawModulus", E0, c0, k);
  }

  double PowerLawModulus::value(const double z) const
  {
    return E0 * std::pow(z / c0, k);
  }

  double PowerLawModulus::average(const double z1, const double z2) const
  {
    if (!(z1 >= 0.0))
      fail("PowerLawModulus::average", "z1", z1, "[0, inf)");
    if (!(z2 > z1))
      fail("PowerLawModulus::average", "z2", z2, "(z1, inf)");
    // E0 c0^{-k} (z2^{1+k} - z1^{1+k}) / ((1+k)(z2 - z1)), written with the ratio t = z1/z2 so that
    // thin layers deep down do not cancel: z2^k (1 - t^{1+k}) / ((1+k)(1 - t)).
    const double t = z1 / z2;
    const double factor =
      (t == 0.0) ? 1.0 / (1.0 + k) : -std::expm1((1.0 + k) * std::log(t)) / ((1.0 + k) * (1.0 - t));
    return value(z2) * factor;
  }

  std::string PowerLawModulus::description() const
  {
    std::ostringstream s;
    s.precision(17);
    s << "power law E(z) = " << E0 << " (z/" << c0 << ")^" << k;
    return s.str();
  }



  ShiftedPowerLawModulus::ShiftedPowerLawModulus(const double E0, const double c0, const double k,
                                                 const double z0)
    : E0(E0)
    , c0(c0)
    , k(k)
    , z0(z0)
  {
    check_power_law("ShiftedPowerLawModulus", E0, c0, k);
    // z0 = 0 is the power law itself (PowerLawModulus, singular at the surface).
    if (!(z0 > 0.0) || !std::isfinite(z0))
      fail("ShiftedPowerLawModulus", "z0", z0, "(0, inf) (z0 = 0 is PowerLawModulus)");
  }

  ScaledModulus::ScaledModulus(std::shared_ptr<const ModulusField> base_field, const double scale)
    : base(std::move(base_field))
    , factor(scale)
  {
    if (!base)
      throw std::invalid_argument("ScaledModulus: the base modulus field is null");
    if (!(std::isfinite(scale) && scale > 0))
      fail("ScaledModulus", "factor", scale, "(0, inf)");
  }

  std::string ScaledModulus::description() const
  {
    std::ostringstream s;
    s.precision(17);
    s << factor << " times " << base->description();
    return s.str();
  }



  double ShiftedPowerLawModulus::value(const double z) const
  {
    return E0 * std::pow((z + z0) / c0, k);
  }

  double ShiftedPowerLawModulus::average(const double z1, const double z2) const
  {
    check_average_interval("ShiftedPowerLawModulus::average", z1, z2);
    // The power law's mean over [z1 + z0, z2 + z0], of length z2 - z1.
    return E0 * power_mean(c0, k, z2 + z0, z2 - z1);
  }

  std::string ShiftedPowerLawModulus::description() const
  {
    std::ostringstream s;
    s.precision(17);
    s << "shifted power law E(z) = " << E0 << " ((z + " << z0 << ")/" << c0 << ")^" << k;
    return s.str();
  }



  CoatingModulus::CoatingModulus(const double E0, const double c0, const double k, const double H)
    : E0(E0)
    , c0(c0)
    , k(k)
    , H(H)
  {
    check_power_law("CoatingModulus", E0, c0, k);
    if (!(H > 0.0) || !std::isfinite(H))
      fail("CoatingModulus", "H", H, "(0, inf)");
  }

  double CoatingModulus::value(const double z) const
  {
    return E0 * std::pow(std::min(z, H) / c0, k);
  }

  double CoatingModulus::average(const double z1, const double z2) const
  {
    check_average_interval("CoatingModulus::average", z1, z2);
    if (z1 >= H)
      return substrate_modulus();
    if (z2 <= H)
      return E0 * power_mean(c0, k, z2, z2 - z1);
    return (E0 * power_mean(c0, k, H, H - z1) * (H - z1) + substrate_modulus() * (z2 - H)) / (z2 - z1);
  }

  std::string CoatingModulus::description() const
  {
    std::ostringstream s;
    s.precision(17);
    s << "coating E(z) = " << E0 << " (min(z, " << H << ")/" << c0 << ")^" << k;
    return s.str();
  }



  ErrorFunctionModulus::ErrorFunctionModulus(const double E_bulk, const double E_surface, const double width)
    : E_bulk(E_bulk)
    , E_surface(E_surface)
    , width(width)
  {
    if (!(E_bulk > 0.0) || !std::isfinite(E_bulk))
      fail("ErrorFunctionModulus", "E_bulk", E_bulk, "(0, inf)");
    if (!(E_surface > 0.0) || !std::isfinite(E_surface))
      fail("ErrorFunctionModulus", "E_surface", E_surface, "(0, inf)");
    if (!(width > 0.0) || !std::isfinite(width))
      fail("ErrorFunctionModulus", "width", width, "(0, inf)");
  }

  double ErrorFunctionModulus::value(const double z) const
  {
    return E_bulk + (E_surface - E_bulk) * std::erfc(z / width);
  }

  double ErrorFunctionModulus::average(const double z1, const double z2) const
  {
    check_average_interval("ErrorFunctionModulus::average", z1, z2);
    const double length = z2 - z1;
    double       mean_erfc = 0.0; // the mean of erfc(z/w) over [z1, z2]
    if (length < width)
      {
        // erfc(z/w) is entire and varies on the scale w: Gauss on [z1, z2] is exact to round-off, where the
        // difference of the primitives below would lose the digits of length / w.
        const dealii::QGauss<1> gauss(average_points);
        for (unsigned int i = 0; i < gauss.size(); ++i)
          mean_erfc += gauss.weight(i) * std::erfc((z1 + length * gauss.point(i)[0]) / width);
      }
    else
      {
        // G(x) = x erfc(x) - exp(-x^2)/sqrt(pi), G'(x) = erfc(x).
        constexpr double inv_sqrt_pi = 0.564189583547756286948079451560772586;
        const auto G = [](const double x) { return x * std::erfc(x) - std::exp(-x * x) * inv_sqrt_pi; };
        mean_erfc = (G(z2 / width) - G(z1 / width)) * width / length;
      }
    return E_bulk + (E_surface - E_bulk) * mean_erfc;
  }

  std::string ErrorFunctionModulus::description() const
  {
    std::ostringstream s;
    s.precision(17);
    s << "error function E(z) = " << E_bulk << " + (" << E_surface << " - " << E_bulk << ") erfc(z/" << width
      << ")";
    return s.str();
  }



  TabulatedModulus::TabulatedModulus(std::vector<double> z_rows, std::vector<double> E_rows)
    : z(std::move(z_rows))
    , E(std::move(E_rows))
  {
    if (z.size() != E.size())
      fail("TabulatedModulus", "E.size()", E.size(), "{z.size() = " + std::to_string(z.size()) + "}");
    if (z.size() < 2)
      fail("TabulatedModulus", "z.size()", z.size(), "[2, inf)");
    if (z[0] != 0.0)
      fail("TabulatedModulus", "z[0]", z[0], "{0} (the table starts at the surface)");
    for (std::size_t i = 0; i < z.size(); ++i)
      {
        if (i > 0 && !(z[i] > z[i - 1] && std::isfinite(z[i])))
          fail("TabulatedModulus", "z[" + std::to_string(i) + "]", z[i],
               "(z[" + std::to_string(i - 1) + "] = " + decimal(z[i - 1]) + ", inf): z must increase strictly");
        if (!(E[i] > 0.0) || !std::isfinite(E[i]))
          fail("TabulatedModulus", "E[" + std::to_string(i) + "]", E[i], "(0, inf)");
      }
  }

  std::shared_ptr<TabulatedModulus> TabulatedModulus::from_csv(const std::string &file)
  {
    const TableFile     table = read_table_file(file, "TabulatedModulus::from_csv", "z", "E");
    std::vector<double> z, E;
    for (std::size_t i = 0; i < table.x.size(); ++i)
      {
        const double zi = table.x[i], Ei = table.y[i];
        const auto   where = [&] {
          return "TabulatedModulus::from_csv: \"" + file + "\" line " + std::to_string(table.line[i]);
        };
        if (z.empty() && zi != 0.0)
          fail(where(), "z", zi, "{0}: the first row is the surface");
        if (!z.empty() && !(zi > z.back()))
          fail(where(), "z", zi, "(" + decimal(z.back()) + ", inf): z must increase strictly");
        if (!(Ei > 0.0) || !std::isfinite(Ei))
          fail(where(), "E", Ei, "(0, inf)");
        z.push_back(zi);
        E.push_back(Ei);
      }
    try
      {
        return std::make_shared<TabulatedModulus>(std::move(z), std::move(E));
      }
    catch (const std::invalid_argument &e)
      {
        throw std::invalid_argument("TabulatedModulus::from_csv: \"" + file + "\": " + e.what());
      }
  }

  double TabulatedModulus::value(const double depth) const
  {
    if (depth >= z.back())
      return E.back();
    // The row interval [z_{i-1}, z_i) holding depth (z_0 = 0 <= depth).
    const std::size_t i = std::upper_bound(z.begin(), z.end(), depth) - z.begin();
    if (i == 0)
      return E.front(); // depth < 0: not part of the body; the surface value
    const double w = (depth - z[i - 1]) / (z[i] - z[i - 1]);
    return (1.0 - w) * E[i - 1] + w * E[i];
  }

  double TabulatedModulus::integral(const double x) const
  {
    double sum = 0.0;
    for (std::size_t i = 1; i < z.size() && z[i - 1] < x; ++i)
      {
        const double hi = std::min(x, z[i]);
        sum += 0.5 * (E[i - 1] + value(hi)) * (hi - z[i - 1]);
      }
    if (x > z.back())
      sum += E.back() * (x - z.back());
    return sum;
  }

  double TabulatedModulus::average(const double z1, const double z2) const
  {
    check_average_interval("TabulatedModulus::average", z1, z2);
    // Inside one row interval (or below the table) the mean is the trapezoid of the ends; otherwise the
    // difference of the running integral.
    const auto row = [&](const double x) { return std::upper_bound(z.begin(), z.end(), x) - z.begin(); };
    if (row(z1) == row(z2) || z1 >= z.back())
      return 0.5 * (value(z1) + value(z2));
    return (integral(z2) - integral(z1)) / (z2 - z1);
  }

  std::string TabulatedModulus::description() const
  {
    std::ostringstream s;
    s.precision(6);
    s << "table of " << z.size() << " rows to z = " << z.back() << ", E from " << E.front() << " to "
      << E.back();
    return s.str();
  }



  LayeredModulus::LayeredModulus(std::shared_ptr<const ModulusField> base_field,
                                 std::vector<double> layer_interfaces)
    : base(std::move(base_field))
    , interfaces(std::move(layer_interfaces))
  {
    if (!base)
      throw std::invalid_argument("LayeredModulus: base field is null");
    if (interfaces.empty())
      throw std::invalid_argument("LayeredModulus: interfaces is empty, need N >= 1 layers");
    double previous = 0.0;
    for (unsigned int i = 0; i < interfaces.size(); ++i)
      {
        if (!(interfaces[i] > previous) || !std::isfinite(interfaces[i]))
          fail("LayeredModulus", "interfaces[" + std::to_string(i) + "]", interfaces[i],
               "(previous interface, inf): interfaces must increase from 0");
        layer_modulus.push_back(base->average(previous, interfaces[i]));
        previous = interfaces[i];
      }
  }

  std::shared_ptr<LayeredModulus> LayeredModulus::uniform(std::shared_ptr<const ModulusField> base,
                                                          const unsigned int n_layers,
                                                          const double depth)
  {
    if (n_layers == 0)
      fail("LayeredModulus::uniform", "n_layers", 0, "[1, inf)");
    if (!(depth > 0.0))
      fail("LayeredModulus::uniform", "depth", depth, "(0, inf)");
    std::vector<double> z(n_layers);
    for (unsigned int i = 0; i < n_layers; ++i)
      z[i] = depth * (i + 1.0) / n_layers;
    return std::make_shared<LayeredModulus>(std::move(base), z);
  }

  std::shared_ptr<LayeredModulus> LayeredModulus::geometric(std::shared_ptr<const ModulusField> base,
                                                            const unsigned int n_layers,
                                                            const double first_thickness,
                                                            const double ratio)
  {
    if (n_layers == 0)
      fail("LayeredModulus::geometric", "n_layers", 0, "[1, inf)");
    if (!(first_thickness > 0.0))
      fail("LayeredModulus::geometric", "first_thickness", first_thickness, "(0, inf)");
    if (!(ratio >= 1.0))
      fail("LayeredModulus::geometric", "ratio", ratio, "[1, inf)");
    std::vector<double> z(n_layers);
    double              t = first_thickness, depth = 0.0;
    for (unsigned int i = 0; i < n_layers; ++i, t *= ratio)
      z[i] = (depth += t);
    return std::make_shared<LayeredModulus>(std::move(base), z);
  }

  double LayeredModulus::geometric_ratio(const unsigned int n_layers, const double first_thickness,
                                         const double depth)
  {
    if (n_layers == 0)
      fail("LayeredModulus::geometric_ratio", "n_layers", 0, "[1, inf)");
    if (!(depth > 0.0) || !std::isfinite(depth))
      fail("LayeredModulus::geometric_ratio", "depth", depth, "(0, inf)");
    // A relative slack of 1e-12 lets first_thickness = depth / N (uniform layers) through despite rounding.
    if (!(first_thickness > 0.0) || first_thickness > depth / n_layers * (1 + 1e-12))
      fail("LayeredModulus::geometric_ratio", "first_thickness", first_thickness,
           "(0, depth / n_layers = " + std::to_string(depth / n_layers) + "]");
    if (n_layers == 1 || first_thickness >= depth / n_layers)
      return 1.0;
    // Total thickness t1 (q^N - 1)/(q - 1) = t1 expm1(N x)/expm1(x), x = ln q, increases with x from
    // N t1 <= depth at x = 0; the last layer alone is t1 q^{N-1} <= depth, so x <= ln(depth/t1)/(N-1).
    const auto total = [&](const double x) {
      return x == 0.0 ? n_layers * first_thickness : first_thickness * std::expm1(n_layers * x) / std::expm1(x);
    };
    double lo = 0.0, hi = std::log(depth / first_thickness) / (n_layers - 1.0);
    for (unsigned int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (total(mid) < depth ? lo : hi) = mid;
      }
    return std::exp(0.5 * (lo + hi));
  }

  std::shared_ptr<LayeredModulus> LayeredModulus::geometric_to_depth(std::shared_ptr<const ModulusField> base,
                                                                     const unsigned int n_layers,
                                                                     const double first_thickness,
                                                                     const double depth)
  {
    const double q      = geometric_ratio(n_layers, first_thickness, depth);
    auto         layers = geometric(base, n_layers, first_thickness, q);
    // Put the last interface exactly at `depth` (the bisection leaves a relative 1e-15 there).
    // (The constructor checks that the interfaces still increase.)
    std::vector<double> z = layers->interfaces;
    z.back()              = depth;
    return std::make_shared<LayeredModulus>(std::move(base), std::move(z));
  }

  double LayeredModulus::value(const double z) const
  {
    const auto it = std::lower_bound(interfaces.begin(), interfaces.end(), z);
    if (it == interfaces.end())
      return base->value(z);
    return layer_modulus[it - interfaces.begin()];
  }

  std::string LayeredModulus::description() const
  {
    std::ostringstream s;
    s.precision(6);
    s << interfaces.size() << " layers to z = " << interfaces.back() << " averaging "
      << base->description();
    return s.str();
  }



  struct ExpressionModulus::Parser
  {
    dealii::FunctionParser<1> function;
  };

  ExpressionModulus::ExpressionModulus(const std::string &expr,
                                       const std::map<std::string, double> &constants,
                                       const double surface_exponent)
    : parser(std::make_unique<Parser>())
    , expression(expr)
    , exponent(surface_exponent)
  {
    if (!(surface_exponent > -1.0 && surface_exponent < 1.0))
      fail("ExpressionModulus", "surface_exponent", surface_exponent, "(-1, 1)");
    try
      {
        parser->function.initialize("z", expression, constants);
        // Evaluate once so that a syntax error surfaces here and not in the assembly.
        (void)parser->function.value(dealii::Point<1>(1.0));
      }
    catch (const std::exception &e)
      {
        throw std::invalid_argument("ExpressionModulus: cannot parse E(z) = \"" + expression +
                                    "\": " + e.what());
      }
  }

  ExpressionModulus::~ExpressionModulus() = default;

  double ExpressionModulus::value(const double z) const
  {
    return parser->function.value(dealii::Point<1>(z));
  }

  std::string ExpressionModulus::description() const
  {
    return "E(z) = " + expression;
  }



  void Material::validate(const bool mixed) const
  {
    if (!modulus)
      throw std::invalid_argument("Material: modulus field is null");
    if (std::isnan(nu))
      fail("Material", "nu", nu, mixed ? "(0, 0.5]" : "(-1, 0.5)");
    if (!mixed && !(nu > -1.0 && nu < 0.5))
      fail("Material", "nu", nu, "(-1, 0.5) (incompressible nu = 0.5 needs the mixed formulation)");
    // The mixed formulation carries 1/lambda = (1 + nu)(1 - 2 nu) / (nu E): finite for nu > 0 only.
    if (mixed && !(nu > 0.0 && nu <= 0.5))
      fail("Material (mixed formulation)", "nu", nu, "(0, 0.5]");
    const double s = modulus->surface_exponent();
    if (s >= 1.0)
      {
        // E ~ z at the surface: the Gibson medium (9.42-9.44), an incompressible limit. With nu < 1/2
        // or the displacement formulation the FE model is not meant for it (and the closed forms of
        // chapter 9.1 need k < 1).
        if (!mixed)
          fail("Material", "modulus surface exponent", s,
               "(-1, 1) (s = 1, the Gibson medium, needs nu = 0.5 and the mixed formulation)");
        if (!(s == 1.0 && nu == 0.5))
          fail("Material (mixed formulation)", "modulus surface exponent", s,
               "(-1, 1), or 1 with nu = 0.5 (the Gibson medium 9.42; nu = " + std::to_string(nu) + ")");
      }
  }
} // namespace gradcontact::fem
