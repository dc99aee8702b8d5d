// fem_study: one FE run of the graded half-space with any mesh/discretisation setting, its error against
// the closed form and its timings, the numbers fem/doc/ names. Not a test.
//
//   fem_study load=punch k=0 p=3 h_edge=1e-5 h_surface=0.25 h_far=3 g=1.15 L=1e8 layer=1e-10 R1=4
//             edge_refinements=0 global=0
// load = punch | paraboloid | cone | power (n=, A=) | pressure; pointwise=1 prints p(r) per sample;
// layers=N layer_depth=D/a: N layers with the exact layer means of the power law over [0, D a], uniform, or
// with layer_kind=geometric layer_first=t1/a geometric ones (first thickness t1, ratio from D, N);
// subdiv=m: QIterated copies in cells crossing a layer interface (default 8);
// formulation = displacement | mixed | automatic (nu -> 0.5, fem/doc/model.md "Mixed formulation");
// k = 1 (with nu = 0.5, mixed) is the Gibson medium: references from the Winkler law p = 2 E0 w / (3 c0)
// (9.44); load=pressure then also prints w inside / outside and the transition width at r = a.
//   fem_study load=pressure k=1 nu=0.5 formulation=mixed
// vtu=file.vtu writes the fields (u_r, u_z, and q when mixed, E);
// every key is optional (defaults: the recommended parameters for k). Prints one line per run: key=value pairs.
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/modulus/modulus.h>

#include "study.h"

#include <analytic/material.h>
#include <analytic/normal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <string>

using namespace gradcontact::fem;
using gradcontact::studies::AxisymmetricRun;
using gradcontact::studies::StudyArguments;

namespace
{
  /// The material, the load's name and the mesh and discretisation of one run (AxisymmetricRun).
  struct Run : AxisymmetricRun
  {
    bool gibson = false; ///< k = 1: the Gibson medium, whose reference is the Winkler law
  };

  Run parse_run(const StudyArguments &args)
  {
    Run run;
    static_cast<AxisymmetricRun &>(run) =
      gradcontact::studies::axisymmetric_run(args, [](MeshParameters &mesh) { mesh.axis_refinements = 0; });
    run.gibson = (run.k == 1.0);
    return run;
  }

  /// E0 (z/c0)^k, or its layer means with layers=N (uniform, or geometric with layer_kind=geometric); the geometric
  /// layers' ratio in `layer_ratio`.
  Material make_material(const StudyArguments &args, const Run &run, double &layer_ratio)
  {
    Material material{std::make_shared<PowerLawModulus>(run.E0, run.c0, run.k), run.nu};
    if (!args.has("layers"))
      return material;
    const auto         base     = std::make_shared<PowerLawModulus>(run.E0, run.c0, run.k);
    const unsigned int n_layers = static_cast<unsigned>(args.num("layers", 1));
    const double       depth    = args.num("layer_depth", 1.0) * run.a;
    const std::string  kind     = args.text("layer_kind", "uniform");
    if (kind == "uniform")
      material.modulus = LayeredModulus::uniform(base, n_layers, depth);
    else if (kind == "geometric")
      {
        const double first = args.num("layer_first", 1.0 / n_layers * depth / run.a) * run.a;
        layer_ratio        = LayeredModulus::geometric_ratio(n_layers, first, depth);
        material.modulus   = LayeredModulus::geometric_to_depth(base, n_layers, first, depth);
      }
    else
      throw std::invalid_argument("fem_study: layer_kind = '" + kind + "' is not uniform or geometric");
    return material;
  }

  /// The load of a run, its closed-form force, and where the FE is sampled.
  struct Plan
  {
    LoadCase              load;
    double                reference = 0; ///< the closed-form force
    std::string           control;       ///< radius, depth or force (indenters)
    double                a_true = 0;    ///< the closed form's contact radius
    double                a_ref  = 0;    ///< the radius the errors are relative to
    gradcontact::PowerLaw power{2.0, 1.0};
    OutputRequest         out;
  };

  /// Constant pressure: w on 0 .. 2 a in this many intervals (the Winkler comparison and the transition at r = a).
  constexpr unsigned int n_w = 2000;

