// mode1_study: one Fourier-mode-1 FE run (fem/tangential/fourier_mode1_solver.h) with any mesh/discretisation
// setting, its error against the closed forms of chapter 9.3, and its timings; the numbers
// fem/doc/loads-and-contact.md, "Tangential loads", names. Not a test.
//
//   mode1_study load=punch k=0 nu=0.3 p=3 h_edge=1e-5 g=1.15 L=1e8 layer=1e-10 normal=1
//   mode1_study load=slip k=0.5 nu=0.4 c=0.5        (c: stick radius / a; R = 50 a, mu = 0.3)
// punch: K_T against the MDR 2 cT0 a^{1+k} / ((1+k) c0^k) (9.78)-(9.79) and, for k = 0, Mindlin's
// 8 G a / (2 - nu); with normal=1 also the normal flat punch of AxisymmetricSolver on the same mesh
// and alpha = K_N / K_T against cN0 / cT0. slip: the traction mu [p(r; a) - p(r; c)] (9.80) and the
// stick-zone displacement against u0 = mu alpha [d(a) - d(c)]. osc: the oscillation (9.81)-(9.86) after loading to
// F_A = phi mu F_N. load=cylinder: the mode-1 model against the independent 3D cylinder of the FE tests
// (tests/fem/cylinder_3d.h; ref2d, ref3d the refinements of the two).
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/tangential/fourier_mode1_solver.h>
#include <fem/modulus/modulus.h>

#include "study_arguments.h"

#include "cylinder_3d.h"

#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/tangential.h>

#include <deal.II/base/quadrature_lib.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <string>

using namespace gradcontact::fem;
using gradcontact::studies::StudyArguments;

namespace
{
  using Clock = std::chrono::steady_clock;

  double seconds_since(const Clock::time_point start)
  {
    return std::chrono::duration<double>(Clock::now() - start).count();
  }

  /// Mode 1 vs 3D on the cylinder R = H = 1, load tau = (1 - r^2/a^2)^2 on r <= a = 0.5, smooth grading
  /// E = (1 + 4 z)^{1/2}, nu = 0.3 (tests/fem/cylinder_3d.h).
  void run_cylinder(const StudyArguments &args)
  {
    const double   R = 1, H = 1, a = 0.5, nu = args.num("nu", 0.3);
    const Material material{std::make_shared<ExpressionModulus>("(1+4*z)^0.5"), nu};
    auto tau = [a](const double r) { return r < a ? std::pow(1 - r * r / (a * a), 2) : 0.0; };
    const std::vector<double> radii{0.0, 0.25, 0.5, 0.75};
    dealii::Triangulation<2>  meridian;
    testing::make_meridian_rectangle(R, H, a, 4, 4, static_cast<unsigned>(args.num("ref2d", 5)), meridian);
    DiscretizationParameters disc;
    FourierMode1Solver       mode1(material, meridian, disc);
    TangentialOutputRequest  out;
    out.displacement_radii = radii;
    const TangentialResult m = mode1.run(TangentialLoad::profile(tau, a), out);
    const auto c = testing::solve_cylinder_3d({material, R, H, tau, static_cast<unsigned>(args.num("ref3d", 1))},
                                              radii);
    const double scale = m.surface[0].U;
    double       err   = 0;
    for (unsigned i = 0; i < radii.size(); ++i)
      {
        const auto &s = m.surface[i];
        std::printf("r=%.2f U=%.8e ux3d(x)=%.8e V=%.8e ux3d(y)=%.8e W=%.8e uz3d(x)=%.8e uy3d(x)=%.2e uz3d(y)=%.2e\n",
                    s.r, s.U, c.at_x[i][0], s.V, c.at_y[i][0], s.W, c.at_x[i][2], c.at_x[i][1], c.at_y[i][2]);
        err = std::max({err, std::abs(s.U - c.at_x[i][0]), std::abs(s.V - c.at_y[i][0]),
                        std::abs(s.W - c.at_x[i][2])});
      }
    std::printf("max_diff/U(0)=%.3e dofs_3d=%u dofs_mode1=%u t_3d=%.2f iterations=%u energy_mismatch=%.2e\n",
                err / scale, c.n_dofs, m.n_dofs, c.seconds, c.iterations, m.energy_mismatch);
  }

  /// The half-space runs: E0 = 2 GPa, c0 = 3 a, a = 0.1 mm, its mesh and discretisation.
  struct Run
  {
    double                   E0 = 2e9, c0 = 3e-4, a = 1e-4, k = 0, nu = 0.3;
    std::string              load_name;
    MeshParameters           mesh;
    DiscretizationParameters disc;
  };

  /// nu=holl: Holl's ratio 1 / (2 + k).
  Run parse_run(const StudyArguments &args)
  {
    Run run;
    run.k         = args.num("k", 0.0);
    run.nu        = args.has("nu") && args.text("nu") == "holl" ? 1 / (2 + run.k) : args.num("nu", 0.3);
    run.load_name = args.text("load", "punch");
    run.mesh      = recommended_mesh_parameters(run.a, run.k, args.num("truncation", 1e-8));
    run.mesh.axis_refinements   = 0;
    run.mesh.edge_refinements   = 0;
    run.mesh.global_refinements = 0;
    args.apply(run.mesh);
    args.apply(run.disc);
    return run;
  }

