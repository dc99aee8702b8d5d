// ladder_study: the contract ladder of one point, every level of it, against the closed form. Not a test.
//
//   ladder_study k=0 nu=0.3 e0=1 load=punch|paraboloid tol=1e-6 p=3 levels=5 max_dofs=1.2e6 w=2 pr=0.5 [sr=0 sz=0.1]
// Prints, per level, the DoFs, the force (and the depth under a paraboloid), w(w a) and p(pr a), their true
// relative errors, the level-to-level ratios, and the contract's estimate; p overrides the degree of the ladder.
// With sz: the recovered stresses at (sr a, sz a) too, each relative to the largest of them.
// mode=p p_min=2 p_max=6: the degree ladder on the level-0 mesh instead (no estimate).
#include <fem/accuracy/accuracy.h>
#include <fem/modulus/modulus.h>

#include "study_arguments.h"

#include <analytic/batch.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

using namespace gradcontact;
using namespace gradcontact::fem;
using gradcontact::studies::StudyArguments;

namespace
{
  /// One point: E0 = c0 = 1, the flat punch of depth 1 or the paraboloid R = 1 at contact radius 1, sampled at
  /// w(w a) and p(pr a).
  struct Point
  {
    double k = 0, nu = 0.3, e0 = 1, tol = 1e-8, w_r = 2, p_r = 0.5, s_r = 0, s_z = -1;
    bool   punch = true;
  };

  Point parse_point(const StudyArguments &args)
  {
    Point pt;
    pt.k     = args.num("k", 0);
    pt.nu    = args.num("nu", 0.3);
    pt.e0    = args.num("e0", 1);
    pt.tol   = args.num("tol", 1e-8);
    pt.w_r   = args.num("w", 2);
    pt.p_r   = args.num("pr", 0.5);
    pt.punch = args.text("load", "punch") == "punch";
    pt.s_r   = args.num("sr", 0);
    pt.s_z   = args.num("sz", -1);
    return pt;
  }

  /// The contract's settings for the point; p= overrides the degree, the mesh and discretisation keys apply.
  Settings ladder_settings_of(const StudyArguments &args, const Material &material, const Point &pt)
  {
    Settings s = contract_settings(1., material, pt.tol, pt.w_r);
    if (args.has("p"))
      s.discretization.degree = static_cast<unsigned>(args.num("p", 2));
    args.apply(s.mesh);
    args.apply(s.discretization);
    return s;
  }

  /// mode=p: the degree ladder, degrees p_min .. p_max on the level-0 mesh, with e_step more edge refinements and the
  /// surface layer thinner by layer_step per degree (no estimate).
  ContractResult degree_ladder(const StudyArguments &args, const Material &material, const Settings &s,
                               const LoadCase &load, const OutputRequest &out)
  {
    ContractResult c;
    const unsigned p_min = static_cast<unsigned>(args.num("p_min", 2)), p_max = static_cast<unsigned>(args.num("p_max", 6));
    const unsigned e_step = static_cast<unsigned>(args.num("e_step", 0));
    const double   layer_step = args.num("layer_step", 1);
    c.degree = p_max;
    c.force.scale = 1;
    for (unsigned p = p_min; p <= p_max; ++p)
      {
        Settings t = s;
        t.discretization.degree = p;
        t.mesh.edge_refinements += e_step * (p - p_min);
        t.mesh.surface_layer_thickness *= std::pow(layer_step, p - p_min);
        if (t.discretization.surface_map.enabled && args.has("floor_follows"))
          t.discretization.surface_map.floor = t.mesh.h_edge * std::pow(0.5, t.mesh.edge_refinements);
        AxisymmetricSolver level(material, t.mesh, t.discretization);
        const Result r = level.run(load, out);
        c.level_dofs.push_back(r.n_dofs);
        c.force.levels.push_back(r.force);
        c.depth.levels.push_back(r.depth);
        if (c.displacement.empty())
          c.displacement.resize(1), c.pressure.resize(1);
        c.displacement[0].levels.push_back(r.displacement[0].value);
        c.pressure[0].levels.push_back(r.pressure[0].value);
        c.pressure[0].scale = std::abs(r.pressure[0].value);
        if (!r.reliable)
          std::printf("degree %u unreliable: %s\n", p, r.message.c_str());
      }
    return c;
  }