  /// The load of `run` and its closed-form force. Indenters: a_true is the contact radius of the closed form; the
  /// mesh is graded at a_mesh = a_true * shift (control=depth|force find the radius on that mesh).
  void plan_load(const StudyArguments &args, const Run &run, const gradcontact::Medium &medium, const double winkler,
                 Plan &plan)
  {
    const double a = run.a;
    plan.control   = args.text("control", "radius");
    plan.a_true    = a / args.num("shift", 1.0);
    plan.power     = gradcontact::PowerLaw{args.num("n", 2.0), args.num("A", 1.0)};
    if (run.load_name == "paraboloid")
      plan.power = gradcontact::as_power_law(gradcontact::Paraboloid{50 * a});
    else if (run.load_name == "cone")
      plan.power = gradcontact::as_power_law(gradcontact::Cone{args.num("tan", 0.1)});
    else if (run.load_name == "power")
      plan.power.A = args.num("A", 0.02) * std::pow(a, 1 - plan.power.n);
    LoadCase &load = plan.load;
    if (run.load_name == "punch")
      {
        load.type      = LoadType::flat_punch;
        load.depth     = 1e-3 * a;
        plan.reference = run.gibson ? M_PI * a * a * winkler * load.depth
                                    : gradcontact::force(medium, gradcontact::FlatPunch{a}, load.depth);
      }
    else if (run.load_name == "pressure")
      {
        load.type      = LoadType::constant_pressure;
        load.pressure  = 1e6;
        plan.reference = M_PI * a * a * load.pressure;
      }
    else
      {
        if (run.gibson)
          throw std::invalid_argument("fem_study: k = 1 (Gibson) supports load = punch | pressure");
        load.profile = Profile::power_law(plan.power.n, plan.power.A);
        if (plan.control == "radius")
          load.type = LoadType::indenter;
        else if (plan.control == "depth")
          {
            load.type  = LoadType::indenter_depth;
            load.depth = gradcontact::depth(medium, plan.power, plan.a_true);
          }
        else
          {
            load.type  = LoadType::indenter_force;
            load.force = gradcontact::force(medium, plan.power, plan.a_true);
          }
        plan.reference = gradcontact::force(medium, plan.power, plan.control == "radius" ? a : plan.a_true);
      }
    plan.a_ref = run.load_name == "punch" || plan.control == "radius" ? a : plan.a_true;
  }

  /// Where the FE is sampled: w on 0 .. 2 a and around r = a (pressure), p(r) inside 0.99 a (punch), w(1.5 a),
  /// w(10 a) and p(r) (indenters); vtu=file.
  void plan_output(const StudyArguments &args, const Run &run, Plan &plan)
  {
    const double   a   = run.a;
    OutputRequest &out = plan.out;
    if (run.load_name == "pressure")
      {
        for (unsigned int i = 0; i <= n_w; ++i)
          out.displacement_radii.push_back(2 * a * i / n_w);
        // and a (1 -+ t), t = 1e-9 .. 1e-1 with 20 points per decade, for the transition width
        for (int j = 0; j <= 160; ++j)
          for (const double sign : {-1.0, 1.0})
            out.displacement_radii.push_back(a * (1 + sign * std::pow(10.0, -9 + j / 20.0)));
        std::sort(out.displacement_radii.begin(), out.displacement_radii.end());
      }
    else if (run.load_name == "punch")
      {
        // p(r) of the punch (singular at r = a): L2 and max pointwise error over r < 0.99 a
        for (unsigned int i = 0; i < 400; ++i)
          out.pressure_radii.push_back(0.99 * a * (i + 0.5) / 400);
      }
    else
      {
        out.displacement_radii = {1.5 * plan.a_ref, 10 * plan.a_ref};
        for (unsigned int i = 0; i < 400; ++i)
          out.pressure_radii.push_back(0.99 * plan.a_ref * (i + 0.5) / 400);
      }
    if (args.has("vtu"))
      out.vtu_file = args.text("vtu");
  }

