// Young's modulus fields E(z) of the graded half-space and the material of the FE model.
//
// The half-space occupies z > 0 (z points into the material); the Poisson ratio nu is constant.
// Three fields are provided, all behind ModulusField so that the assembly never knows which one it sees:
//
//   PowerLawModulus     E(z) = E0 (z / c0)^k,  -1 < k <= 1                                  (9.1)
//                       (k = 1 with nu = 1/2 is the Gibson medium, 9.42-9.44: only the mixed
//                       formulation of the axisymmetric solver accepts it, see Material::validate)
//   LayeredModulus      N layers [z_{i-1}, z_i] with the exact layer averages of another field,
//                       E_i = (z_i - z_{i-1})^{-1} \int_{z_{i-1}}^{z_i} E(z) dz, and that field below
//                       the last interface
//   ExpressionModulus   any E(z) given as a deal.II FunctionParser expression in the variable z
//
// A field may be singular at the surface like z^s (s = k for the power law). It reports s through
// surface_exponent(); the assembly then integrates the cells touching z = 0 with a Gauss-Jacobi rule that
// is exact for z^s times a polynomial (fem/gauss_jacobi.h) and asks for the regular factor E(z) / (z/h)^s.
// Plain Gauss points under-estimate the flat-punch force by 0.4-1.3 % for k < 0.
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

  /// The graded body: E(z) and a constant Poisson ratio, -1 < nu < 1/2 (displacement formulation) or
  /// 0 < nu <= 1/2 (mixed formulation, fem/axisymmetric_solver.h).
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
