#include "model/coulomb_sphere.h"
#include "report/report.h"

#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/tangential.h>
#include <fem/bodies/half_space_3d.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace gradcontact::cases
{
  std::string to_string(const CoulombPathKind kind)
  {
    switch (kind)
      {
        case CoulombPathKind::decoupled:
          return "decoupled";
        case CoulombPathKind::idealised:
          return "idealised";
        case CoulombPathKind::fe:
          break;
      }
    return "fe";
  }

  namespace
  {
    /// into = max(into, v), a NaN `into` (nothing recorded yet) taking v.
    void worse(double &into, const double v) { into = std::isnan(into) ? v : std::max(into, v); }

    /// Simpson's rule over equally spaced samples (an even number of intervals).
    double simpson(const std::vector<double> &y, const double h)
    {
      double sum = y.front() + y.back();
      for (std::size_t i = 1; i + 1 < y.size(); ++i)
        sum += (i % 2 ? 4 : 2) * y[i];
      return sum * h / 3;
    }
  } // namespace

  CoulombSphereResult run_coulomb_sphere(const MPI_Comm communicator, const CoulombSphereCase &c,
                                         const std::function<void(const CoulombSphereStep &, const fem::SurfaceCompliance3D &)> &on_step)
  {
    return run_coulomb_sphere(communicator, c, prepare_coulomb_sphere(communicator, c), on_step);
  }

  namespace
  {
    /// The chapter's sphere of a case (9.24 family, 9.80-9.86): the contact radius at the depth, full sliding at
    /// delta >= mu alpha d (9.80 at c = 0), and in partial slip F_A with u_A, delta_A as 9.85 returns it from F_A
    /// (the branches' domain; equal to delta_A up to round-off).
    struct SphereTheory
    {
      gradcontact::Medium                 medium;
      gradcontact::tangential::SphereSlip slip;
      double                              a, force_n, full_slip, force_a, u_A;
      bool                                partial;

      double on_branch(const double u) const { return std::clamp(u, -u_A, u_A); }
      /// Whether the tangential steps have closed forms to compare with.
      bool compared(const CoulombSphereCase &c) const { return partial && std::isfinite(c.mu); }
    };

    /// The theory of case `c`, its a(d), F_N(a) and F_A also into `result`.
    SphereTheory sphere_theory(const CoulombSphereCase &c, CoulombSphereResult &result)
    {
      using namespace gradcontact::tangential;
      const Medium       medium = gradcontact::medium(GradedHalfSpace{c.E0, c.c0, c.k, c.nu});
      const Paraboloid   sphere{c.R};
      const SphereSlip   slip{c.R, c.mu};
      const double       a  = contact_radius_from_depth(medium, as_power_law(sphere), c.depth);
      result.a_theory       = a;
      result.force_n_theory = gradcontact::force(medium, sphere, a);
      const double full_slip = std::isfinite(c.mu) ? c.mu * medium.alpha() * c.depth : std::numeric_limits<double>::infinity();
      const bool   partial   = c.delta > 0 && c.delta < full_slip;
      double u_A = 0;
      if (partial && std::isfinite(c.mu))
        {
          result.force_a_theory = tangential_force(medium, slip, a, a * std::sqrt(1 - c.delta / full_slip));
          u_A                   = displacement_at_A(medium, slip, a, result.force_a_theory);
        }
      return SphereTheory{medium, slip, a, result.force_n_theory, full_slip, result.force_a_theory, u_A, partial};
    }

    using StepCallback = std::function<void(const CoulombSphereStep &, const fem::SurfaceCompliance3D &)>;

    /// One loading path on the compliance `C` as it runs: the contact, the path so far, and the worst stick-zone
    /// measures and the friction work of the cycle accumulated over its steps.
    struct PathRun
    {
      PathRun(const CoulombSphereCase &c, const SphereTheory &theory, const fem::SurfaceCompliance3D &C,
              const CoulombPathKind kind, const StepCallback &on_step)
        : c(c), theory(theory), C(C), kind(kind), on_step(on_step),
          contact(C, fem::Profile::paraboloid(c.R), [&c] {
            fem::CoulombParameters friction;
            friction.mu = c.mu_normal;
            return friction;
          }())
      {}
      const CoulombSphereCase        &c;
      const SphereTheory             &theory;
      const fem::SurfaceCompliance3D &C;
      const CoulombPathKind           kind;
      const StepCallback             &on_step;
      fem::CoulombContact3D           contact;
      CoulombPath                     path;
      double worst_c = 0, worst_half = 0, worst_round = 0;
      double cycle_work = 0; // the friction work of the unloading and reloading steps
      bool   stick_found = false;
    };

    /// A tangential step `s` against the chapter: F_x on loading (9.80), on the branches (9.84, / F_A), and the
    /// stick zone along the rays the mesh has nodes on.
    void compare_with_theory(PathRun &run, CoulombSphereStep &s, const double delta, const gradcontact::tangential::Branch branch)
    {
      using namespace gradcontact::tangential;
      const SphereTheory &t = run.theory;
      const double a = t.a;
      if (branch == Branch::loading)
        {
          s.theory_stick   = a * std::sqrt(1 - delta / t.full_slip);
          s.theory_force_x = tangential_force(t.medium, t.slip, a, s.theory_stick);
          worse(run.path.loading_deviation, std::abs(s.state.force_x / s.theory_force_x - 1));
        }
      else
        {
          s.theory_force_x = hysteresis_force(t.medium, t.slip, a, t.force_a, branch, t.on_branch(delta));
          // (the force at +-u_A is +-F_A up to round-off, which may put it a few ulps outside)
          s.theory_stick = reversal_radius(t.medium, t.slip, a, t.force_a, branch,
                                           std::clamp(s.theory_force_x, -t.force_a, t.force_a));
          worse(run.path.branch_deviation, std::abs(s.state.force_x - s.theory_force_x) / t.force_a);
        }
      double lo = std::numeric_limits<double>::infinity(), hi = 0;
      for (const fem::RayBracket &ray : s.shape.stick)
        if (ray.nodes > 0)
          {
            run.worst_c        = std::max(run.worst_c, std::abs(ray.radius() - s.theory_stick) / a);
            run.worst_half     = std::max(run.worst_half, ray.half_width() / a);
            lo                 = std::min(lo, ray.radius());
            hi                 = std::max(hi, ray.radius());
            run.stick_found = true;
          }
      if (hi >= lo)
        run.worst_round = std::max(run.worst_round, (hi - lo) / a);
    }

    /// One step of `run`: solve, measure, compare; false when it did not converge (the path stops).
    bool coulomb_step(PathRun &run, const std::string &phase, const double d, const double delta,
                      const gradcontact::tangential::Branch branch)
    {
      CoulombPath &path = run.path;
      CoulombSphereStep s;
      s.phase = phase;
      s.path  = run.kind;
      s.state = run.contact.step_depth(d, delta);
      s.shape = fem::zone_shape(run.C, s.state);
      // the work of friction of the cycle
      if (phase == "unloading" || phase == "reloading")
        add_friction_work(s.state, run.cycle_work);
      path.max_iterations = std::max(path.max_iterations, s.state.iterations);
      if (phase != "normal") // the slip of the normal loading is radial
        {
          path.slip_angle   = std::max(path.slip_angle, s.shape.slip_angle);
          path.slip_force_y = std::max(path.slip_force_y, s.shape.slip_force_y);
        }
      if (phase == "normal")
        path.normal_slip = std::max(path.normal_slip, s.state.n_slip);
      else if (run.theory.compared(run.c))
        compare_with_theory(run, s, delta, branch);
      if (!s.state.converged && path.converged)
        {
          path.converged = false;
          path.message   = phase + " step: " + s.state.message;
        }
      if (run.on_step)
        run.on_step(s, run.C);
      s.state.status.clear(); // the per-node vectors are the callback's only
      s.state.nodal_force.clear();
      s.state.displacement.clear();
      s.state.slip.clear();
      path.steps.push_back(std::move(s));
      return path.steps.back().state.converged;
    }

    /// The cycle after the tangential loading: unloading to -delta_A and reloading to delta_A, then the closure,
    /// the loop area and the friction work.
    void run_cycle(PathRun &run)
    {
      using gradcontact::tangential::Branch;
      const CoulombSphereCase &c = run.c;
      CoulombPath             &path = run.path;
      const unsigned int       m = c.tangential_steps;
      bool                     ok = true;
      const double        loaded = path.steps.back().state.force_x;
      std::vector<double> unloading{loaded}, reloading;
      for (unsigned int j = 1; ok && j <= 2 * m; ++j)
        {
          ok = coulomb_step(run, "unloading", c.depth, c.delta * (1.0 - 1.0 * j / m), Branch::unloading);
          unloading.push_back(path.steps.back().state.force_x);
        }
      if (ok)
        reloading.push_back(unloading.back());
      for (unsigned int j = 1; ok && j <= 2 * m; ++j)
        {
          ok = coulomb_step(run, "reloading", c.depth, c.delta * (-1.0 + 1.0 * j / m), Branch::reloading);
          reloading.push_back(path.steps.back().state.force_x);
        }
      if (!ok)
        return;
      path.closure = std::abs(reloading.back() / loaded - 1);
      // The loop area: the unloading branch runs from +delta_A down, the reloading one from -delta_A up;
      // at the same delta the reloading force is the larger (the loop is run counter-clockwise in the
      // (F_x, delta) plane).
      std::reverse(unloading.begin(), unloading.end());
      std::vector<double> gap(unloading.size());
      for (std::size_t i = 0; i < gap.size(); ++i)
        gap[i] = reloading[i] - unloading[i];
      path.energy        = simpson(gap, c.delta / m);
      path.friction_work = run.cycle_work;
    }

    /// One loading path on the compliance `C`: normal loading to the depth, then (delta > 0) tangential loading and
    /// the cycle.
    CoulombPath run_path(const CoulombSphereCase &c, const SphereTheory &theory, const fem::SurfaceCompliance3D &C,
                         const CoulombPathKind kind, const StepCallback &on_step)
    {
      using gradcontact::tangential::Branch;
      PathRun      run(c, theory, C, kind, on_step);
      CoulombPath &path = run.path;
      bool ok = true;
      for (unsigned int i = 1; ok && i <= c.normal_steps; ++i)
        ok = coulomb_step(run, "normal", c.depth * i / c.normal_steps, 0.0, Branch::loading);
      if (ok)
        path.force_z_deviation = path.steps.back().state.force_z / theory.force_n - 1;
      if (ok && c.delta > 0)
        {
          run.contact.set_friction(c.mu);
          const unsigned int m = c.tangential_steps;
          for (unsigned int j = 1; ok && j <= m; ++j)
            ok = coulomb_step(run, "loading", c.depth, c.delta * j / m, Branch::loading);
          if (ok && c.cycle)
            run_cycle(run);
          if (run.stick_found)
            {
              path.stick_deviation  = run.worst_c;
              path.stick_resolution = run.worst_half;
              path.out_of_round     = run.worst_round;
            }
        }
      return std::move(path);
    }

    /// 9.86, and Simpson's rule on the closed-form loop at the points of the FE's steps, into `result`.
    void energy_theory(const CoulombSphereCase &c, const SphereTheory &t, CoulombSphereResult &result)
    {
      using namespace gradcontact::tangential;
      result.energy_theory  = dissipated_energy(t.medium, t.slip, t.a, result.force_a_theory);
      const unsigned int  m = c.tangential_steps;
      std::vector<double> closed(2 * m + 1);
      for (std::size_t i = 0; i < closed.size(); ++i)
        {
          const double u = t.on_branch(-c.delta + i * c.delta / m);
          closed[i]      = hysteresis_force(t.medium, t.slip, t.a, result.force_a_theory, Branch::reloading, u) -
                      hysteresis_force(t.medium, t.slip, t.a, result.force_a_theory, Branch::unloading, u);
        }
      result.energy_rule = simpson(closed, c.delta / m) / result.energy_theory - 1;
    }

    /// Path x against path y: F_x on loading relative, on the branches relative to y's F_x at delta_A, and the
    /// stick radius along the rays / a (when `stick` is set).
    void against(const CoulombSphereCase &c, const double a, const CoulombPath &px, const CoulombPath &py,
                 double &loading, double &branch, double *stick)
    {
      const std::vector<CoulombSphereStep> &x = px.steps, &y = py.steps;
      const std::size_t loaded = c.normal_steps + c.tangential_steps - 1;
      const double scale = x.size() > loaded && y.size() > loaded ? std::abs(y[loaded].state.force_x) : 0.;
      for (std::size_t i = c.normal_steps; i < std::min(x.size(), y.size()); ++i)
        {
          if (x[i].phase == "loading")
            worse(loading, std::abs(x[i].state.force_x / y[i].state.force_x - 1));
          else if (scale > 0)
            worse(branch, std::abs(x[i].state.force_x - y[i].state.force_x) / scale);
          if (stick)
            for (unsigned int ray = 0; ray < 3; ++ray)
              if (x[i].shape.stick[ray].nodes > 0)
                worse(*stick, std::abs(x[i].shape.stick[ray].radius() - y[i].shape.stick[ray].radius()) / a);
        }
    }
  } // namespace

  CoulombSphereResult run_coulomb_sphere(const MPI_Comm communicator, const CoulombSphereCase &c,
                                         const CoulombSphereSurface &prepared,
                                         const std::function<void(const CoulombSphereStep &, const fem::SurfaceCompliance3D &)> &on_step)
  {
    c.validate();
    if (prepared.k != c.k || prepared.nu != c.nu)
      throw std::invalid_argument("run_coulomb_sphere: the prepared surface is of k = " + std::to_string(prepared.k) +
                                  ", nu = " + std::to_string(prepared.nu) + ", the case of k = " + std::to_string(c.k) +
                                  ", nu = " + std::to_string(c.nu));
    const auto          start = std::chrono::steady_clock::now();
    CoulombSphereResult result;
    const fem::SurfaceCompliance3D &surface = prepared.compliance;
    result.compliance_seconds = prepared.seconds;
    result.dofs          = prepared.dofs;
    result.surface_nodes = surface.nodes.size();
    result.unknowns      = surface.C.m();
    result.processes     = dealii::Utilities::MPI::n_mpi_processes(communicator);

    const SphereTheory theory = sphere_theory(c, result);
    if (c.cycle && theory.compared(c))
      energy_theory(c, theory, result);
    result.fe = run_path(c, theory, surface, CoulombPathKind::fe, on_step);
    if (c.decoupled_reference)
      {
        result.decoupled = run_path(c, theory, fem::without_coupling(surface), CoulombPathKind::decoupled, on_step);
        const std::vector<CoulombSphereStep> &x = result.fe.steps, &y = result.decoupled.steps;
        if (x.size() >= c.normal_steps && y.size() >= c.normal_steps)
          result.coupling_force_z =
            x[c.normal_steps - 1].state.force_z / y[c.normal_steps - 1].state.force_z - 1;
        against(c, theory.a, result.fe, result.decoupled, result.coupling_loading, result.coupling_branch,
                &result.coupling_stick);
        result.coupling_energy = result.fe.energy / result.decoupled.energy - 1;
      }
    if (c.idealised_reference)
      {
        result.idealised = run_path(c, theory, fem::without_coupling(fem::along_load(surface)), CoulombPathKind::idealised,
                                    on_step);
        against(c, theory.a, result.decoupled, result.idealised, result.direction_loading, result.direction_branch, nullptr);
        result.direction_energy = result.decoupled.energy / result.idealised.energy - 1;
      }
    dealii::Utilities::System::MemoryStats memory;
    dealii::Utilities::System::get_memory_stats(memory);
    result.memory_mb = dealii::Utilities::MPI::max(static_cast<double>(memory.VmHWM) / 1024, communicator);
    result.seconds   = prepared.seconds + dealii::Utilities::MPI::max(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), communicator);
    return result;
  }

  std::pair<double, double> fe_stick_radius(const CoulombIndenterStep &step)
  {
    if (!step.stick_radius)
      throw std::runtime_error("the 3D mesh has no surface nodes on the rays of the stick zone");
    return {*step.stick_radius, step.stick_half_width};
  }

  std::vector<CoulombIndenterStep> run_coulomb_indenter(const MPI_Comm communicator, const CoulombSphereCase &body,
                                                        const fem::Profile &indenter, const unsigned int steps,
                                                        unsigned int &dofs)
  {
    const CoulombSphereSurface surface = prepare_coulomb_sphere(communicator, body);
    dofs                               = static_cast<unsigned int>(surface.dofs);
    fem::CoulombParameters friction;
    friction.mu = body.mu;
    fem::CoulombContact3D            contact(surface.compliance, indenter, friction);
    std::vector<CoulombIndenterStep> path;
    const auto step = [&](const std::string &phase, const Branch branch, const double d, const double delta) {
      const fem::CoulombState3D state = contact.step_depth(d, delta);
      if (!state.converged)
        throw std::runtime_error(phase + " step to d = " + format(d) + ", delta = " + format(delta) +
                                 " did not converge: " + state.message);
      CoulombIndenterStep st;
      st.branch  = branch;
      st.delta   = state.delta;
      st.force_x = state.force_x;
      double sum = 0;
      int    n   = 0;
      for (const fem::RayBracket &ray : fem::zone_shape(surface.compliance, state).stick)
        if (ray.nodes > 0)
          sum += ray.radius(), st.stick_half_width = std::max(st.stick_half_width, ray.half_width()), ++n;
      if (n > 0)
        st.stick_radius = sum / n;
      add_friction_work(state, st.friction_work);
      path.push_back(st);
    };
    for (unsigned int i = 1; i <= steps; ++i)
      step("normal", Branch::loading, body.depth * i / steps, 0.);
    path.clear(); // the tangential steps only
    for (unsigned int j = 1; j <= steps; ++j)
      step("loading", Branch::loading, body.depth, body.delta * j / steps);
    for (unsigned int j = 1; j <= 2 * steps; ++j)
      step("unloading", Branch::unloading, body.depth, body.delta * (1. - 1. * j / steps));
    for (unsigned int j = 1; j <= 2 * steps; ++j)
      step("reloading", Branch::reloading, body.depth, body.delta * (-1. + 1. * j / steps));
    return path;
  }
} // namespace gradcontact::cases