  /// Constant pressure: prints w against the Winkler value 3 c0 p0 / (2 E0) (Gibson) or w(r) of (9.40): max relative
  /// error inside r <= 0.9 a and outside r >= 1.1 a (relative to w_c), and the transition width: from the first r
  /// where w leaves w_W by more than 10 % (1 %) to the last r where |w| exceeds 10 % (1 %) of w_W (Gibson only).
  void tabulate_pressure(const StudyArguments &args, const Run &run, const gradcontact::Medium &medium,
                         const double winkler, const LoadCase &load, const Result &r)
  {
    const double a         = run.a;
    const bool   gibson    = run.gibson;
    const double w_winkler = load.pressure / winkler;
    double       in = 0, out_max = 0;
    // first r off the inside value / last r off zero by more than 10 % and 1 % of w_W
    double first_off[2] = {2 * a, 2 * a}, last_off[2] = {0, 0};
    for (const Sample &s : r.displacement)
      {
        const double w_ref = gibson ? (s.r <= a ? w_winkler : 0.0)
                                    : gradcontact::displacement(medium, gradcontact::UniformPressure{a, load.pressure}, s.r);
        const double scale = gibson ? w_winkler : gradcontact::centre_displacement(medium, gradcontact::UniformPressure{a, load.pressure});
        if (s.r <= 0.9 * a)
          in = std::max(in, std::abs(s.value - w_ref) / scale);
        if (s.r >= 1.1 * a)
          out_max = std::max(out_max, std::abs(s.value - w_ref) / scale);
        for (unsigned int b = 0; b < 2; ++b)
          {
            const double band = (b == 0 ? 0.1 : 0.01) * w_winkler;
            if (std::abs(s.value - w_winkler) > band)
              first_off[b] = std::min(first_off[b], s.r);
            if (std::abs(s.value) > band)
              last_off[b] = std::max(last_off[b], s.r);
          }
        if (args.has("pointwise"))
          std::printf("r/a=%.6e w_fe=%.10e w_ref=%.10e\n", s.r / a, s.value, w_ref);
      }
    std::printf("pressure: w_c/w_ref-1=%.3e max|w-w_ref|/w_c in r<=0.9a=%.3e out r>=1.1a=%.3e "
                "w(a)/w_winkler=%.4f transition_10%%/a=%.3e transition_1%%/a=%.3e\n",
                r.depth / (gibson ? w_winkler : gradcontact::centre_displacement(medium, gradcontact::UniformPressure{a, load.pressure})) - 1,
                in, out_max, r.displacement[n_w / 2 + 161].value / w_winkler, (last_off[0] - first_off[0]) / a,
                (last_off[1] - first_off[1]) / a);
  }

  /// The flat punch: p(r) against (9.16)'s pressure (L2 into p_err, and the largest pointwise error printed) and how
  /// close the power law is to the Winkler limit (9.44): the closed-form force over pi a^2 k_W d.
  void tabulate_punch(const Run &run, const gradcontact::Medium &medium, const double winkler, const LoadCase &load,
                      const Result &r, double &p_err)
  {
    const double a = run.a;
    double       p_max = 0, p_norm = 0;
    for (const Sample &s : r.pressure)
      {
        const double p = run.gibson ? winkler * load.depth
                                    : gradcontact::pressure(medium, gradcontact::FlatPunch{a}, load.depth, s.r);
        p_err += (s.value - p) * (s.value - p) * s.r;
        p_norm += p * p * s.r;
        p_max = std::max(p_max, std::abs(s.value / p - 1));
      }
    p_err = std::sqrt(p_err / p_norm);
    std::printf("punch: p_max_rel=%.3e F_closed/F_winkler=%.6f\n", p_max,
                run.gibson ? 1.0 : gradcontact::force(medium, gradcontact::FlatPunch{a}, load.depth) /
                                     (M_PI * a * a * winkler * load.depth));
  }

