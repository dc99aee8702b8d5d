#include <analytic/errors.h>
#include <analytic/point_load.h>

#include <numerics/gauss_jacobi.h>

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <stdexcept>

namespace gradcontact
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();

    using Vec = std::array<double, 2>;
    using Mat = std::array<Vec, 2>; // [row][column]; rows: the two equilibrium equations, columns: U, Wt = x W

    Vec times(const Mat &m, const Vec &v) { return {m[0][0] * v[0] + m[0][1] * v[1], m[1][0] * v[0] + m[1][1] * v[1]}; }
    Mat scaled(const Mat &m, const double s) { return {{{m[0][0] * s, m[0][1] * s}, {m[1][0] * s, m[1][1] * s}}}; }
    Mat sum(const Mat &a, const Mat &b)
    {
      return {{{a[0][0] + b[0][0], a[0][1] + b[0][1]}, {a[1][0] + b[1][0], a[1][1] + b[1][1]}}};
    }
    Vec solve(const Mat &m, const Vec &r)
    {
      const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
      if (!(std::abs(det) > 0))
        throw std::logic_error("PointLoadField: a series recurrence met a singular step");
      return {(r[0] * m[1][1] - m[0][1] * r[1]) / det, (m[0][0] * r[1] - r[0] * m[1][0]) / det};
    }

    /// The equilibrium operator P0(delta) + x^2 P2(delta) on (U, Wt), delta = x d/dx, each a 2x2 matrix of
    /// polynomials c0 + c1 delta + c2 delta^2 (all multiplied by 2 (1 + nu)(2 nu - 1), which keeps them polynomial
    /// in nu). Derived by inserting u = R^-(1+k) (U e_R + V e_theta) into the equilibrium equations in spherical
    /// coordinates with E ~ R^k x^k, and dividing by x^(k-2) (first equation) and sin(theta) x^(k-3) (second).
    struct Operator
    {
      std::array<Mat, 3> p0, p2; ///< [power of delta]

      Operator(const double k, const double n)
      {
        const double a = 2 * n - 1, b = n - 1;
        // row 0: A (on U), G (on Wt); row 1: B (on U), H (on Wt)
        p0[0] = {{{0., a * k * (k + 1) - 4 * b}, {0., 2 * b * (2 - k)}}};
        p0[1] = {{{a * (k - 1), k * a + 4 * b}, {0., 2 * b * (k - 3)}}};
        p0[2] = {{{a, 0.}, {0., 2 * b}}};
        p2[0] = {{{-4 * (n * (k + 1) - 1), -(a * k * (k + 3) + 4 * b)}, {-2 * k * (k * n + n - 1), k}}};
        p2[1] = {{{-a * (k + 1), -(k * a + 4 * b)}, {-(2 * k * n + 4 * n - 3), -2 * b * (k + 1)}}};
        p2[2] = {{{-a, 0.}, {0., -2 * b}}};
      }

      static Mat at(const std::array<Mat, 3> &p, const double m)
      {
        return sum(sum(p[0], scaled(p[1], m)), scaled(p[2], m * m));
      }
      Mat m0(const double m) const { return at(p0, m); }
      Mat m2(const double m) const { return at(p2, m); }
    };

    /// The two solutions free of traction on the surface, as series in x: entry m is the coefficient of x^m of
    /// (U, Wt). `odd`: exponent 1 (U ~ -(2+k) x, Wt ~ x); else exponent 0 (U ~ 1, Wt ~ x^2).
    /// Recurrence: M0(m) f_m = -M2(m - 2) f_(m-2); M0 is upper triangular with a zero first entry at m = 1 and a zero
    /// second diagonal entry at m = 2 as k -> 0, where the quotients are taken in closed form.
    std::vector<Vec> surface_solution(const Operator &op, const double k, const double n, const bool odd,
                                      const std::size_t terms)
    {
      std::vector<Vec> f(terms, Vec{0., 0.});
      std::size_t m = odd ? 1 : 0;
      f[m] = odd ? Vec{-(2 + k), 1.} : Vec{1., 0.};
      for (m += 2; m < terms; m += 2)
        {
          const Vec rhs = times(op.m2(double(m - 2)), f[m - 2]);
          const Mat M   = op.m0(double(m));
          if (!odd && m == 2)
            {
              // H0(2) and B2(0) both carry a factor k: their quotient in closed form.
              f[2][1] = (k * n + n - 1) / (n - 1) * f[0][0];
              f[2][0] = -(rhs[0] + M[0][1] * f[2][1]) / M[0][0];
            }
          else
            f[m] = solve(M, {-rhs[0], -rhs[1]});
        }
      return f;
    }

    /// The operator in t = 1 - x: sum_j C_j(t) d^j/dt^j with C_j polynomials in t (powers 0..4).
    std::array<std::array<Mat, 5>, 3> axis_operator(const Operator &op)
    {
      // delta = -(1 - t) d/dt, delta^2 = (1 - t)^2 d^2/dt^2 - (1 - t) d/dt, x^2 = (1 - t)^2.
      const auto binomial_power = [](const int p) { // coefficients of (1 - t)^p
        std::array<double, 5> c{};
        double                b = 1;
        for (int i = 0; i <= p; ++i)
          {
            c[i] = (i % 2 ? -b : b);
            b    = b * (p - i) / (i + 1);
          }
        return c;
      };
      std::array<std::array<Mat, 5>, 3> C{};
      const auto add = [&](const int j, const Mat &m, const int p, const double s) {
        const auto c = binomial_power(p);
        for (int i = 0; i <= p; ++i)
          C[j][i] = sum(C[j][i], scaled(m, s * c[i]));
      };
      add(0, op.p0[0], 0, 1.);
      add(0, op.p2[0], 2, 1.);
      add(1, sum(op.p0[1], op.p0[2]), 1, -1.);
      add(1, sum(op.p2[1], op.p2[2]), 3, -1.);
      add(2, op.p0[2], 2, 1.);
      add(2, op.p2[2], 4, 1.);
      return C;
    }

    /// A solution regular on the axis, as a series in t = 1 - x, from its value f_0 at the axis. The axis is a
    /// regular singular point (C_2 vanishes there), so f_(n+1) follows from the lower coefficients.
    std::vector<Vec> axis_solution(const std::array<std::array<Mat, 5>, 3> &C, const Vec &f0, const std::size_t terms)
    {
      std::vector<Vec> f(terms, Vec{0., 0.});
      f[0] = f0;
      const auto falling = [](const long q, const int j) {
        double r = 1;
        for (int i = 0; i < j; ++i)
          r *= double(q - i);
        return r;
      };
      for (std::size_t n = 0; n + 1 < terms; ++n)
        {
          Vec rhs{0., 0.};
          for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 5; ++i)
              {
                const long q = long(n) + j - i;
                if (q < 0 || q > long(n))
                  continue;
                const Vec t = times(C[j][i], f[q]);
                rhs[0] -= falling(q, j) * t[0];
                rhs[1] -= falling(q, j) * t[1];
              }
          const double nn = double(n);
          const Mat    N  = scaled(sum(scaled(C[2][1], nn * (nn + 1)), scaled(C[1][0], nn + 1)), 1.);
          f[n + 1]        = solve(N, rhs);
        }
      return f;
    }

    /// {U, dU/dx, Wt, dWt/dx} of a series in powers of y at y, dy/dx = `sign`.
    std::array<double, 4> sum_series(const std::vector<Vec> &f, const double y, const double sign)
    {
      std::array<double, 4> s{};
      double                p = 1, dp = 0; // y^m, m y^(m-1)
      for (std::size_t m = 0; m < f.size(); ++m)
        {
          s[0] += f[m][0] * p;
          s[1] += f[m][0] * dp;
          s[2] += f[m][1] * p;
          s[3] += f[m][1] * dp;
          dp = double(m + 1) * p;
          p *= y;
        }
      s[1] *= sign;
      s[3] *= sign;
      return s;
    }

    /// The matching angle (x = cos theta): the surface series serve below, the axis series above.
    constexpr double x_match = 0.5;
    /// Terms: |x|^m and |t|^n fall below 1e-19 of the leading term on either side of x_match.
    constexpr std::size_t surface_terms = 72, axis_terms = 72;

    double det3(const std::array<std::array<double, 4>, 4> &M, const std::size_t skip_row, const std::size_t skip_col)
    {
      double a[3][3];
      for (std::size_t i = 0, ii = 0; i < 4; ++i)
        {
          if (i == skip_row)
            continue;
          for (std::size_t j = 0, jj = 0; j < 4; ++j)
            if (j != skip_col)
              a[ii][jj++] = M[i][j];
          ++ii;
        }
      return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    }

    /// The null vector of the singular 4x4 matching matrix: a row of its adjugate (the cofactors of the row whose
    /// cofactors are largest).
    std::array<double, 4> null_vector(const std::array<std::array<double, 4>, 4> &M)
    {
      std::array<double, 4> best{};
      double                best_norm = -1;
      for (std::size_t row = 0; row < 4; ++row)
        {
          std::array<double, 4> v{};
          double                norm = 0;
          for (std::size_t col = 0; col < 4; ++col)
            {
              v[col] = ((row + col) % 2 ? -1 : 1) * det3(M, row, col);
              norm += v[col] * v[col];
            }
          if (norm > best_norm)
            {
              best      = v;
              best_norm = norm;
            }
        }
      return best;
    }

    /// R^2 sigma / P of the modes {U, U_x, W, W_x} at x (not yet scaled to a force).
    SphericalStress stresses(const std::array<double, 4> &w, const double x, const double k, const double nu)
    {
      const double s2 = 1 - x * x, s = std::sqrt(s2);
      const double U = w[0], Ux = w[1], W = w[2], Wx = w[3];
      const double eRR = -(1 + k) * U, ett = -s2 * Wx + x * W + U, epp = U + x * W;
      const double eRt = -0.5 * s * (Ux + (2 + k) * W);
      const double lam = nu / ((1 + nu) * (1 - 2 * nu)), mu2 = 1 / (1 + nu); // lambda', 2 mu'
      const double tr = eRR + ett + epp, E = std::pow(x, k);
      return {E * (lam * tr + mu2 * eRR), E * (lam * tr + mu2 * ett), E * (lam * tr + mu2 * epp), E * mu2 * eRt};
    }

    /// The stresses near the surface as series in x: sigma R^2 / P = x^k (b_RR, b_tt, b_pp) and
    /// sigma_Rt R^2 / P = -x^k s b_q / (1 + nu), from the surface series of (U, Wt) term by term (W = Wt / x).
    /// The traction-free solutions make sigma_tt ~ x^(2+k) and sigma_Rt ~ x^(1+k): b_tt starts at x^2 and b_q at x,
    /// so their leading coefficients, zero but for rounding, are set to zero; summing their differences in x instead
    /// would lose the traction to cancellation near the surface (relative error eps / x^2).
    std::vector<std::array<double, 4>> surface_brackets(const std::vector<Vec> &f, const double k, const double nu)
    {
      const std::size_t n   = f.size();
      const auto        u   = [&](const long m) { return m >= 0 && m < long(n) ? f[m][0] : 0.; };
      const auto        w   = [&](const long m) { return m >= 0 && m + 1 < long(n) ? f[m + 1][1] : 0.; };
      const double      lam = nu / ((1 + nu) * (1 - 2 * nu)), mu2 = 1 / (1 + nu);
      std::vector<std::array<double, 4>> b(n - 1);
      for (long m = 0; m + 1 < long(n); ++m)
        {
          const double s2Wx = (m + 1) * w(m + 1) - (m - 1) * w(m - 1); // (1 - x^2) W_x
          const double eRR = -(1 + k) * u(m), ett = -s2Wx + w(m - 1) + u(m), epp = u(m) + w(m - 1);
          const double tr  = eRR + ett + epp;
          b[m] = {lam * tr + mu2 * eRR, lam * tr + mu2 * ett, lam * tr + mu2 * epp, (m + 1) * u(m + 1) + (2 + k) * w(m)};
        }
      b[0][1] = b[1][1] = b[0][3] = 0;
      return b;
    }
  } // namespace

  PointLoadField::PointLoadField(const double k, const double nu)
    : k_(k)
    , nu_(nu)
  {
    check::open_interval("PointLoadField", "k", k, -1., 1.);
    check::finite("PointLoadField", "nu", nu);
    if (!(nu >= 0 && nu < 0.5))
      check::fail("PointLoadField", "nu", nu, "is outside [0, 0.5)");
    const Operator op(k, nu);
    const auto     even = surface_solution(op, k, nu, false, surface_terms);
    const auto     odd  = surface_solution(op, k, nu, true, surface_terms);
    const auto     C    = axis_operator(op);
    const auto     ax0  = axis_solution(C, {1., 0.}, axis_terms);
    const auto     ax1  = axis_solution(C, {0., 1.}, axis_terms);

    // Match the four at x_match: (U, U_x, Wt, Wt_x) of a0 ax0 + a1 ax1 - b0 even - b1 odd = 0.
    const std::array<std::array<double, 4>, 4> columns{sum_series(ax0, 1 - x_match, -1.), sum_series(ax1, 1 - x_match, -1.),
                                                       sum_series(even, x_match, 1.), sum_series(odd, x_match, 1.)};
    std::array<std::array<double, 4>, 4> M{};
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = 0; j < 4; ++j)
        M[i][j] = (j < 2 ? 1 : -1) * columns[j][i];
    const std::array<double, 4> c = null_vector(M);

    surface_.assign(surface_terms, Vec{0., 0.});
    for (std::size_t m = 0; m < surface_terms; ++m)
      for (int i = 0; i < 2; ++i)
        surface_[m][i] = c[2] * even[m][i] + c[3] * odd[m][i];
    axis_.assign(axis_terms, Vec{0., 0.});
    for (std::size_t n = 0; n < axis_terms; ++n)
      for (int i = 0; i < 2; ++i)
        axis_[n][i] = c[0] * ax0[n][i] + c[1] * ax1[n][i];

    surface_stress_ = surface_brackets(surface_, k, nu);

    // Scale so that the stresses on a hemisphere carry the force: 2 pi int_0^1 (S_RR x - S_Rt s) dx = -1 (the
    // material outside pushes back on the force P = 1). The integrand is x^k times a function analytic on each
    // side of x_match: Gauss-Jacobi with the weight x^k below, Gauss-Legendre above.
    const auto integrand_over_xk = [&](const double x) {
      const SphericalStress S = spherical(x);
      return (S.RR * x - S.Rth * std::sqrt(1 - x * x)) / std::pow(x, k_);
    };
    const detail::GaussJacobiRule low  = detail::gauss_jacobi_rule(40, 1 + k, 1.);
    const detail::GaussJacobiRule high = detail::gauss_jacobi_rule(40, 1., 1.);
    double                        force = 0;
    for (std::size_t q = 0; q < low.size(); ++q)
      force += low.weight[q] * std::pow(x_match, 1 + k) * integrand_over_xk(x_match * low.node[q]);
    for (std::size_t q = 0; q < high.size(); ++q)
      {
        const double x = x_match + (1 - x_match) * high.node[q];
        force += high.weight[q] * (1 - x_match) * std::pow(x, k) * integrand_over_xk(x);
      }
    force *= 2 * pi;
    if (!(std::abs(force) > 0) || !std::isfinite(force))
      throw std::logic_error("PointLoadField: the matched field carries no force");
    for (auto *series : {&surface_, &axis_})
      for (Vec &f : *series)
        f = {-f[0] / force, -f[1] / force};
    for (auto &b : surface_stress_)
      for (double &c : b)
        c /= -force;
  }

  SphericalStress PointLoadField::spherical(const double x) const
  {
    if (x >= x_match)
      return stresses(modes(x), x, k_, nu_);
    double b[4] = {0, 0, 0, 0}, p = 1;
    for (const auto &c : surface_stress_)
      {
        for (int i = 0; i < 4; ++i)
          b[i] += c[i] * p;
        p *= x;
      }
    const double E = std::pow(x, k_);
    return {E * b[0], E * b[1], E * b[2], -E / (2 * (1 + nu_)) * std::sqrt(1 - x * x) * b[3]};
  }

  std::array<double, 4> PointLoadField::modes(const double x) const
  {
    if (x < x_match)
      {
        // Wt = x W: the surface series of W is that of Wt shifted by one power (its x^0 coefficient is zero).
        const std::array<double, 4> s = sum_series(surface_, x, 1.);
        double                      W = 0, Wx = 0, p = 1, dp = 0;
        for (std::size_t m = 1; m < surface_.size(); ++m)
          {
            W += surface_[m][1] * p;
            Wx += surface_[m][1] * dp;
            dp = double(m) * p;
            p *= x;
          }
        return {s[0], s[1], W, Wx};
      }
    const std::array<double, 4> s = sum_series(axis_, 1 - x, -1.);
    const double                W = s[2] / x;
    return {s[0], s[1], W, (s[3] - W) / x};
  }

  SphericalStress PointLoadField::angular(const double theta) const
  {
    check::finite("PointLoadField::angular", "theta", theta);
    if (!(theta >= 0 && theta < pi / 2))
      check::fail("PointLoadField::angular", "theta", theta, "is outside [0, pi/2)");
    const double x = std::cos(theta);
    return spherical(x);
  }

  AxisymmetricStress PointLoadField::stress(const double P, const double r, const double z) const
  {
    check::finite("PointLoadField::stress", "P", P);
    check::non_negative("PointLoadField::stress", "r", r);
    check::positive("PointLoadField::stress", "z", z);
    const double R2 = r * r + z * z, R = std::sqrt(R2), x = z / R, s = r / R;
    const SphericalStress S = spherical(x);
    const double          f = P / R2;
    return {f * (S.RR * s * s + S.thth * x * x + 2 * S.Rth * s * x), f * (S.RR * x * x + S.thth * s * s - 2 * S.Rth * s * x),
            f * S.phph, f * ((S.RR - S.thth) * s * x + S.Rth * (x * x - s * s))};
  }

  std::array<double, 2> PointLoadField::displacement(const GradedHalfSpace &body, const double P, const double r,
                                                     const double z) const
  {
    validate("PointLoadField::displacement", body);
    check::finite("PointLoadField::displacement", "P", P);
    check::non_negative("PointLoadField::displacement", "r", r);
    check::non_negative("PointLoadField::displacement", "z", z);
    if (!(r > 0 || z > 0))
      check::fail("PointLoadField::displacement", "r", r, "and z = 0: the load point itself (need r > 0 or z > 0)");
    if (body.k != k_ || body.nu != nu_)
      throw DomainError("PointLoadField::displacement: body has k = " + check::format(body.k) + ", nu = " +
                        check::format(body.nu) + ", the field was built for k = " + check::format(k_) +
                        ", nu = " + check::format(nu_));
    const double R = std::hypot(r, z), x = z / R, s = r / R;
    const auto   w = modes(x);
    const double scale = P * std::pow(body.c0, body.k) / body.E0 * std::pow(R, -(1 + body.k));
    const double uR = scale * w[0], ut = scale * s * w[2];
    return {uR * s + ut * x, uR * x - ut * s};
  }
} // namespace gradcontact
