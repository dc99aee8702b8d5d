// Young's modulus fields E(z) of the graded half-space and the material of the FE model.
//
// The half-space occupies z > 0 (z points into the material); the Poisson ratio nu is constant.
// Every field is a ModulusField, so that the assembly never knows which one it sees:
//
//   PowerLawModulus     E(z) = E0 (z / c0)^k,  -1 < k <= 1                                  (9.1)
//                       (k = 1 with nu = 1/2 is the Gibson medium, 9.42-9.44: only the mixed
//                       formulation of the axisymmetric solver accepts it, see Material::validate)
//   LayeredModulus      N layers [z_{i-1}, z_i] with the exact layer averages of another field,
//                       E_i = (z_i - z_{i-1})^{-1} \int_{z_{i-1}}^{z_i} E(z) dz, and that field below
//                       the last interface
//   ExpressionModulus   any E(z) given as a deal.II FunctionParser expression in the variable z
//
// and four "real gradings", where the power law (9.1) stops describing the material:
//
//   ShiftedPowerLawModulus  E(z) = E0 ((z + z0) / c0)^k, z0 > 0: a finite surface modulus E0 (z0/c0)^k
//   CoatingModulus          a power-law coating of thickness H on the homogeneous substrate E0 (H/c0)^k
//   TabulatedModulus        a measured profile: piecewise linear between rows (z_i, E_i), constant below
//   ErrorFunctionModulus    E(z) = E_b + (E_s - E_b) erfc(z / w): a surface modulus E_s that relaxes to the
//                           bulk E_b over the width w, like a diffusion profile
//
// A field may be singular at the surface like z^s (s = k for the power law). It reports s through
// surface_exponent(); the assembly then integrates the cells touching z = 0 with a Gauss-Jacobi rule that
// is exact for z^s times a polynomial (fem/base/gauss_jacobi.h) and asks for the regular factor E(z) / (z/h)^s.
// Plain Gauss points cannot integrate the singular factor and under-estimate the flat-punch force by far
// more than the discretisation error for k < 0.
#ifndef GRADCONTACT_FEM_MODULUS_H
#define GRADCONTACT_FEM_MODULUS_H

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// E(z), z >= 0 the depth below the surface.
  class ModulusField
  {
  public:
    virtual ~ModulusField() = default;

    /// E(z) for z > 0 (z = 0 may be infinite or zero).
    virtual double value(double z) const = 0;

    /// The exponent s of the surface behaviour E(z) ~ z^s as z -> 0 (0 when E is regular there).
    virtual double surface_exponent() const { return 0.0; }

    /// The exponent of E(z) ~ z^s far below the surface, which sets the truncation error of the far field
    /// (recommended_mesh_parameters): the surface exponent unless the field says otherwise.
    virtual double deep_exponent() const { return surface_exponent(); }

    /// Depths where E jumps (layer interfaces); quadrature is subdivided in cells that straddle one.
    virtual std::vector<double> discontinuities() const { return {}; }

    /// The mean of E over [z1, z2], 0 <= z1 < z2. Numerical (composite Gauss-Jacobi) unless overridden.
    virtual double average(double z1, double z2) const;

    /// One line for logs and reports.
    virtual std::string description() const = 0;
  };

  /// E(z) = E0 (z/c0)^k (9.1), E0 > 0, c0 > 0, -1 < k <= 1. k = 1 (E = E0 z / c0) is the Gibson
  /// medium (9.42) when nu = 1/2; a Material with k = 1 is valid only for the mixed formulation.
  class PowerLawModulus : public ModulusField
  {
  public:
    PowerLawModulus(double E0, double c0, double k);
    double value(double z) const override;
    double surface_exponent() const override { return k; }
    /// Exact: E0 c0^{-k} (z2^{1+k} - z1^{1+k}) / ((1+k)(z2 - z1)).
    double average(double z1, double z2) const override;
    std::string description() const override;

    const double E0, c0, k;
  };

  /// factor E(z) of `base` (factor > 0, finite): the same grading, every modulus times the factor. The accuracy
  /// contract's rounding probe (fem/accuracy/accuracy.h) solves the same problem on it: in exact arithmetic its
  /// displacements are the base's under loads times the factor, while every matrix entry is rounded anew.
  class ScaledModulus : public ModulusField
  {
  public:
    ScaledModulus(std::shared_ptr<const ModulusField> base, double factor);
    double value(double z) const override { return factor * base->value(z); }
    double surface_exponent() const override { return base->surface_exponent(); }
    double deep_exponent() const override { return base->deep_exponent(); }
    std::vector<double> discontinuities() const override { return base->discontinuities(); }
    double average(double z1, double z2) const override { return factor * base->average(z1, z2); }
    std::string description() const override;

    const std::shared_ptr<const ModulusField> base;
    const double factor;
  };

  /// N layers with the exact averages of `base` between consecutive interfaces
  /// 0 = z_0 < z_1 < ... < z_N, and `base` itself for z > z_N.
  class LayeredModulus : public ModulusField
  {
  public:
    LayeredModulus(std::shared_ptr<const ModulusField> base, std::vector<double> interfaces);

    /// N layers of equal thickness over [0, depth].
    static std::shared_ptr<LayeredModulus> uniform(std::shared_ptr<const ModulusField> base,
                                                   unsigned int n_layers, double depth);
    /// N layers whose thickness grows by `ratio` from `first_thickness` (layering of a real FGM coating
    /// is often finer at the surface).
    static std::shared_ptr<LayeredModulus> geometric(std::shared_ptr<const ModulusField> base,
                                                     unsigned int n_layers, double first_thickness,
                                                     double ratio);
    /// N geometric layers of first thickness `first_thickness` that end exactly at `depth`: the ratio q
    /// solves first_thickness (q^N - 1) / (q - 1) = depth (q = 1 when N first_thickness = depth).
    /// Needs 0 < first_thickness <= depth / N (q >= 1: layers that thicken downward); N = 1 is one
    /// layer over [0, depth] for first_thickness = depth.
    static std::shared_ptr<LayeredModulus> geometric_to_depth(std::shared_ptr<const ModulusField> base,
                                                              unsigned int n_layers, double first_thickness,
                                                              double depth);
    /// The ratio q of geometric_to_depth (bisection in ln q to round-off).
    static double geometric_ratio(unsigned int n_layers, double first_thickness, double depth);

    double value(double z) const override;
    std::vector<double> discontinuities() const override { return interfaces; }
    /// The base's: below the last interface E is the base.
    double deep_exponent() const override { return base->deep_exponent(); }
    std::string description() const override;

    const std::shared_ptr<const ModulusField> base;
    const std::vector<double> interfaces;   // z_1 .. z_N
    std::vector<double> layer_modulus;      // E_1 .. E_N
  };

  /// E(z) from a muParser expression in z, e.g. "E0*min((z/c0)^k, 100)" with constants {E0, c0, k}.
  /// `surface_exponent` declares E ~ z^s at the surface if the expression is singular there (else 0).
  class ExpressionModulus : public ModulusField
  {
  public:
    ExpressionModulus(const std::string &expression,
                      const std::map<std::string, double> &constants = {},
                      double surface_exponent = 0.0);
    ~ExpressionModulus() override;
    double value(double z) const override;
    double surface_exponent() const override { return exponent; }
    std::string description() const override;

  private:
    struct Parser;
    std::unique_ptr<Parser> parser;
    std::string expression;
    double exponent;
  };

  /// E(z) = E0 ((z + z0) / c0)^k, E0 > 0, c0 > 0, -1 < k <= 1, z0 > 0: the power law (9.1) shifted by z0,
  /// with the finite surface modulus E0 (z0/c0)^k; regular at z = 0 (surface exponent 0).
  /// Limits (flat punch of radius a, fem/doc/real-gradings.md):
  ///  - z0 >> a: Sneddon's punch on E0 (z0/c0)^k, F/F_S - 1 = k (a/z0) [c1 ln(z0/a) + c2], c1 = 0.773
  ///    at nu = 0.3 (the depth moment of Boussinesq's energy density), c2 = O(1);
  ///  - z0 << a, k > 0: the power law (9.16) times 1 + (1 - 2 nu)(1 + k) h_N / (2 pi k (1 - k)(1 - nu)^2)
  ///    (z0/a)^{1-k} (the compliance of the stiffer surface layer under the punch pressure); the mesh
  ///    must resolve z0: surface_layer_thickness = z0 / a;
  ///  - z0 << a, k < 0: E ~ z^k is nearly singular in every surface cell thicker than z0, which the
  ///    plain Gauss rule of a regular field under-integrates: no mesh of the near field resolves it.
  class ShiftedPowerLawModulus : public ModulusField
  {
  public:
    ShiftedPowerLawModulus(double E0, double c0, double k, double z0);
    double value(double z) const override;
    /// ((z + z0)/c0)^k behaves as z^k far below z0.
    double deep_exponent() const override { return k; }
    /// Exact: E0 c0^{-k} ((z2 + z0)^{1+k} - (z1 + z0)^{1+k}) / ((1+k)(z2 - z1)).
    double average(double z1, double z2) const override;
    std::string description() const override;

    const double E0, c0, k, z0;
  };

  /// A graded coating of thickness H on a homogeneous substrate: E0 (z/c0)^k (9.1) for 0 < z <= H, the
  /// substrate modulus E0 (H/c0)^k for z > H; E0 > 0, c0 > 0, -1 < k <= 1, H > 0. Continuous with a kink
  /// at H, which discontinuities() reports, so that the cells crossing it get the QIterated rule: without
  /// it, a surface cell crossing H applies Gauss-Jacobi to E / xi^k, singular above H; with it such a cell
  /// loses Gauss-Jacobi, which costs accuracy where the surface cells are about H thick (H = 0.01..0.1 a;
  /// tests/fem/test_real_gradings.cc checks the coating against both limits below).
  /// Limits (flat punch): H >> a is the power law (9.16) up to C (a/H)^{1+k}, like a truncation;
  /// H << a is Sneddon's punch on the substrate up to O(H/a ln(a/H)).
  class CoatingModulus : public ModulusField
  {
  public:
    CoatingModulus(double E0, double c0, double k, double H);
    double value(double z) const override;
    double surface_exponent() const override { return k; }
    /// The homogeneous substrate.
    double deep_exponent() const override { return 0.0; }
    std::vector<double> discontinuities() const override { return {H}; }
    /// Exact: the power-law integral over [z1, min(z2, H)] plus the substrate over [max(z1, H), z2].
    double average(double z1, double z2) const override;
    std::string description() const override;

    /// E0 (H/c0)^k.
    double substrate_modulus() const { return value(H); }

    const double E0, c0, k, H;
  };

  /// A measured profile E(z) as a table: rows (z_i, E_i), 0 = z_0 < z_1 < ... < z_{n-1}, E_i > 0 finite,
  /// n >= 2; E is linear in z between rows and E_{n-1} below the last row. Continuous, so no
  /// discontinuities(): the rows are kinks, which plain Gauss integrates with an error far below that of
  /// interpolating E from the table (reporting them as discontinuities would buy QIterated rules in every
  /// cell a row crosses, a larger assembly, for a change far below the interpolation error).
  class TabulatedModulus : public ModulusField
  {
  public:
    TabulatedModulus(std::vector<double> z, std::vector<double> E);

    /// Reads a table from a CSV file: two numeric columns z [m], E [Pa] separated by ',' (or blanks),
    /// one row a line; an optional header line (the first non-comment line, if it is not numeric),
    /// lines starting with '#' and blank lines are skipped. Throws std::invalid_argument naming the file
    /// and the line of a bad row (not two numbers, z not increasing, E <= 0 or not finite).
    static std::shared_ptr<TabulatedModulus> from_csv(const std::string &file);

    double value(double z) const override;
    /// Exact: the trapezoid of every row interval in [z1, z2] (and the constant below the last row).
    double average(double z1, double z2) const override;
    std::string description() const override;

    const std::vector<double> z, E;

  private:
    /// \int_0^x E(z) dz.
    double integral(double x) const;
  };

  /// The error-function grading E(z) = E_b + (E_s - E_b) erfc(z / w), E_b > 0 the bulk modulus far below
  /// the surface, E_s > 0 the surface modulus E(0), w > 0 the width; E_s > E_b is a stiff skin (an oxidised
  /// or implanted surface, a diffusion profile erfc(z / (2 sqrt(D t))) with w = 2 sqrt(D t)), E_s < E_b a
  /// soft one. The "more practical" of the gradings in the FE study of D. Lee, J.R. Barber, M.D. Thouless,
  /// "Indentation of an elastic half space with material properties varying with depth", Int. J. Eng. Sci.
  /// 47 (2009) 1274-1283 (its error-function grading, next to a power law truncated to a finite surface
  /// value); written here with w as the only length. Regular at z = 0, homogeneous below a few w.
  /// Limits (flat punch of radius a, fem/doc/real-gradings.md; tests/fem/test_real_gradings.cc):
  ///  - w >> a: Sneddon's punch on E_s, with the surface slope E'(0)/E_s = -(1 - E_b/E_s) 2/(sqrt(pi) w) in
  ///    the place of k/z0 of the shifted power law: F/F_S(E_s) - 1 = (E_b/E_s - 1) (2/sqrt(pi)) (a/w)
  ///    [c1 ln(w/a) + c2], c1 = 0.773 at nu = 0.3, c2 = O(1);
  ///  - w << a: Sneddon's punch on E_b, F/F_S(E_b) - 1 = (w/a) [A ln(a/w) + B]: a thin layer under the edge
  ///    of the punch, A from its in-plane stiffness \int (E - E_b) dz and its normal compliance
  ///    \int (1/E_b - 1/E) dz; the mesh must resolve w over the whole near field, not only under the punch
  ///    (recommended_settings: surface_layer_thickness = w / (4 a), halving_radius = near_field_size).
  class ErrorFunctionModulus : public ModulusField
  {
  public:
    ErrorFunctionModulus(double E_bulk, double E_surface, double width);
    double value(double z) const override;
    /// Exact: E_b + (E_s - E_b) w [G(z2/w) - G(z1/w)] / (z2 - z1), G(x) = x erfc(x) - exp(-x^2)/sqrt(pi)
    /// the primitive of erfc; 24-point Gauss where z2 - z1 < w (there the primitives cancel).
    double average(double z1, double z2) const override;
    std::string description() const override;

    const double E_bulk, E_surface, width;
  };

  /// The graded body: E(z) and a constant Poisson ratio, -1 < nu < 1/2 (displacement formulation) or
  /// 0 < nu <= 1/2 (mixed formulation, fem/bodies/axisymmetric_solver.h).
  struct Material
  {
    std::shared_ptr<const ModulusField> modulus;
    double nu = 0.3;

    /// Throws std::invalid_argument naming the offending member, its value and the valid range.
    /// `mixed`: the displacement-pressure formulation, which accepts nu = 1/2 and, with nu = 1/2 only,
    /// a surface exponent s = 1 (the Gibson medium E = E0 z / c0, 9.42). Without it: -1 < nu < 1/2 and
    /// -1 < s < 1.
    void validate(bool mixed = false) const;
  };
} // namespace gradcontact::fem

#endif