  /// An indenter: w(1.5 a), w(10 a) and p(r) (L2) against the closed form, at the FE depth under radius control
  /// (whose force then becomes the reference) and at the closed-form state under depth or force control.
  void tabulate_indenter(const StudyArguments &args, const gradcontact::Medium &medium, const Result &r, Plan &plan,
                         double (&w_err)[2], double &p_err)
  {
    const double a_cmp = plan.control == "radius" ?
                           gradcontact::contact_radius_from_depth(medium, plan.power, r.depth) : plan.a_true;
    for (unsigned int i = 0; i < 2; ++i)
      {
        const double w = gradcontact::displacement(medium, plan.power, a_cmp, r.displacement[i].r);
        w_err[i]       = r.displacement[i].value / w - 1;
      }
    double p_norm = 0;
    for (const Sample &s : r.pressure)
      {
        const double p = gradcontact::pressure(medium, plan.power, a_cmp, s.r);
        if (args.has("pointwise"))
          std::printf("r/a=%.6e p_fe=%.10e p_exact=%.10e rel=%.3e\n", s.r / plan.a_ref, s.value, p, s.value / p - 1);
        p_err += (s.value - p) * (s.value - p) * s.r;
        p_norm += p * p * s.r;
      }
    p_err = std::sqrt(p_err / p_norm);
    if (plan.control == "radius")
      plan.reference = gradcontact::force(medium, plan.power, a_cmp);
  }

  /// The run's line: key=value pairs of the setting, the errors, the solver's counts and the times of its phases.
  void print_run(const Run &run, const gradcontact::Medium &medium, const Plan &plan, const Result &r,
                 const double (&w_err)[2], const double p_err, const double layer_ratio, const double total)
  {
    const bool no_radius = run.load_name == "punch" || run.load_name == "pressure";
    std::printf("formulation=%s nu=%g ", r.formulation == Formulation::mixed ? "mixed" : "displacement", run.nu);
    std::printf("load=%s control=%s k=%g p=%u h_edge=%g L=%g dofs=%u F_error=%.3e a_error=%.3e d_error=%.3e "
                "w1.5_error=%.2e w10_error=%.2e p_L2=%.2e iterations=%u set=%u mismatch=%.1e mesh=%.2f "
                "setup=%.2f assemble=%.2f factorize=%.2f solve=%.2f post=%.2f total=%.2f rings=%u "
                "layer_ratio=%.6g far_scale=%.6g far_deviation=%.1e doublings=%u %s\n",
                run.load_name.c_str(), plan.control.c_str(), run.k, run.disc.degree, run.mesh.h_edge,
                run.mesh.far_field_size, r.n_dofs, r.force / plan.reference - 1,
                no_radius ? 0.0 : r.contact_radius / plan.a_ref - 1,
                no_radius ? 0.0 : r.depth / gradcontact::depth(medium, plan.power, plan.a_ref) - 1,
                w_err[0], w_err[1], p_err, r.iterations, r.active_set_size, r.energy_mismatch, r.time.mesh,
                r.time.setup, r.time.assemble, r.time.factorize, r.time.solve, r.time.postprocess, total,
                r.mesh.n_rings, layer_ratio, r.far_field_ring_scale, r.far_field_self_similarity,
                r.far_field_doublings, r.message.c_str());
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      const StudyArguments args(argc, argv, "fem_study");
      const Run            run   = parse_run(args);
      const auto           start = std::chrono::steady_clock::now();
      double               layer_ratio = 0;
      const Material       material    = make_material(args, run, layer_ratio);
      AxisymmetricSolver   solver(material, run.mesh, run.disc);
      // The closed forms of chapter 9.1 need k < 1; the Gibson medium (k = 1) has the Winkler law.
      const gradcontact::Medium medium =
        gradcontact::medium(gradcontact::GradedHalfSpace{run.E0, run.c0, run.gibson ? 0.0 : run.k, run.nu});
      const double winkler = gradcontact::gibson_winkler_modulus(run.E0, run.c0); // p / w, 9.44
      Plan         plan;
      plan_load(args, run, medium, winkler, plan);
      plan_output(args, run, plan);
      const Result r     = solver.run(plan.load, plan.out);
      const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      double       w_err[2] = {0, 0}, p_err = 0;
      if (run.load_name == "pressure")
        tabulate_pressure(args, run, medium, winkler, plan.load, r);
      else if (run.load_name == "punch")
        tabulate_punch(run, medium, winkler, plan.load, r, p_err);
      else
        tabulate_indenter(args, medium, r, plan, w_err, p_err);
      print_run(run, medium, plan, r, w_err, p_err, layer_ratio, total);
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << '\n';
      return 1;
    }
}
