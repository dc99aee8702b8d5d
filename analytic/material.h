// gradcontact/analytic: the power-law graded half-space and its MDR coefficients.
//
// E(z) = E0 (z / c0)^k, -1 < k < 1, constant Poisson ratio nu (chapter 9, eq. 9.1).
// The MDR maps the contact onto a Winkler foundation with modulus c_N(x) = cN0 (|x|/c0)^k (9.4);
// tangential contact uses c_T(x) = cT0 (|x|/c0)^k and alpha = cN0 / cT0 (9.78).
#ifndef GRADCONTACT_ANALYTIC_MATERIAL_H
#define GRADCONTACT_ANALYTIC_MATERIAL_H

namespace gradcontact
{
  /// A graded elastic half-space, E(z) = E0 (z/c0)^k (9.1). Units: E0 [Pa], c0 [m].
  struct GradedHalfSpace
  {
    double E0;
    double c0;
    double k;
    double nu;
  };

  /// Checks E0 > 0, c0 > 0, -1 < k < 1, 0 <= nu <= 1/2 and that beta (9.7) is real and positive,
  /// i.e. 1 - nu (1 + k) > 0. Throws DomainError naming `function`.
  void validate(const char *function, const GradedHalfSpace &body);

  /// beta(k, nu) = sqrt((1+k)(1 - k nu/(1-nu))) (9.7).
  double beta(double k, double nu);

  /// C(k, nu) = 2^(1+k) Gamma((3+k+beta)/2) Gamma((3+k-beta)/2) / (pi Gamma(2+k)) (9.6).
  double C(double k, double nu);

  /// h_N(k, nu) (9.5); h_N(0, nu) = 1.
  double h_N(double k, double nu);

  /// h_T(k, nu) (9.79); h_T(0, nu) = 2 / ((1+nu)(2-nu)), i.e. c_T = 4G/(2-nu) for k = 0.
  double h_T(double k, double nu);

  /// The equivalent medium of the MDR: what every closed form needs of the material(s).
  struct Medium
  {
    double k;   ///< exponent of the grading (both bodies)
    double c0;  ///< characteristic depth (both bodies) [m]
    double cN0; ///< normal foundation modulus c_N at |x| = c0 (9.4) [Pa]
    double cT0; ///< tangential foundation modulus c_T at |x| = c0 [Pa]

    /// alpha = normal over tangential stiffness (9.78)
    double alpha() const { return cN0 / cT0; }
  };

  /// One graded body pressed by a rigid indenter: cN0 = h_N E0/(1-nu^2), cT0 = h_T E0.
  Medium medium(const GradedHalfSpace &body);

  /// Two graded bodies with the same k and c0 (9.4, 9.78): the compliances add.
  Medium medium(const GradedHalfSpace &body1, const GradedHalfSpace &body2);

  /// Checks a Medium built by hand: -1 < k < 1, c0 > 0, cN0 > 0, cT0 > 0.
  void validate(const char *function, const Medium &m);
} // namespace gradcontact

#endif