  /// The closed form of `quantity` at the point (analytic/batch.h), at radius r (r < 0: none).
  double exact(const Point &pt, const std::string &quantity, const double r, const std::string &component = "")
  {
    nlohmann::json q = {{"case", pt.punch ? "flat_punch" : "paraboloid"}, {"quantity", quantity}, {"a", 1.0},
                        {"material", {{"E0", pt.e0}, {"c0", 1.0}, {"k", pt.k}, {"nu", pt.nu}}}};
    if (pt.punch)
      q["d"] = 1.0;
    else
      q["geometry"] = {{"R", 1.0}};
    if (r >= 0)
      q["r"] = r;
    if (!component.empty())
      q["z"] = pt.s_z, q["component"] = component;
    return batch::evaluate(batch::parse(q));
  }

  /// One quantity level by level: its value, true relative error and the ratio of consecutive changes.
  void show(const ContractResult &c, const char *name, const Estimated &e, const double ref, const double scale)
  {
    std::printf("  %s exact=%.15g estimate=%.2e\n", name, ref, e.relative());
    for (std::size_t l = 0; l < e.levels.size(); ++l)
      {
        const double err = (e.levels[l] - ref) / scale;
        const double ratio =
          l >= 2 ? (e.levels[l] - e.levels[l - 1]) / (e.levels[l - 1] - e.levels[l - 2]) : std::nan("");
        std::printf("    level %zu dofs %8llu value %.15g rel.error %+.3e ratio %+.3f\n", l,
                    static_cast<unsigned long long>(c.level_dofs[l]), e.levels[l], err, ratio);
      }
  }

  void tabulate(const Point &pt, const ContractResult &c)
  {
    const double F = exact(pt, "force", -1), W = exact(pt, "displacement", pt.w_r), P = exact(pt, "pressure", pt.p_r);
    const double D = pt.punch ? 1.0 : exact(pt, "depth", -1);
    std::printf("k=%g nu=%g degree=%u levels=%zu limit=%s\n", pt.k, pt.nu, c.degree, c.level_dofs.size(),
                c.limit.c_str());
    show(c, "force", c.force, F, std::abs(F));
    if (!pt.punch)
      show(c, "depth", c.depth, D, std::abs(D));
    if (!c.displacement.empty())
      show(c, "w", c.displacement[0], W, std::abs(W));
    if (!c.pressure.empty())
      show(c, "p", c.pressure[0], P, c.pressure[0].scale);
    if (!c.stress.empty())
      {
        const char *names[4] = {"rr", "zz", "tt", "rz"};
        for (unsigned i = 0; i < 4; ++i)
          show(c, (std::string("sigma_") + names[i]).c_str(), c.stress[0][i], exact(pt, "stress", pt.s_r, names[i]),
               c.stress[0][i].scale);
      }
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      const StudyArguments args(argc, argv, "ladder_study");
      const Point          pt = parse_point(args);
      Material             material{std::make_shared<PowerLawModulus>(pt.e0, 1., pt.k), pt.nu};
      const Settings       s = ladder_settings_of(args, material, pt);
      AccuracyBudget       budget;
      budget.max_levels = static_cast<unsigned>(args.num("levels", 5));
      budget.max_dofs   = static_cast<dealii::types::global_dof_index>(args.num("max_dofs", 1.2e6));
      ContractSolver solver(material, s, pt.tol, budget);
      LoadCase       load;
      if (pt.punch)
        load.type = LoadType::flat_punch, load.depth = 1;
      else
        load.type = LoadType::indenter, load.profile = Profile::paraboloid(1);
      OutputRequest out;
      out.displacement_radii = {pt.w_r};
      out.pressure_radii     = {pt.p_r};
      if (pt.s_z >= 0)
        out.stress_points = {{pt.s_r, pt.s_z}};
      const ContractResult c =
        args.text("mode", "h") == "p" ? degree_ladder(args, material, s, load, out) : solver.run(load, out);
      tabulate(pt, c);
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << '\n';
      return 1;
    }
}