  void print_setting(const Run &run)
  {
    std::printf("load=%s k=%g nu=%.6g p=%u h_edge=%g g=%g L=%g layer=%g\n", run.load_name.c_str(), run.k, run.nu,
                run.disc.degree, run.mesh.h_edge, run.mesh.ring_growth, run.mesh.far_field_size,
                run.mesh.surface_layer_thickness);
  }

  /// The surface refinement toward the stick radius: c a (slip), or c_A = a (1 - phi)^{1/(k+3)} at the turning
  /// point A (osc), c_levels times.
  SurfaceRefinement plan_refinement(const StudyArguments &args, const Run &run)
  {
    SurfaceRefinement refine;
    if (run.load_name == "slip")
      refine = {{args.num("c", 0.5) * run.a}, static_cast<unsigned>(args.num("c_levels", 0))};
    if (run.load_name == "osc")
      refine = {{run.a * std::pow(1 - args.num("phi", 0.9), 1 / (run.k + 3))},
                static_cast<unsigned>(args.num("c_levels", 0))};
    return refine;
  }

  /// The tangential flat punch: K_T against (9.78)-(9.79) (and Mindlin at k = 0); normal=1: the normal punch on the
  /// same mesh and alpha = K_N / K_T against cN0 / cT0.
  void run_punch(const StudyArguments &args, const Run &run, const Material &material,
                 const gradcontact::Medium &medium, FourierMode1Solver &solver)
  {
    const double a = run.a, k = run.k, nu = run.nu, E0 = run.E0, c0 = run.c0;
    const double           delta = 1e-3 * a;
    const TangentialResult t     = solver.run(TangentialLoad::flat_punch(delta));
    const double K_mdr = 2 * medium.cT0 * std::pow(a, 1 + k) / ((1 + k) * std::pow(c0, k));
    std::printf("K_T=%.12e K_T_mdr=%.12e err_mdr=%.3e", t.stiffness, K_mdr, t.stiffness / K_mdr - 1);
    if (k == 0)
      {
        const double G = E0 / (2 * (1 + nu));
        std::printf(" err_mindlin=%.3e", t.stiffness / (8 * G * a / (2 - nu)) - 1);
      }
    std::printf(" dofs=%u energy_mismatch=%.2e reliable=%d t_setup=%.2f t_fact=%.2f t_solve=%.2f\n",
                t.n_dofs, t.energy_mismatch, t.reliable, t.time.mesh + t.time.setup + t.time.assemble,
                t.time.factorize, t.time.solve);
    if (args.num("normal", 0) == 0)
      return;
    AxisymmetricSolver normal(material, run.mesh, run.disc);
    LoadCase           l;
    l.type               = LoadType::flat_punch;
    l.depth              = delta;
    const Result n       = normal.run(l);
    const double K_N     = n.force / delta;
    const double K_N_mdr = 2 * medium.cN0 * std::pow(a, 1 + k) / ((1 + k) * std::pow(c0, k));
    std::printf("K_N_err=%.3e alpha=%.12e alpha_mdr=%.12e alpha_err=%.3e dofs_normal=%u\n",
                K_N / K_N_mdr - 1, K_N / t.stiffness, medium.alpha(),
                (K_N / t.stiffness) / medium.alpha() - 1, n.n_dofs);
  }

  /// Partial slip of the sphere R = 50 a, mu = 0.3, stick radius c: the traction mu [p(r; a) - p(r; c)] (9.80), the
  /// stick zone's u_x against u0 and F_x against (9.80).
  void run_slip(const StudyArguments &args, const Run &run, const gradcontact::Medium &medium,
                FourierMode1Solver &solver, const Clock::time_point start)
  {
    const double a = run.a;
    const double R = 50 * a, mu = 0.3, c = args.num("c", 0.5) * a;
    const gradcontact::Paraboloid             sphere{R};
    const gradcontact::tangential::SphereSlip slip{R, mu};
    auto pressure = [&](const double r, const double b) { return gradcontact::pressure(medium, sphere, b, r); };
    TangentialOutputRequest out;
    for (const double x : {0.0, 0.25, 0.5, 0.75, 0.9, 1.0, 1.5})
      out.displacement_radii.push_back(x * a);
    const TangentialResult t  = solver.run(TangentialLoad::partial_slip(pressure, mu, a, c), out);
    const double           u0 = gradcontact::tangential::tangential_displacement(medium, slip, a, c);
    const double           Fx = gradcontact::tangential::tangential_force(medium, slip, a, c);
    std::printf("mean_ux=%.12e u0=%.12e err_u0=%.3e spread=%.3e max_uy=%.3e Fx_err=%.3e dofs=%u "
                "energy_mismatch=%.2e t_total=%.2f\n",
                t.stick.mean_ux, u0, t.stick.mean_ux / u0 - 1, t.stick.relative_spread, t.stick.relative_max_uy,
                t.force / Fx - 1, t.n_dofs, t.energy_mismatch, seconds_since(start));
    for (const auto &s : t.surface)
      std::printf("  r/a=%.3f U/u0=%.8f V/u0=%.8f W/u0=%.8f\n", s.r / a, s.U / u0, s.V / u0, s.W / u0);
  }

  /// Oscillation between +-F_A = +-phi mu F_N after loading to A (9.81)-(9.86): the unloading traction (9.82) on one
  /// mesh and one factorisation, the stick-zone mean of u_x against (9.83), and the dissipated energy
  /// W = \int_{-F_A}^{F_A} [u_un(F) - u_re(F)] dF with u_re(F) = -u_un(-F), by Gauss-Legendre in F on FE values and on
  /// the closed form.
  void run_oscillation(const StudyArguments &args, const Run &run, const gradcontact::Medium &medium,
                       FourierMode1Solver &solver, const Clock::time_point start)
  {
    namespace t = gradcontact::tangential;
    const double a = run.a, k = run.k;
    const double R = 50 * a, mu = 0.3, phi = args.num("phi", 0.9);
    const t::SphereSlip slip{R, mu};
    const double F_N = gradcontact::force(medium, gradcontact::Paraboloid{R}, a);
    const double FA  = phi * mu * F_N;
    const double cA  = a * std::pow(1 - FA / (mu * F_N), 1 / (k + 3));
    auto u_fe = [&](const double Fx) {
      const double c = a * std::pow(1 - (FA - Fx) / (2 * mu * F_N), 1 / (k + 3)); // stick radius
      std::vector<double> cuts;
      for (const double b : {cA, c})
        if (b > 0 && b < a * (1 - 1e-12))
          cuts.push_back(b);
      auto tau = [&](const double r) { return t::traction(medium, slip, a, FA, t::Branch::unloading, Fx, r); };
      // The rigid displacement u0 is the surface displacement where nothing ever slipped,
      // r <= c_A: in c_A < r <= c the slip accumulated on loading stays (only the change since
      // A is uniform there).
      const TangentialResult res = solver.run(TangentialLoad::profile(tau, a, cA, cuts));
      return res.stick.mean_ux;
    };
    for (const double f : {0.5, 0.0, -0.5, -1.0})
      {
        const double Fx = f * FA, u = u_fe(Fx);
        const double ref = t::tangential_displacement(medium, slip, a, FA, t::Branch::unloading, Fx);
        std::printf("unloading Fx/FA=%+.2f u0_fe=%.12e u0=%.12e err=%.3e\n", f, u, ref, u / ref - 1);
      }
    const unsigned int      n = static_cast<unsigned>(args.num("n_gauss", 12));
    const dealii::QGauss<1> gauss(n);
    double                  W_fe = 0, W_quad = 0;
    for (unsigned int q = 0; q < n; ++q)
      {
        const double F = FA * (2 * gauss.point(q)[0] - 1), w = 2 * FA * gauss.weight(q);
        // The nodes are symmetric: sum_q w_q [u(F_q) + u(-F_q)] = 2 sum_q w_q u(F_q).
        W_fe += 2 * w * u_fe(F);
        W_quad += 2 * w * t::tangential_displacement(medium, slip, a, FA, t::Branch::unloading, F);
      }
    const double W = t::dissipated_energy(medium, slip, a, FA);
    std::printf("W_fe=%.12e W_quad(closed form)=%.12e W=%.12e err_fe=%.3e quad_err=%.3e fe_vs_quad=%.3e "
                "dofs=%u t_total=%.1f\n", W_fe, W_quad, W, W_fe / W - 1, W_quad / W - 1, W_fe / W_quad - 1,
                solver.n_dofs(), seconds_since(start));
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      const StudyArguments args(argc, argv, "mode1_study");
      if (args.has("load") && args.text("load") == "cylinder")
        {
          run_cylinder(args);
          return 0;
        }
      const Run                 run = parse_run(args);
      const Material            material{std::make_shared<PowerLawModulus>(run.E0, run.c0, run.k), run.nu};
      const gradcontact::Medium medium =
        gradcontact::medium(gradcontact::GradedHalfSpace{run.E0, run.c0, run.k, run.nu});
      print_setting(run);
      const auto         start = Clock::now();
      FourierMode1Solver solver(material, run.mesh, run.disc, plan_refinement(args, run));
      if (run.load_name == "punch")
        run_punch(args, run, material, medium, solver);
      else if (run.load_name == "slip")
        run_slip(args, run, medium, solver, start);
      else if (run.load_name == "osc")
        run_oscillation(args, run, medium, solver, start);
      else
        throw std::invalid_argument("mode1_study: load = " + run.load_name + " outside {punch, slip, osc}");
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << '\n';
      return 1;
    }
  return 0;
}
