#include "scene/scene.h"

#include "scene/expression.h"

#include "report/report.h"

#include <deal.II/base/utilities.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace gradcontact::cases
{
  using dealii::ParameterHandler;
  using dealii::Utilities::trim;
  namespace Patterns = dealii::Patterns;

  namespace
  {
    std::vector<double> to_doubles(const std::string &list)
    {
      std::vector<double> out;
      for (const std::string &item : dealii::Utilities::split_string_list(list))
        if (!item.empty())
          out.push_back(dealii::Utilities::string_to_double(item));
      return out;
    }

    // A list of non-negative numbers.
    const Patterns::List double_list(Patterns::Double(0.), 0, 1000);

    // An entry's text, once its pattern has matched, as its member's type (the conversions of get_double & co.).
    void assign(double &x, const std::string &text) { x = dealii::Utilities::string_to_double(text); }
    void assign(unsigned int &x, const std::string &text)
    {
      x = static_cast<unsigned int>(dealii::Utilities::string_to_int(text));
    }
    void assign(bool &x, const std::string &text) { x = text == "true" || text == "yes"; }
    void assign(std::string &x, const std::string &text) { x = text; }
    void assign(std::vector<double> &x, const std::string &text) { x = to_doubles(text); }

    /// Declares an entry and binds `variable` to it: ParameterHandler::add_parameter, but with the default
    /// text as written (add_parameter writes the variable's value with six digits, which rounds a default
    /// such as 1.000001 and rewrites 1e9 as 1e+09 in --help-scene and the resolved scene). The action runs
    /// on the default now, and on every value the file or an override sets.
    template <typename T>
    void add(ParameterHandler &prm, const std::string &name, T &variable, const std::string &default_text,
             const Patterns::PatternBase &pattern, const std::string &documentation)
    {
      prm.declare_entry(name, default_text, pattern, documentation);
      prm.add_action(name, [&variable](const std::string &text) { assign(variable, text); });
    }

    /// The values of a Selection entry, each with its name in a scene, in the order the pattern lists them.
    template <typename T>
    using Choices = std::vector<std::pair<T, std::string>>;

    /// A Selection entry bound to `variable`: its name's value.
    template <typename T>
    void add_choice(ParameterHandler &prm, const std::string &name, T &variable, const Choices<T> &choices,
                    const std::string &default_name, const std::string &documentation)
    {
      std::string names;
      for (const auto &choice : choices)
        names += (names.empty() ? "" : "|") + choice.second;
      prm.declare_entry(name, default_name, Patterns::Selection(names), documentation);
      prm.add_action(name, [&variable, choices](const std::string &text) {
        for (const auto &choice : choices)
          if (choice.second == text)
            variable = choice.first;
      });
    }

    using Modulus = MaterialParameters::Modulus;
    /// Material/modulus: each representation of E(z) and its name in a scene.
    const Choices<Modulus> modulus_names{{Modulus::power_law, "power law"},
                                         {Modulus::layered, "layered"},
                                         {Modulus::expression, "expression"},
                                         {Modulus::shifted_power_law, "shifted power law"},
                                         {Modulus::coating, "coating"},
                                         {Modulus::table, "table"},
                                         {Modulus::error_function, "error function"}};
    using Load = LoadParameters;
    const Choices<Load::Type> load_types{{Load::Type::flat_punch, "flat punch"},
                                         {Load::Type::paraboloid, "paraboloid"},
                                         {Load::Type::cone, "cone"},
                                         {Load::Type::power_law, "power law"},
                                         {Load::Type::concave_punch, "concave punch"},
                                         {Load::Type::constant_pressure, "constant pressure"}};
    const Choices<Load::Control> load_controls{{Load::Control::contact_radius, "contact radius"},
                                               {Load::Control::depth, "depth"},
                                               {Load::Control::force, "force"}};
    const Choices<Load::Contact> contacts{{Load::Contact::disc, "disc"}, {Load::Contact::unilateral, "unilateral"}};
    using Elasticity = IndenterParameters::Elasticity;
    const Choices<Elasticity> elasticities{{Elasticity::rigid, "rigid"},
                                           {Elasticity::homogeneous, "homogeneous"},
                                           {Elasticity::graded, "graded"}};
    using Formulation = DiscretizationParameters::Formulation;
    const Choices<Formulation> formulations{{Formulation::displacement, "displacement"},
                                            {Formulation::mixed, "mixed"},
                                            {Formulation::automatic, "automatic"}};
    using Law = AdhesionParameters::Law;
    const Choices<Law> adhesion_laws{{Law::jkr, "JKR"}, {Law::dugdale, "Dugdale"}, {Law::lennard_jones, "Lennard-Jones"}};
    using Study = TangentialParameters::Study;
    const Choices<Study> studies{{Study::none, "none"},
                                 {Study::stiffness, "stiffness"},
                                 {Study::partial_slip, "partial slip"},
                                 {Study::oscillation, "oscillation"}};
    using MapParameter = MapParameters::Parameter;
    const Choices<MapParameter> map_parameters{{MapParameter::none, "none"},
                                               {MapParameter::surface_depth, "surface depth"},
                                               {MapParameter::coating_thickness, "coating thickness"},
                                               {MapParameter::erf_width, "erf width"},
                                               {MapParameter::indenter_modulus, "indenter modulus"},
                                               {MapParameter::friction_coefficient, "friction coefficient"},
                                               {MapParameter::tabor_parameter, "Tabor parameter"},
                                               {MapParameter::coulomb_3d, "Coulomb 3D"},
                                               {MapParameter::largest_stress, "largest stress"}};
    // Two-valued selections read as a flag.
    const Choices<bool> accuracies{{false, "levels"}, {true, "contract"}};
    const Choices<bool> on_off{{true, "on"}, {false, "off"}};
    const Choices<bool> off_on{{false, "off"}, {true, "on"}};
    const Choices<bool> auto_off{{true, "auto"}, {false, "off"}};
    const Choices<bool> far_field_conditions{{true, "auto"}, {false, "clamped"}};
    const Choices<bool> critical_controls{{true, "force"}, {false, "displacement"}};
  } // namespace

  void SceneInfo::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    add(prm, "name", name, "", Patterns::Anything(), "Report folder name; empty: the file name without .prm.");
    add(prm, "description", description, "", Patterns::Anything(), "One line saying what the scene checks.");
    prm.leave_subsection();
  }

  void MaterialParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    add(prm, "E0", E0, "1e9", Patterns::Double(0.), "E0 of E(z) = E0 (z/c0)^k (9.1) [Pa], > 0.");
    add(prm, "c0", c0, "1e-3", Patterns::Double(0.), "Characteristic depth c0 [m], > 0.");
    add(prm, "k", k, "0.5", Patterns::Double(-1., 1.), "Exponent k of the grading, -1 < k < 1.");
    add(prm, "nu", nu, "0.3", Patterns::Double(0., 0.5), "Poisson ratio, 0 <= nu <= 1/2; the FE model needs Discretization/formulation = mixed (or automatic) at nu = 1/2.");
    add_choice(prm, "modulus", modulus, modulus_names, "power law",
               "How the FE model represents E(z): pointwise power law, N layers with exact layer "
               "averages, an expression in z, E0 ((z + z0)/c0)^k (a finite surface modulus), a graded "
               "coating of thickness H on the homogeneous substrate E0 (H/c0)^k, a CSV table, or the "
               "error-function grading E0 [1 + (m - 1) erfc(z/w)] (Lee, Barber & Thouless 2009; needs k = 0). "
               "The closed forms and the numerical MDR always use the power law E0 (z/c0)^k.");
    add(prm, "layers", layers, "16", Patterns::Integer(1, 100000), "Layered modulus: number of layers.");
    add(prm, "layered depth", layered_depth, "10", Patterns::Double(0.), "Layered modulus: depth of the layered zone / a.");
    add(prm, "expression", expression, "E0*(z/c0)^k", Patterns::Anything(),
        "Expression modulus: E(z) (muparser; constants E0, c0, k).");
    add(prm, "surface depth", surface_depth, "0", Patterns::Double(0.), "Shifted power law: z0 [m], > 0.");
    add(prm, "coating thickness", coating_thickness, "0", Patterns::Double(0.), "Coating: its thickness H [m], > 0.");
    add(prm, "surface modulus ratio", surface_modulus_ratio, "10", Patterns::Double(0.),
        "Error function: m = E(0) / E0, > 0 (E0 is the modulus far below the surface; m > 1 a stiff "
        "skin, m < 1 a soft one).");
    add(prm, "erf width", erf_width, "0", Patterns::Double(0.),
        "Error function: the width w [m] of E0 [1 + (m - 1) erfc(z/w)], > 0.");
    add(prm, "table file", table_file, "", Patterns::Anything(),
        "Table: a CSV file of z [m], E [Pa] rows (z from 0, increasing; linear between rows, "
        "constant below the last); a relative path is taken from the scene's folder.");
    prm.leave_subsection();
  }

  std::string to_string(const MaterialParameters::Modulus modulus)
  {
    return std::find_if(modulus_names.begin(), modulus_names.end(), [&](const auto &n) { return n.first == modulus; })
      ->second;
  }

  void MaterialParameters::check() const
  {
    if (modulus == Modulus::shifted_power_law && !(surface_depth > 0.))
      throw std::invalid_argument("Material/surface depth = " + format(surface_depth) +
                                  " must be z0 in (0, inf) [m] with Material/modulus = shifted power law");
    if (modulus == Modulus::coating && !(coating_thickness > 0.))
      throw std::invalid_argument("Material/coating thickness = " + format(coating_thickness) +
                                  " must be H in (0, inf) [m] with Material/modulus = coating");
    // The ratio is also read by an erf-width map, whatever Material/modulus says.
    if (!(surface_modulus_ratio > 0.) || !std::isfinite(surface_modulus_ratio))
      throw std::invalid_argument("Material/surface modulus ratio = " + format(surface_modulus_ratio) +
                                  " must be m = E(0)/E0 in (0, inf)");
    if (modulus == Modulus::error_function && !(erf_width > 0.))
      throw std::invalid_argument("Material/erf width = " + format(erf_width) +
                                  " must be w in (0, inf) [m] with Material/modulus = error function");
    if (modulus == Modulus::error_function && k != 0.)
      throw std::invalid_argument("Material/k = " + format(k) +
                                  " must be 0 with Material/modulus = error function (E0 is the modulus below the "
                                  "skin; the closed forms compare with the homogeneous E0)");
    if (modulus == Modulus::table && table_file.empty())
      throw std::invalid_argument("Material/table file is empty: Material/modulus = table needs a CSV file");
    if (E0 <= 0. || c0 <= 0.)
      throw std::invalid_argument("Material: E0 and c0 must be > 0");
    if (k <= -1. || k >= 1.)
      throw std::invalid_argument("Material/k = " + std::to_string(k) + " is outside (-1, 1)");
  }

  void LoadParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Load");
    add_choice(prm, "type", type, load_types, "flat punch",
               "The load: rigid flat punch (9.16), paraboloid (9.26), cone (9.20), power-law "
               "indenter A r^n (9.30), concave punch in complete contact (9.34), constant pressure (9.40).");
    add_choice(prm, "control", control, load_controls, "contact radius",
               "Curved indenters: what is prescribed.");
    add_choice(prm, "contact", contact, contacts, "disc",
               "Curved indenters and the concave punch: disc = the contact zone is the disc r <= a (found "
               "among discs under depth or force control); unilateral = the contact set is found by the "
               "Signorini conditions (an annulus, a concave punch short of complete contact), the mesh "
               "graded toward the edge found; needs Load/control = depth or force (curved indenters).");
    add(prm, "a", a, "1e-4", Patterns::Double(0.), "Contact radius (punch radius, loaded radius) [m].");
    add(prm, "depth", depth, "1e-6", Patterns::Double(), "Depth d (flat punch, depth control) or centre displacement d0 (concave punch) [m].");
    add(prm, "force", force, "1e-2", Patterns::Double(0.), "Normal force (force control) [N].");
    add(prm, "R", R, "1e-2", Patterns::Double(0.), "Paraboloid radius [m].");
    add(prm, "tan theta", tan_theta, "0.1", Patterns::Double(0.), "Cone slope tan(theta).");
    add(prm, "n", n, "2", Patterns::Double(0.), "Power-law exponent n > 0.");
    add(prm, "A", A, "1", Patterns::Double(0.), "Power-law coefficient A [m^(1-n)].");
    add(prm, "h0", h0, "1e-7", Patterns::Double(0.), "Concave punch depth h0 [m] (9.31).");
    add(prm, "p0", p0, "1e6", Patterns::Double(), "Constant pressure p0 [Pa].");
    prm.leave_subsection();
  }

  void IndenterParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Indenter");
    add_choice(prm, "elasticity", elasticity, elasticities, "rigid",
               "rigid; homogeneous (an elastic body E, nu carrying the profile, e.g. a sphere of radius R >> a "
               "modelled as a half-space); graded (a second body E (z/c0)^k with the Material's k and c0, 9.4). "
               "Elastic indenters need Load/contact = unilateral.");
    add(prm, "E", E, "1e9", Patterns::Double(0.), "homogeneous: the indenter's E; graded: its E0 [Pa], > 0.");
    add(prm, "nu", nu, "0.3", Patterns::Double(0., 0.5), "The indenter's Poisson ratio, [0, 0.5].");
    prm.leave_subsection();
  }

  void IndenterParameters::check() const
  {
    if (elasticity != Elasticity::rigid && !(E > 0.))
      throw std::invalid_argument("Indenter/E: " + format(E) + " must be in (0, inf) for an elastic indenter");
  }

  void FrictionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Friction");
    prm.declare_entry("coefficient", "0", Patterns::Anything(),
                      "The Coulomb friction coefficient mu, the scene's one entry for it. A tangential scene (Tangential/"
                      "study, a tangential candidate, a Coulomb 3D map without Map/values): the mu of 9.80-9.87, in "
                      "(0, inf). Any other scene: friction between the rigid indenter and the surface during normal "
                      "loading, >= 0, or inf (full stick); 0: frictionless (the chapter's assumption); mu > 0 needs "
                      "Load/contact = unilateral and a rigid indenter, and the closed-form rows then measure the "
                      "frictionless idealisation. Formerly also Tangential/friction coefficient (a deprecated name).");
    add(prm, "load steps", load_steps, "24", Patterns::Integer(1, 10000),
        "Normal loading with friction: steps of the loading path from zero (the frictional answer depends on the path; a vertex that "
        "comes into contact during a step carries no shear in it: an error of the step's size).");
    prm.leave_subsection();
  }

  void FrictionParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Friction");
    const std::string c = dealii::Utilities::trim(prm.get("coefficient"));
    prm.leave_subsection();
    if (c == "inf" || c == "full stick")
      coefficient = std::numeric_limits<double>::infinity();
    else
      {
        std::istringstream in(c);
        double mu = std::nan("");
        if (!(in >> mu) || !(in >> std::ws).eof() || !(mu >= 0.) || !std::isfinite(mu))
          throw std::invalid_argument("Friction/coefficient: '" + c + "' must be a number in [0, inf) or inf (full stick)");
        coefficient = mu;
      }
  }

  void DiscretizationParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    add(prm, "degree", degree, "3", Patterns::Integer(1, 8), "FE_Q degree.");
    prm.declare_entry("refinements", "0", Patterns::List(Patterns::Integer(), 1, 12),
                      "Uniform refinements of the recommended mesh, each in 0..10; several values make a convergence "
                      "study. Each level has about 4 times the DoFs of the one before: the run forecasts a level's DoFs "
                      "and memory from a coarser one and refuses, before it starts, a level that would not fit in "
                      "this machine's free memory.");
    add(prm, "force tolerance", force_tolerance, "1e-6", Patterns::Double(1e-12, 1.),
        "The wanted relative force error: selects the recommended mesh (fem/doc/meshes.md).");
    add_choice(prm, "accuracy", contract, accuracies, "levels",
               "levels: one FE solve per entry of refinements (a convergence study against the references); "
               "contract (normal, JKR adhesion and tangential scenes with a rigid indenter on a disc): the "
               "ladder of fem/accuracy/accuracy.h (hp; uniform refinements where E jumps) until the Richardson "
               "estimate of every FE quantity (force, depth, contact radius, p(r) relative to the largest |p|, "
               "w(r); the critical states of adhesion; K_T and the tangential curves) is within force tolerance, "
               "or a refusal naming the limit; every FE row shows the asked tolerance, the estimate and the "
               "verdict.");
    add_choice(prm, "memory guard", memory_guard, on_off, "on",
               "on: a refinement level whose forecast direct factorisation exceeds 80 % of this machine's "
               "available memory is refused before it starts; off (or `gradcontact run --force`): solved "
               "anyway.");
    add(prm, "far field", far_field, "0", Patterns::Double(0.), "L/a of the truncated domain; 0: the recommended one.");
    add_choice(prm, "formulation", formulation, formulations, "displacement",
               "FE unknowns: displacement; mixed (u and q = lambda div u, Taylor-Hood: nu -> 0.5 without "
               "locking, nu = 0.5, the Gibson medium k = 1); automatic (mixed for nu >= 0.45). "
               "fem/doc/model.md, \"Mixed formulation\".");
    add_choice(prm, "surface map", surface_map, auto_off, "auto",
               "auto: a modulus vanishing at the surface like z^k, 0 < k <= 0.95, without jumps is resolved by "
               "the singular depth map of fem/modulus/surface_map.h in the rigid frictionless normal scenes of the "
               "displacement formulation (no thin cells; flat punch k = 0.5 2.3e-6 with a third of the DoFs); "
               "off, and the mixed formulation: z-halvings to 1e-10 a.");
    add_choice(prm, "far field condition", condensed_far_field, far_field_conditions, "auto",
               "auto: for a power-law modulus in the scenes of the axisymmetric and mode-1 solvers (normal, "
               "candidate, JKR, Dugdale, tangential) with the displacement formulation and without the surface "
               "map, the half-space beyond L is condensed onto max(r, z) = L "
               "(fem/elasticity/far_field.h: no truncation error; L / a = far field, else 100 or 1.5 times the largest "
               "displacement radius); clamped: u = 0 at L.");
    prm.leave_subsection();
  }

  void DiscretizationParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    refinements.clear();
    for (const std::string &s : dealii::Utilities::split_string_list(prm.get("refinements")))
      {
        const int level = dealii::Utilities::string_to_int(s);
        if (level < 0 || level > 10)
          throw std::invalid_argument("Discretization/refinements = " + s +
                                      ": the valid range is 0..10 (each refinement multiplies the DoFs by about 4; "
                                      "the run also refuses a level that would not fit in memory)");
        refinements.push_back(static_cast<unsigned int>(level));
      }
    prm.leave_subsection();
  }

  void OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Outputs");
    add(prm, "force", force, "true", Patterns::Bool(), "Compare the normal force.");
    add(prm, "depth", depth, "true", Patterns::Bool(), "Compare the depth (centre displacement for pressure loads).");
    add(prm, "contact radius", contact_radius, "true", Patterns::Bool(), "Compare the contact radius (depth and force control).");
    add(prm, "pressure radii", pressure_radii, "", double_list, "Radii / a at which to compare p(r) (r < a); empty: none.");
    add(prm, "displacement radii", displacement_radii, "", double_list, "Radii / a at which to compare w(r); empty: none.");
    add(prm, "vtu", vtu, "false", Patterns::Bool(), "Write the FE fields as VTU.");
    add(prm, "plots", plots, "true", Patterns::Bool(), "Write gnuplot plots of the sampled profiles.");
    prm.leave_subsection();
  }

  void ReferenceParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("References");
    add(prm, "closed form", closed_form, "true", Patterns::Bool(), "Compare with the chapter's closed form.");
    add(prm, "numerical MDR", numerical_mdr, "false", Patterns::Bool(), "Compare with the numerical MDR engine.");
    add(prm, "fem", fem, "true", Patterns::Bool(),
        "Run the FE model; false compares the closed form with the numerical MDR only.");
    prm.leave_subsection();
  }

  void ToleranceParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Tolerances");
    add(prm, "force", force, "1e-5", Patterns::Double(0.), "Relative tolerance of the force.");
    add(prm, "depth", depth, "1e-4", Patterns::Double(0.), "Relative tolerance of the depth.");
    add(prm, "contact radius", contact_radius, "1e-4", Patterns::Double(0.), "Relative tolerance of the contact radius.");
    add(prm, "pressure", pressure, "1e-3", Patterns::Double(0.), "Tolerance of p(r), relative to the largest |p| sampled.");
    add(prm, "displacement", displacement, "1e-4", Patterns::Double(0.), "Relative tolerance of w(r).");
    prm.leave_subsection();
  }

  void CandidateParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Candidate");
    add(prm, "profile", profile, "", Patterns::Anything(),
        std::string("A profile f(r) (variable r; f(0) = 0) whose candidate closed forms below are checked "
                    "against the numerical MDR. Empty: no candidate check. Every candidate entry is an "
                    "expression: numbers, names, + - * / ^ (power), comparisons, && || !, c ? x : y, "
                    "and the functions ") + Expression::function_names() +
          " (`gradcontact run --help-functions` says what each is).");
    add(prm, "profile slope", slope, "", Patterns::Anything(), "f'(r); empty: finite differences of f.");
    add(prm, "profile curvature", curvature, "", Patterns::Anything(), "f''(r); required for a pressure candidate.");
    add(prm, "constants", constants, "", Patterns::Anything(),
        "Constants of the expressions, \"name = expression, ...\", each of which may use the names before "
        "it and the functions (kappa = n/2 * beta(n/2, (1+k)/2)). Always defined: E0, c0, k, nu, pi, "
        "the coefficients h_N (9.5), h_T (9.79), beta, C, cN0 = c_N0 (9.4), cT0 = c_T0, alpha = "
        "cN0/cT0 (9.78), dgamma (Adhesion/work of adhesion) and mu (Friction/coefficient).");
    add(prm, "depth", depth, "", Patterns::Anything(), "Candidate d(a) (variable a).");
    add(prm, "force", force, "", Patterns::Anything(), "Candidate F_N(a) (variable a).");
    add(prm, "pressure", pressure, "", Patterns::Anything(), "Candidate p(r, a) (variables r, a), at Outputs/pressure radii.");
    add(prm, "displacement", displacement, "", Patterns::Anything(),
        "Candidate w(r, a) (variables r, a), at Outputs/displacement radii.");
    add(prm, "outer radius", outer_radius, "", Patterns::Anything(),
        "Load/contact = unilateral: candidate outer edge of the contact (variables d, F).");
    add(prm, "inner radius", inner_radius, "", Patterns::Anything(),
        "Load/contact = unilateral: candidate inner edge of the contact, 0 for a disc (variables d, F).");
    add(prm, "profile table", profile_table, "", Patterns::Anything(),
        "Load/contact = unilateral: a CSV file of rows r, f(r) [m] (r from 0, ascending; relative to the "
        "scene's folder), linear between rows, e.g. a measured indenter, instead of `profile`; its last r "
        "is the indenter's radius.");
    add(prm, "indenter radius", indenter_radius, "0", Patterns::Double(0.),
        "Load/contact = unilateral: the indenter's radius [m] (a concave punch ends there); 0: unbounded. "
        "With unilateral contact every candidate takes the FE's depth d and force F instead of a "
        "(d, F; r, d, F for p and w), is compared with the FE only (the MDR assumes a disc), and the "
        "profile is indented under Load/control = depth or force.");
    add(prm, "adhesive depth", adhesive_depth, "", Patterns::Anything(),
        "JKR candidate d(a) on the adhesive branch (variable a; Adhesion/work of adhesion is dgamma), "
        "over the radii of `range`.");
    add(prm, "adhesive force", adhesive_force, "", Patterns::Anything(), "JKR candidate F_N(a) (variable a), over `range`.");
    add(prm, "adhesive pressure", adhesive_pressure, "", Patterns::Anything(),
        "JKR candidate p(r, a) (variables r, a) at Load/a and Outputs/pressure radii (needs f'').");
    add_choice(prm, "critical control", critical_force_control, critical_controls, "force",
               "The control of the critical state of the three entries below.");
    add(prm, "critical radius", critical_radius, "", Patterns::Anything(), "JKR candidate critical radius a_c (a constant).");
    add(prm, "critical force", critical_force, "", Patterns::Anything(), "JKR candidate critical force F_c (a constant).");
    add(prm, "critical depth", critical_depth, "", Patterns::Anything(), "JKR candidate critical depth d_c (a constant).");
    add(prm, "tangential stiffness", tangential_stiffness, "", Patterns::Anything(),
        "Candidate K_T(a) (variable a), over `range`; Friction/coefficient is mu.");
    add(prm, "tangential force", tangential_force, "", Patterns::Anything(),
        "Candidate F_x(c, a) of partial slip with stick radius c (variables c, a) at Load/a.");
    add(prm, "tangential displacement", tangential_displacement, "", Patterns::Anything(),
        "Candidate u0(c, a) of partial slip (variables c, a) at Load/a.");
    add(prm, "stick radius", stick_radius, "", Patterns::Anything(),
        "Candidate c(Fx, a) (variables Fx, a), 0 < Fx < mu F_N(a).");
    add(prm, "dissipated energy", dissipated_energy, "", Patterns::Anything(),
        "Candidate energy dissipated per cycle of +-FA (variables FA, a), 0 < FA < mu F_N(a).");
    add(prm, "unloading displacement", unloading_displacement, "", Patterns::Anything(),
        "Candidate u0 on the unloading branch from FA (variables Fx, FA, a); FA = Tangential/amplitude "
        "mu F_N(a).");
    add(prm, "reloading displacement", reloading_displacement, "", Patterns::Anything(),
        "Candidate u0 on the reloading branch from -FA (variables Fx, FA, a).");
    add(prm, "range", range, "0.25, 4", Patterns::List(Patterns::Double(0.), 2, 2),
        "The contact radii of the curves over a (d(a), F(a) of the normal and the adhesive family; K_T(a)): "
        "from range[0] Load/a to range[1] Load/a, and Load/a itself for the normal family (where the FE "
        "solves). A profile that needs a > b (a flat punch of radius b) sets range[0] so.");
    add(prm, "points", points, "9", Patterns::Integer(2, 200), "Points on every candidate curve.");
    add(prm, "tolerance", tolerance, "1e-8", Patterns::Double(0.),
        "Relative tolerance of the candidate against the numerical MDR (every row whose reference is "
        "the numerical MDR).");
    add_choice(prm, "Coulomb 3D", coulomb_3d, off_on, "off",
               "Tangential candidates: on also runs the 3D Coulomb model of fem/tangential/coulomb_contact_3d.h with the "
               "candidate's profile (normal loading to the numerical MDR's d(a), then the tangential "
               "displacement of Tangential/amplitude mu F_N(a) and one cycle, Tangential/load steps each way); "
               "its rows (F_x against u0, the stick radius, the branches, the loop area) say how far Coulomb's "
               "law (the normal-tangential coupling, a free slip direction) is from the candidate, against the "
               "Tolerances section or FE tolerance.");
    prm.declare_entry("FE tolerance", "", Patterns::Anything(),
                      "Relative tolerance of the candidate against the FE (every row whose reference is an FE model); "
                      "empty: the Tolerances section's entry of the row's quantity (force, depth, contact radius, "
                      "pressure, displacement). The FE is less accurate than the numerical MDR, so the two differ.");
    prm.leave_subsection();
  }

  bool CandidateParameters::has_adhesive_entries() const
  {
    return !(adhesive_depth.empty() && adhesive_force.empty() && adhesive_pressure.empty() && critical_radius.empty() &&
             critical_force.empty() && critical_depth.empty());
  }

  bool CandidateParameters::has_tangential_entries() const
  {
    return !(tangential_stiffness.empty() && tangential_force.empty() && tangential_displacement.empty() &&
             stick_radius.empty() && dissipated_energy.empty() && unloading_displacement.empty() &&
             reloading_displacement.empty());
  }

  CandidateParameters::Family CandidateParameters::family() const
  {
    const bool adhesive = has_adhesive_entries(), tangential = has_tangential_entries();
    if (adhesive && tangential)
      throw std::invalid_argument("Candidate: adhesive and tangential candidate entries in one scene; the two are "
                                  "different contacts (tangential contact is non-adhesive): give one family per scene");
    return adhesive ? Family::adhesive : tangential ? Family::tangential : Family::normal;
  }

  void CandidateParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Candidate");
    const std::string fe = dealii::Utilities::trim(prm.get("FE tolerance"));
    fe_tolerance = 0.;
    if (!fe.empty())
      {
        std::size_t used = 0;
        try
          {
            fe_tolerance = std::stod(fe, &used);
          }
        catch (const std::exception &)
          {
            used = 0;
          }
        if (used != fe.size() || !(fe_tolerance > 0.) || !std::isfinite(fe_tolerance))
          throw std::invalid_argument("Candidate/FE tolerance = '" + fe +
                                      "': must be empty (the Tolerances section) or a number in (0, inf)");
      }
    prm.leave_subsection();
  }

  bool AdhesionParameters::enabled(const LoadParameters &load) const
  {
    return work_of_adhesion > 0. || (load.type == LoadParameters::Type::constant_pressure && tensile_strength > 0.);
  }

  void AdhesionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Adhesion");
    add(prm, "work of adhesion", work_of_adhesion, "0", Patterns::Double(0.),
        "dgamma [J/m^2]; > 0 makes the scene adhesive (JKR, 9.45-9.68): critical states from the FE "
        "model (fem/adhesion/adhesion.h) against the closed forms and the numerical MDR.");
    prm.declare_entry("control", "both", Patterns::Selection("force|displacement|both"),
                      "Critical states under force control, displacement control or both (curved profiles).");
    prm.add_action("control", [this](const std::string &control) {
      force_control        = control != "displacement";
      displacement_control = control != "force";
    });
    add(prm, "tensile strength", tensile_strength, "0", Patterns::Double(0.),
        "sigma_th [Pa]: the centre mechanism of the concave punch (9.67-9.68); with Load/type = "
        "constant pressure the optimal profile p = -sigma_th on r <= a (9.69-9.74).");
    add(prm, "initial radius", initial_radius, "0", Patterns::Double(0.),
        "Start of the critical-radius search [m]; 0: Load/a.");
    add(prm, "stencil ratio", stencil_ratio, "1.05", Patterns::Double(1.000001, 2.),
        "Ratio of neighbouring FE contact radii in the derivative of the stiffness (G(a)).");
    add(prm, "local stencil", local_stencil, "true", Patterns::Bool(),
        "Finish every critical search with FE radii a_c q^(+-1) (exact fit for any E(z)); the "
        "fit is exact for the power law without them.");
    add(prm, "curve points", curve_points, "", Patterns::List(Patterns::Double(0.), 0, 50),
        "a / a_c (force control) of FE points on the adhesive force-depth curve (9.57, figures 9.22-9.23); empty: "
        "none.");
    add_choice(prm, "law", law, adhesion_laws, "JKR",
               "JKR: the chapter's adhesion (infinitely short range; the FE from its energy release rate). "
               "Dugdale: a cohesive zone of finite range (tension sigma_0 where the gap is below dgamma / "
               "sigma_0, fem/adhesion/cohesive_zone.h): the FE drops JKR's assumption and the closed-form rows say "
               "\"(JKR idealisation)\" (paraboloid or power law). Lennard-Jones: the smooth law of "
               "fem/adhesion/smooth_cohesion.h (repulsion included, its largest attraction the Dugdale sigma_0 of the "
               "Tabor parameter), in Tabor-parameter maps (Map/parameter = Tabor parameter; without it the "
               "map is Dugdale's) and for adhesive candidates (with the cohesive strength).");
    add(prm, "Tabor parameter", tabor_parameter, "0", Patterns::Double(0.),
        "Dugdale: lambda (cases/runners/fe_cohesive.h; Maugis' at k = 0), which sets sigma_0; or give the "
        "cohesive strength.");
    add(prm, "cohesive strength", cohesive_strength, "0", Patterns::Double(0.), "Dugdale: sigma_0 [Pa]; or give the Tabor parameter.");
    prm.leave_subsection();
  }

  void TangentialParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Tangential");
    add_choice(prm, "study", study, studies, "none",
               "Tangential contact by the Fourier mode-1 FE model (fem/tangential/fourier_mode1_solver.h): none; "
               "stiffness (Load/type = flat punch: K_T of 9.78-9.79, alpha = K_N / K_T, Mindlin at k = 0); "
               "partial slip (Load/type = paraboloid: the traction mu [p(r; a) - p(r; c)] of 9.80, F_x and the "
               "stick-zone displacement, the F_x(u0) curve); oscillation (paraboloid: +-F_A after loading, "
               "9.81-9.87: unloading branch, hysteresis loop, dissipated energy, points A to E).");
    add(prm, "stick radius", stick_radius, "0.5", Patterns::Double(0., 1.),
        "Partial slip: stick radius c / a, in (0, 1] (c = a: no slip yet, tau = 0: no FE row at that point).");
    add(prm, "amplitude", amplitude, "0.9", Patterns::Double(0., 1.),
        "Oscillation: F_A / (mu F_N), in (0, 1); 1 and above is gross slip.");
    add(prm, "load steps", load_steps, "5", Patterns::Integer(2, 50),
        "FE points on the F_x(u0) curve (partial slip: c/a = i / steps, i = 1..steps - 1, and "
        "Tangential/stick radius) or on the unloading branch F/F_A = 1 .. -1 (oscillation), 2..50.");
    add(prm, "Holl ratio", holl_ratio, "false", Patterns::Bool(),
        "Use the decoupled pairing nu = 1 / (2 + k) of 9.3.1 instead of Material/nu; needs k in (0, 1).");
    add(prm, "stick levels", stick_levels, "8", Patterns::Integer(0, 30),
        "Surface refinement levels toward the stick radii (the kink of tau at c; fem/doc/loads-and-contact.md).");
    add(prm, "assumption tolerance", assumption_tolerance, "1e-4", Patterns::Double(0.),
        "Tolerance of the measured assumption error of 9.80 (relative spread of u_x over the stick "
        "zone, max |u_y| / mean u_x), both compared with 0.");
    prm.leave_subsection();
  }

  void TangentialParameters::check() const
  {
    // The patterns admit the closed ends; the open ones are checked here (9.80: 0 < c <= a; F_A < mu F_N).
    if (!(stick_radius > 0. && stick_radius <= 1.))
      throw std::invalid_argument("Tangential/stick radius = " + format(stick_radius) + " must be c/a in (0, 1]");
    if (!(amplitude > 0. && amplitude < 1.))
      throw std::invalid_argument("Tangential/amplitude = " + format(amplitude) +
                                  " must be F_A/(mu F_N) in (0, 1); at 1 and above the sphere slides (gross slip)");
  }

  void MapParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Map");
    add_choice(prm, "parameter", parameter, map_parameters, "none",
               "The map's variable, whose values Map/values gives: none (no map), surface depth (values a/z0; "
               "Material/modulus = shifted power law, z0 = a / value), coating thickness (values a/H; "
               "Material/modulus = coating, H = a / value), erf width (values a/w; Material/modulus = error "
               "function with Material/surface modulus ratio, w = a / value; k = 0) or indenter modulus (values "
               "E1/E0; a homogeneous elastic indenter E1 = value E0 with Indenter/nu, against the rigid "
               "indenter's closed forms), or friction coefficient (values mu; Coulomb friction between a rigid "
               "indenter and the surface during loading, Friction/load steps, against the frictionless indenter, "
               "for every k and nu of the map), or Tabor parameter (values lambda; a Dugdale cohesive zone, "
               "cases/runners/fe_cohesive.h, against the chapter's JKR pull-off; needs Adhesion/work of adhesion "
               "and a paraboloid or power law), or Coulomb 3D (values mu, empty: Friction/coefficient; the 3D "
               "model of a rigid sphere with Coulomb friction, cases/runners/fe_coulomb_3d.h: normal loading, "
               "Tangential/amplitude and one cycle, for every k and nu of the map, against 9.80-9.86), or largest "
               "stress (no values; the largest shear and von Mises stress below a paraboloid, with their depths, "
               "for every k >= 0 and nu of the map, FE against the closed form, cases/runners/stress_map.h).");
    add(prm, "values", values, "", Patterns::List(Patterns::Double(0.), 0, 100),
        "The values of the variable Map/parameter names, > 0: a/z0, a/H, a/w, E1/E0, the friction "
        "coefficients mu or the Tabor parameters lambda. Formerly Map/ratios (a deprecated name).");
    add(prm, "k values", exponents, "", Patterns::List(Patterns::Double(-1., 1.), 0, 20),
        "The exponents k of the map, -1 < k < 1; empty: Material/k.");
    add(prm, "nu values", poisson_ratios, "", Patterns::List(Patterns::Double(0., 0.5), 0, 20),
        "Friction coefficient and Coulomb 3D maps: the Poisson ratios, [0, 0.5] (0.5 with the mixed "
        "formulation, which the Coulomb 3D map takes there by itself); empty: Material/nu.");
    add(prm, "Holl ratio", holl_ratio, "true", Patterns::Bool(),
        "Friction coefficient map: also nu = 1/(2 + k) where it is <= 1/2 (the decoupled pairing: pressure "
        "causes no radial displacement, so friction must change nothing; the map's sharp check).");
    add(prm, "full stick", full_stick, "true", Patterns::Bool(), "Friction coefficient map: also mu = inf (full stick).");
    add(prm, "thresholds", thresholds, "0.01, 0.001", Patterns::List(Patterns::Double(0.), 1, 10),
        "Deviations from the power law whose ratio the map reports (\"within 1 % when a/z0 >= ...\").");
    prm.leave_subsection();
  }

  void MapParameters::check() const
  {
    for (const double v : values)
      if (!(v > 0.))
        throw std::invalid_argument("Map/values: " + format(v) + " must be in (0, inf)");
    for (const double k : exponents)
      if (!(k > -1. && k < 1.))
        throw std::invalid_argument("Map/k values: " + format(k) + " must be in (-1, 1)");
    for (const double t : thresholds)
      if (!(t > 0.))
        throw std::invalid_argument("Map/thresholds: " + format(t) + " must be in (0, inf)");
  }

  std::string to_string(const SceneKind kind)
  {
    switch (kind)
      {
        case SceneKind::normal:
          return "normal";
        case SceneKind::analytic:
          return "analytic";
        case SceneKind::candidate:
          return "candidate";
        case SceneKind::adhesion:
          return "adhesion";
        case SceneKind::tangential:
          return "tangential";
        case SceneKind::map:
          return "map";
      }
    return "unknown";
  }

  namespace
  {
    /// The mu of tangential contact (9.80-9.87): slip at |tau| = mu p, a finite positive coefficient.
    void check_tangential_mu(const Scene &s, const std::string &where)
    {
      const double mu = s.friction.coefficient;
      if (!(mu > 0.) || !std::isfinite(mu))
        throw std::invalid_argument(where + "Friction/coefficient = " + format(mu) +
                                    " must be in (0, inf) in a tangential scene (the mu of 9.80-9.87; formerly "
                                    "Tangential/friction coefficient, whose default was 0.3)");
    }

    /// The tangential studies need their load (9.78-9.87), a friction coefficient and, for the Holl pairing, k > 0.
    void check_tangential(const Scene &s, const std::string &where)
    {
      using Study = TangentialParameters::Study;
      using Type = LoadParameters::Type;
      const TangentialParameters &t = s.tangential;
      const double k = s.material.k;
      if (t.holl_ratio && !(k > 0.))
        throw std::invalid_argument(where + "Tangential/Holl ratio = true with Material/k = " + format(k) +
                                    ": the Holl ratio nu = 1/(2+k) needs k in (0, 1) (nu <= 1/2)");
      if (t.study == Study::stiffness && s.load.type != Type::flat_punch)
        throw std::invalid_argument(where + "Tangential/study = stiffness needs Load/type = flat punch");
      if ((t.study == Study::partial_slip || t.study == Study::oscillation) && s.load.type != Type::paraboloid)
        throw std::invalid_argument(where + "Tangential/study = " +
                                    (t.study == Study::partial_slip ? "partial slip" : "oscillation") +
                                    " needs Load/type = paraboloid (a sphere, 9.80-9.87)");
      if (s.load.type == Type::paraboloid && s.load.control != LoadParameters::Control::contact_radius)
        throw std::invalid_argument(where + "a tangential study takes the contact radius Load/a: Load/control must "
                                            "be contact radius");
      if (!(s.load.a > 0.))
        throw std::invalid_argument(where + "Load/a = " + format(s.load.a) + " must be in (0, inf)");
      check_tangential_mu(s, where);
    }

    /// JKR needs a work of adhesion; the optimal profile (a prescribed tension) a tensile strength and none.
    void check_adhesion(const Scene &s, const std::string &where)
    {
      const AdhesionParameters &ad = s.adhesion;
      const bool optimal = s.load.type == LoadParameters::Type::constant_pressure;
      if (optimal && ad.work_of_adhesion > 0.)
        throw std::invalid_argument(where + "Adhesion/work of adhesion = " + format(ad.work_of_adhesion) +
                                    " with Load/type = constant pressure: a prescribed pressure has no JKR state; the "
                                    "optimal profile (9.69-9.74) takes Adhesion/tensile strength > 0 and no work of adhesion");
      if (!optimal && !(ad.work_of_adhesion > 0.))
        throw std::invalid_argument(where + "Adhesion/work of adhesion = " + format(ad.work_of_adhesion) +
                                    " must be in (0, inf) for an adhesive scene");
      if (optimal && !(ad.tensile_strength > 0.))
        throw std::invalid_argument(where + "Adhesion/tensile strength = " + format(ad.tensile_strength) +
                                    " must be in (0, inf) for the optimal profile");
      if (ad.law != AdhesionParameters::Law::dugdale && (ad.tabor_parameter > 0. || ad.cohesive_strength > 0.))
        throw std::invalid_argument(where + "Adhesion/Tabor parameter or cohesive strength is set with Adhesion/law = "
                                    "JKR: they belong to law = Dugdale");
      if (ad.law == AdhesionParameters::Law::dugdale)
        {
          using Type = LoadParameters::Type;
          if (s.load.type != Type::paraboloid && s.load.type != Type::power_law)
            throw std::invalid_argument(where + "Adhesion/law = Dugdale needs Load/type = paraboloid or power law (a "
                                        "profile that opens monotonically)");
          if ((ad.tabor_parameter > 0.) == (ad.cohesive_strength > 0.))
            throw std::invalid_argument(where + "Adhesion/law = Dugdale with Tabor parameter = " +
                                        format(ad.tabor_parameter) + " and cohesive strength = " +
                                        format(ad.cohesive_strength) + ": give exactly one of them, > 0");
          if (ad.tabor_parameter > 0. && s.material.modulus != MaterialParameters::Modulus::power_law)
            throw std::invalid_argument(where + "Adhesion/Tabor parameter needs Material/modulus = power law (it is "
                                        "defined by the chapter's JKR state); give Adhesion/cohesive strength instead");
        }
    }

    /// An adhesive or tangential candidate: the profile as an expression on a disc, its family's physics, a range.
    void check_family_candidate(const Scene &s, const std::string &where)
    {
      const CandidateParameters &c = s.candidate;
      const bool adhesive = c.family() == CandidateParameters::Family::adhesive;
      const std::string family = adhesive ? "an adhesive" : "a tangential";
      if (c.profile.empty())
        throw std::invalid_argument(where + family + " candidate needs Candidate/profile (an expression f(r))");
      if (!c.depth.empty() || !c.force.empty() || !c.pressure.empty() || !c.displacement.empty() ||
          !c.outer_radius.empty() || !c.inner_radius.empty())
        throw std::invalid_argument(where + family + " candidate: Candidate/depth, force, pressure, displacement, "
                                    "outer and inner radius are the non-adhesive normal family's; check them in a "
                                    "scene of their own");
      if (s.load.contact == LoadParameters::Contact::unilateral)
        throw std::invalid_argument(where + family + " candidate needs Load/contact = disc");
      // A grading the chapter does not cover is checked against the FE only: the adhesive family entirely, the
      // tangential one by its stiffness (the partial-slip FE is loaded with the MDR's traction of a power law).
      if (s.material.modulus != MaterialParameters::Modulus::power_law)
        {
          if (!s.references.fem)
            throw std::invalid_argument(where + family + " candidate with Material/modulus other than power law is "
                                        "checked against the FE only (the numerical MDR needs the power law): "
                                        "References/fem must be true");
          if (!adhesive && !(c.tangential_force.empty() && c.tangential_displacement.empty() &&
                             c.stick_radius.empty() && c.dissipated_energy.empty() &&
                             c.unloading_displacement.empty() && c.reloading_displacement.empty()))
            throw std::invalid_argument(where + "a tangential candidate with Material/modulus other than power law: "
                                        "only Candidate/tangential stiffness can be checked (against the FE; partial "
                                        "slip needs the MDR's traction of the power law)");
          if (adhesive && !c.adhesive_pressure.empty())
            throw std::invalid_argument(where + "an adhesive candidate with Material/modulus other than power law: "
                                        "Candidate/adhesive pressure is checked against the numerical MDR only, "
                                        "which needs the power law");
        }
      if (!(s.load.a > 0.))
        throw std::invalid_argument(where + "Load/a = " + format(s.load.a) + " must be in (0, inf) for " + family +
                                    " candidate");
      if (!(c.range[0] > 0. && c.range[1] > c.range[0]))
        throw std::invalid_argument(where + "Candidate/range = " + format(c.range[0]) + ", " + format(c.range[1]) +
                                    ": needs 0 < range[0] < range[1]");
      if (s.tangential.enabled())
        throw std::invalid_argument(where + family + " candidate: leave Tangential/study = none (the candidate's "
                                    "path is its own)");
      if (adhesive)
        {
          if (!(s.adhesion.work_of_adhesion > 0.))
            throw std::invalid_argument(where + "an adhesive candidate needs Adhesion/work of adhesion > 0 (it is " +
                                        format(s.adhesion.work_of_adhesion) + ")");
          if (s.adhesion.law != AdhesionParameters::Law::jkr &&
              !(s.adhesion.cohesive_strength > 0. && s.adhesion.tabor_parameter == 0. && s.references.fem))
            throw std::invalid_argument(
              where + "an adhesive candidate with Adhesion/law = " +
              (s.adhesion.law == AdhesionParameters::Law::dugdale ? "Dugdale" : "Lennard-Jones") +
              " needs Adhesion/cohesive strength > 0 (not the Tabor parameter, which is defined for the chapter's "
              "profiles) and References/fem = true: its rows are the " +
              (s.adhesion.law == AdhesionParameters::Law::dugdale ? "cohesive-zone" : "Lennard-Jones") + " FE's");
          if (!c.adhesive_pressure.empty() && c.curvature.empty())
            throw std::invalid_argument("Candidate/profile curvature: needed for an adhesive pressure candidate "
                                        "(give f''(r))");
          return;
        }
      if (s.adhesion.enabled(s.load))
        throw std::invalid_argument(where + "a tangential candidate is non-adhesive (9.75-9.87): Adhesion/work of "
                                    "adhesion = 0");
      check_tangential_mu(s, where);
    }

    /// A candidate checks at least one formula at one point; a pressure needs f'' (see the message).
    void check_candidate(const Scene &s)
    {
      const CandidateParameters &c = s.candidate;
      if (!c.profile.empty() && !c.profile_table.empty())
        throw std::invalid_argument("scene " + s.file + ": Candidate/profile and Candidate/profile table are both set; "
                                    "give one");
      if (!c.profile_table.empty() && s.load.contact != LoadParameters::Contact::unilateral)
        throw std::invalid_argument("scene " + s.file + ": Candidate/profile table needs Load/contact = unilateral (a "
                                    "table has no derivatives for the MDR; it is checked against the FE only)");
      if (s.load.contact == LoadParameters::Contact::unilateral)
        {
          if (!s.references.fem)
            throw std::invalid_argument("scene " + s.file + ": Candidate with Load/contact = unilateral is checked "
                                        "against the FE only: References/fem must be true");
          const bool checks_something = !c.depth.empty() || !c.force.empty() || !c.outer_radius.empty() ||
                                        !c.inner_radius.empty() ||
                                        (!c.pressure.empty() && !s.outputs.pressure_radii.empty()) ||
                                        (!c.displacement.empty() && !s.outputs.displacement_radii.empty());
          if (!checks_something)
            throw std::invalid_argument("Candidate: no candidate formula given (depth, force, outer radius, inner "
                                        "radius, pressure or displacement)");
          return;
        }
      if (!c.outer_radius.empty() || !c.inner_radius.empty() || c.indenter_radius > 0.)
        throw std::invalid_argument("scene " + s.file + ": Candidate/outer radius, inner radius and indenter radius "
                                    "need Load/contact = unilateral (with a disc the contact radius is Load/a)");
      if (c.curvature.empty() && !c.pressure.empty())
        // The pressure needs g'(x), a quadrature of f' and f'' nested in another one: finite-difference
        // noise keeps both from meeting their tolerance, and the nested quadratures make the run slow.
        throw std::invalid_argument("Candidate/profile curvature: needed for a pressure candidate (give f''(r))");
      const bool checks_something = !c.depth.empty() || !c.force.empty() ||
                                    (!c.pressure.empty() && !s.outputs.pressure_radii.empty()) ||
                                    (!c.displacement.empty() && !s.outputs.displacement_radii.empty());
      if (!checks_something)
        throw std::invalid_argument("Candidate: no candidate formula given (depth, force, pressure or displacement)");
    }

    /// Discretization/accuracy = contract is the ladder of fem/accuracy/accuracy.h: the axisymmetric model of a rigid
    /// indenter on a disc, in a normal FE scene, a JKR adhesion scene (its states from the energy release rate) or a
    /// tangential (mode-1) scene.
    void check_contract(const Scene &s, const std::string &where)
    {
      if (!s.discretization.contract)
        return;
      std::string other;
      if (s.map.enabled())
        other = "a Map";
      else if (s.adhesion.enabled(s.load) && s.adhesion.law != AdhesionParameters::Law::jkr)
        other = "Adhesion/law = " + std::string(s.adhesion.law == AdhesionParameters::Law::dugdale ? "Dugdale" :
                                                                                                    "Lennard-Jones");
      else if (s.candidate.enabled())
        other = "a Candidate";
      else if (s.load.contact == LoadParameters::Contact::unilateral)
        other = "Load/contact = unilateral";
      else if (s.indenter.elasticity != IndenterParameters::Elasticity::rigid)
        other = "an elastic Indenter";
      else if (!s.references.fem)
        other = "References/fem = false";
      if (!other.empty())
        throw std::invalid_argument(where + "Discretization/accuracy = contract with " + other +
                                    ": the contract's ladder (fem/accuracy/accuracy.h) answers the normal, JKR adhesion and "
                                    "tangential FE scenes of a rigid indenter on a disc; use accuracy = levels");
    }

    /// The checks every scene passes, whatever its kind: the Lennard-Jones law's maps, nu = 1/2, unilateral contact,
    /// friction, elastic indenters, and Map/nu values without a map.
    void check_common(const Scene &s, const std::string &where)
    {
      if (s.adhesion.law == AdhesionParameters::Law::lennard_jones &&
          s.map.parameter != MapParameters::Parameter::tabor_parameter &&
          s.candidate.family() != CandidateParameters::Family::adhesive)
        throw std::invalid_argument(where + "Adhesion/law = Lennard-Jones runs in Tabor-parameter maps and adhesive "
                                    "candidates only (Map/parameter "
                                    "= Tabor parameter, which gives its lambdas)");
      // The edge's cells of the Lennard-Jones path shrink like lambda^-2 (lennard_jones_edge_refinement).
      if (s.adhesion.law == AdhesionParameters::Law::lennard_jones)
        for (const double lambda : s.map.values)
          if (!(lambda <= largest_lennard_jones_lambda))
            throw std::invalid_argument(where + "Map/values: lambda = " + std::to_string(lambda) +
                                        " with Adhesion/law = Lennard-Jones; the valid range is (0, " +
                                        format(largest_lennard_jones_lambda) +
                                        "] (the adhesive zone narrows like lambda^-2, and the edge refinement and the "
                                        "cost of the path grow with it)");
      if (s.references.fem && s.material.nu >= 0.5 &&
          s.discretization.formulation == DiscretizationParameters::Formulation::displacement)
        throw std::invalid_argument(where + "Material/nu = 0.5 with Discretization/formulation = displacement: the "
                                    "displacement formulation needs nu in [0, 0.5) (it locks); incompressible "
                                    "nu = 0.5 needs formulation = mixed or automatic");
      if (s.load.contact == LoadParameters::Contact::unilateral)
        {
          using Type = LoadParameters::Type;
          const bool candidate = s.candidate.enabled();
          if (!candidate && (s.load.type == Type::flat_punch || s.load.type == Type::constant_pressure))
            throw std::invalid_argument(where + "Load/contact = unilateral needs an indenter (Load/type = paraboloid, "
                                        "cone, power law or concave punch, or a Candidate/profile)");
          if ((candidate || s.load.type != Type::concave_punch) &&
              s.load.control == LoadParameters::Control::contact_radius)
            throw std::invalid_argument(where + "Load/contact = unilateral finds the contact radius: Load/control "
                                        "must be depth or force");
          if (s.tangential.enabled() || s.adhesion.enabled(s.load))
            throw std::invalid_argument(where + "Load/contact = unilateral is a normal-contact scene (no Adhesion or "
                                        "Tangential entries)");
        }
      if (frictional_loading(s))
        {
          if (s.load.contact != LoadParameters::Contact::unilateral)
            throw std::invalid_argument(where + "Friction/coefficient = " + format(s.friction.coefficient) +
                                        " needs Load/contact = unilateral (the stick and slip zones are found with the "
                                        "contact set)");
          if (s.indenter.elasticity != IndenterParameters::Elasticity::rigid)
            throw std::invalid_argument(where + "Friction/coefficient = " + format(s.friction.coefficient) +
                                        " is modelled for a rigid indenter: Indenter/elasticity must be rigid");
          if (s.candidate.enabled() || s.map.enabled())
            throw std::invalid_argument(where + "Friction/coefficient = " + format(s.friction.coefficient) +
                                        " with a Candidate or Map: a friction map sets mu from Map/values (Map/parameter "
                                        "= friction coefficient); a normal candidate is checked frictionless");
        }
      if (s.indenter.elasticity != IndenterParameters::Elasticity::rigid)
        {
          if (s.load.contact != LoadParameters::Contact::unilateral)
            throw std::invalid_argument(where + "Indenter/elasticity = " +
                                        (s.indenter.elasticity == IndenterParameters::Elasticity::graded ? "graded"
                                                                                                        : "homogeneous") +
                                        " needs Load/contact = unilateral (the two-body model finds the contact set)");
          if (s.indenter.elasticity == IndenterParameters::Elasticity::graded &&
              s.material.modulus != MaterialParameters::Modulus::power_law)
            throw std::invalid_argument(where + "Indenter/elasticity = graded takes the Material's k and c0 of the power "
                                        "law (9.4): Material/modulus must be power law");
          if (s.map.enabled())
            throw std::invalid_argument(where + "Map/parameter is set: the map chooses the indenter; Indenter/elasticity "
                                        "must be rigid");
        }
      if (!s.map.enabled() && !s.map.poisson_ratios.empty())
        throw std::invalid_argument(where + "Map/nu values is set without a map (Map/parameter = none): it belongs to a "
                                    "friction coefficient map");
    }

    /// Map/parameter = Coulomb 3D.
    void check_coulomb_map(const Scene &s, const std::string &where)
    {
    if (s.tangential.study != TangentialParameters::Study::oscillation)
      throw std::invalid_argument(where + "Map/parameter = Coulomb 3D needs Tangential/study = oscillation (its "
                                  "friction coefficient, amplitude and load steps set the path)");
    if (s.adhesion.enabled(s.load) || s.candidate.enabled() || s.load.contact == LoadParameters::Contact::unilateral)
      throw std::invalid_argument(where + "Map/parameter = Coulomb 3D: no Adhesion or Candidate entries and "
                                  "Load/contact = disc (the 3D model finds the contact and stick zones itself)");
    if (s.map.values.empty())
      check_tangential_mu(s, where);
    if (s.load.type != LoadParameters::Type::paraboloid)
      throw std::invalid_argument(where + "Map/parameter = Coulomb 3D needs Load/type = paraboloid (the sphere of "
                                  "9.80-9.86)");
    if (s.material.modulus != MaterialParameters::Modulus::power_law)
      throw std::invalid_argument(where + "Map/parameter = Coulomb 3D needs Material/modulus = power law");
    if (!s.references.fem)
      throw std::invalid_argument(where + "Map/parameter is set with References/fem = false: a map is FE data");

    if (s.tangential.holl_ratio)
      throw std::invalid_argument(where + "Map/parameter = Coulomb 3D: use Map/Holl ratio, not Tangential/Holl "
                                  "ratio (the map runs every nu of Map/nu values)");
    if (!(s.load.a > 0.) || !(s.load.R > s.load.a))
      throw std::invalid_argument(where + "Map/parameter = Coulomb 3D needs 0 < Load/a < Load/R (Load/a = " +
                                  format(s.load.a) + ", Load/R = " + format(s.load.R) + ")");
    }

    /// Map/parameter = Tabor parameter.
    void check_tabor_map(const Scene &s, const std::string &where)
    {
    using Type = LoadParameters::Type;
    if (s.adhesion.law == AdhesionParameters::Law::lennard_jones && !s.discretization.refinements.empty() &&
        s.discretization.refinements.back() > 4)
      throw std::invalid_argument(where + "Discretization/refinements = " +
                                  std::to_string(s.discretization.refinements.back()) +
                                  " with Adhesion/law = Lennard-Jones: at most 4 (its mesh is refined 2^level times, "
                                  "fem/adhesion/smooth_cohesion.h)");
    if (s.tangential.enabled() || s.candidate.enabled() || s.load.contact == LoadParameters::Contact::unilateral)
      throw std::invalid_argument(where + "Map/parameter = Tabor parameter: an adhesive scene (no Tangential or "
                                  "Candidate entries, Load/contact = disc)");
    if (s.adhesion.tabor_parameter > 0. || s.adhesion.cohesive_strength > 0.)
      throw std::invalid_argument(where + "Map/parameter = Tabor parameter: Adhesion/Tabor parameter and cohesive "
                                  "strength are not set (Map/values gives the lambdas)");
    if (!(s.adhesion.work_of_adhesion > 0.))
      throw std::invalid_argument(where + "Map/parameter = Tabor parameter with Adhesion/work of adhesion = " +
                                  format(s.adhesion.work_of_adhesion) + ": it must be in (0, inf)");
    if (s.load.type != Type::paraboloid && s.load.type != Type::power_law)
      throw std::invalid_argument(where + "Map/parameter = Tabor parameter needs Load/type = paraboloid or power law "
                                  "(a profile that opens monotonically, with the chapter's JKR pull-off)");
    if (s.material.modulus != MaterialParameters::Modulus::power_law)
      throw std::invalid_argument(where + "Map/parameter = Tabor parameter needs Material/modulus = power law (the "
                                  "map isolates the range of adhesion)");
    if (!s.references.fem)
      throw std::invalid_argument(where + "Map/parameter is set with References/fem = false: a map is FE data");
    if (s.map.values.empty())
      throw std::invalid_argument(where + "Map/values is empty: give the Tabor parameters lambda of the map");
    if (!s.map.poisson_ratios.empty())
      throw std::invalid_argument(where + "Map/nu values is set for Map/parameter = Tabor parameter: the map runs at "
                                  "Material/nu");
    }


    /// A map whose FE finds the contact set needs a curved indenter, and one that isolates `isolates` needs the
    /// power law.
    void require_curved_power_law(const Scene &s, const std::string &where, const std::string &parameter,
                                  const std::string &why_curved, const std::string &isolates)
    {
      if (s.load.type == LoadParameters::Type::flat_punch)
        throw std::invalid_argument(where + "Map/parameter = " + parameter + " with Load/type = flat punch: " +
                                    why_curved + ", which needs a curved indenter (paraboloid, cone or power law)");
      if (s.material.modulus != MaterialParameters::Modulus::power_law)
        throw std::invalid_argument(where + "Map/parameter = " + parameter +
                                    " needs Material/modulus = power law (the map isolates " + isolates + ")");
    }

    /// The maps of normal contact (every other Map/parameter).
    void check_normal_map(const Scene &s, const std::string &where)
    {
    using Type = LoadParameters::Type;
    if (s.tangential.enabled() || s.adhesion.enabled(s.load) || s.candidate.enabled() ||
        s.load.contact == LoadParameters::Contact::unilateral)
      throw std::invalid_argument(where + "Map/parameter is set: a map is a normal-contact scene (no Adhesion, "
                                  "Tangential or Candidate entries, Load/contact = disc)");
    if (s.load.type == Type::constant_pressure || s.load.type == Type::concave_punch)
      throw std::invalid_argument(where + "Map/parameter is set with Load/type = " +
                                  (s.load.type == Type::constant_pressure ? "constant pressure" : "concave punch") +
                                  ": a map needs a flat punch, paraboloid, cone or power law");
    if (s.load.control != LoadParameters::Control::contact_radius)
      throw std::invalid_argument(where + "Map/parameter is set: Load/control must be contact radius (the map "
                                  "runs at Load/a and compares at the FE depth)");
    if (!s.references.fem)
      throw std::invalid_argument(where + "Map/parameter is set with References/fem = false: a map is FE data");
    if (s.map.values.empty())
      throw std::invalid_argument(where + "Map/values is empty: give the values of the map's variable (a/z0, a/H, a/w, "
                                  "E1/E0 or mu, after Map/parameter)");
    if (s.map.parameter == MapParameters::Parameter::indenter_modulus)
      require_curved_power_law(s, where, "indenter modulus", "the elastic indenter's contact set is found",
                               "the indenter's elasticity");
    if (s.map.parameter == MapParameters::Parameter::friction_coefficient &&
        (s.friction.load_steps < 2 || s.friction.load_steps % 2 != 0))
      throw std::invalid_argument(where + "Map/parameter = friction coefficient with Friction/load steps = " +
                                  std::to_string(s.friction.load_steps) +
                                  ": the map extrapolates from N and 2N steps and measures it from N/2: give an even "
                                  "number >= 2");
    if (s.map.parameter != MapParameters::Parameter::friction_coefficient && !s.map.poisson_ratios.empty())
      throw std::invalid_argument(where + "Map/nu values is set for Map/parameter other than friction coefficient: "
                                  "the other maps run at Material/nu");
    if (s.map.parameter == MapParameters::Parameter::friction_coefficient)
      require_curved_power_law(s, where, "friction coefficient", "the map finds the contact set during loading",
                               "friction");
    if (s.map.parameter == MapParameters::Parameter::erf_width)
      for (const double k : s.map.exponents.empty() ? std::vector<double>{s.material.k} : s.map.exponents)
        if (k != 0.)
          throw std::invalid_argument(where + "Map/parameter = erf width with k = " + format(k) + " (" +
                                      (s.map.exponents.empty() ? "Material/k" : "Map/k values") +
                                      "): the error-function grading needs k = 0 (homogeneous E0 below the skin)");
    if (!(s.load.a > 0.))
      throw std::invalid_argument(where + "Load/a = " + format(s.load.a) + " must be in (0, inf) (z0 or H = a / value)");
    }
  } // namespace

  SceneKind decide_kind(const Scene &s)
  {
    const CandidateParameters &c = s.candidate;
    if (s.map.enabled())
      return SceneKind::map;
    // an adhesive or tangential candidate brings its own adhesion or tangential path
    if (c.enabled() && (c.has_adhesive_entries() || c.has_tangential_entries()))
      return SceneKind::candidate;
    if (s.tangential.enabled())
      return SceneKind::tangential;
    if (s.adhesion.enabled(s.load))
      return SceneKind::adhesion;
    if (c.enabled())
      return SceneKind::candidate;
    return s.references.fem ? SceneKind::normal : SceneKind::analytic;
  }

  bool friction_is_tangential(const Scene &s)
  {
    return s.tangential.enabled() || (s.candidate.enabled() && s.candidate.has_tangential_entries());
  }

  bool frictional_loading(const Scene &s) { return s.friction.coefficient > 0. && !friction_is_tangential(s); }

  namespace
  {
    /// Every map: the checks of its parameter.
    /// Map/parameter = largest stress: a sphere on the power law, k >= 0 (on k < 0 no largest stress exists).
    void check_stress_map(const Scene &s, const std::string &where)
    {
      if (s.load.type != LoadParameters::Type::paraboloid)
        throw std::invalid_argument(where + "Map/parameter = largest stress needs Load/type = paraboloid");
      using Modulus = MaterialParameters::Modulus;
      const Modulus modulus = s.material.modulus;
      if (modulus != Modulus::power_law && modulus != Modulus::shifted_power_law && modulus != Modulus::coating)
        throw std::invalid_argument(where + "Map/parameter = largest stress needs Material/modulus = power law, "
                                            "shifted power law or coating");
      // A finite surface modulus bounds the skin's stresses for every k; the power law and a coating (the power law
      // near the surface) have no largest stress on k < 0.
      for (const double k : s.map.exponents.empty() ? std::vector<double>{s.material.k} : s.map.exponents)
        if (!(k >= 0) && modulus != Modulus::shifted_power_law)
          throw std::invalid_argument(where + "Map/k values (or Material/k): " + format(k) +
                                      " must be in [0, 1) for a largest stress on this modulus: on k < 0 the skin's "
                                      "radial and hoop stresses grow without bound toward the surface (a finite "
                                      "surface modulus, Material/modulus = shifted power law, takes k < 0)");
      for (const double nu : s.map.poisson_ratios.empty() ? std::vector<double>{s.material.nu} : s.map.poisson_ratios)
        if (!(nu < 0.5))
          throw std::invalid_argument(where + "Map/nu values (or Material/nu): " + format(nu) +
                                      " must be in [0, 0.5) (the closed-form field)");
    }

    void check_map(const Scene &s, const std::string &where)
    {
      if (s.map.parameter == MapParameters::Parameter::largest_stress)
        check_stress_map(s, where);
      else if (s.map.parameter == MapParameters::Parameter::coulomb_3d)
        check_coulomb_map(s, where);
      else if (s.map.parameter == MapParameters::Parameter::tabor_parameter)
        check_tabor_map(s, where);
      else
        check_normal_map(s, where);
    }

    /// The sections' own ranges, named like the entries' parse errors ("scene <file>: Section/entry ...").
    void check_sections(const Scene &s)
    {
      try
        {
          s.material.check();
          s.indenter.check();
          s.tangential.check();
          s.map.check();
        }
      catch (const std::exception &e)
        {
          throw std::invalid_argument("scene " + s.file + ": " + concise(e));
        }
    }
  } // namespace

  void validate(const Scene &s, const SceneKind kind)
  {
    const std::string where = "scene " + s.file + ": ";
    check_sections(s);
    check_contract(s, where);
    check_common(s, where);
    switch (kind)
      {
        case SceneKind::map:
          check_map(s, where);
          break;
        case SceneKind::candidate:
          if (s.candidate.family() == CandidateParameters::Family::normal)
            check_candidate(s);
          else
            check_family_candidate(s, where);
          break;
        case SceneKind::tangential:
          if (s.adhesion.enabled(s.load))
            throw std::invalid_argument(where + "Tangential/study is set and the scene is adhesive "
                                        "(Adhesion/work of adhesion or tensile strength > 0): tangential contact is "
                                        "non-adhesive (9.75-9.87); choose one");
          check_tangential(s, where);
          break;
        case SceneKind::adhesion:
          check_adhesion(s, where);
          break;
        case SceneKind::normal:
        case SceneKind::analytic:
          break;
      }
  }

  void require_kind(const Scene &s, const SceneKind kind, const std::string &function)
  {
    const SceneKind actual = decide_kind(s);
    if (actual != kind)
      throw std::invalid_argument(function + ": scene " + s.file + " is a " + to_string(actual) + " scene, not a " +
                                  to_string(kind) + " scene");
    validate(s, kind);
  }

  const std::vector<DeprecatedName> &deprecated_names()
  {
    static const std::vector<DeprecatedName> names{{"Tangential/friction coefficient", "Friction/coefficient"},
                                                   {"Map/ratios", "Map/values"}};
    return names;
  }

  namespace
  {
    /// The deprecated name `name` stands for, or nullptr.
    const DeprecatedName *deprecated(const std::string &name)
    {
      for (const DeprecatedName &d : deprecated_names())
        if (d.old_name == name)
          return &d;
      return nullptr;
    }

    /// Declares every entry, bound to the members of `s` (which must outlive `prm`'s reading).
    void declare_all(ParameterHandler &prm, Scene &s)
    {
      s.info.declare(prm);
      s.material.declare(prm);
      s.load.declare(prm);
      s.indenter.declare(prm);
      s.discretization.declare(prm);
      s.outputs.declare(prm);
      s.references.declare(prm);
      s.tolerances.declare(prm);
      s.candidate.declare(prm);
      s.adhesion.declare(prm);
      s.tangential.declare(prm);
      s.friction.declare(prm);
      s.map.declare(prm);
    }

    /// deal.II's tree names with every character but [a-zA-Z0-9] written as _XX (hex; ParameterHandler docs).
    std::string demangle(const std::string &name)
    {
      std::string out;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size() && std::isxdigit(static_cast<unsigned char>(name[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(name[i + 2])))
          {
            out += static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          out += name[i];
      return out;
    }

    /// Every declared entry as "Section/entry" (from the handler's JSON tree: an entry is an object with a "value").
    void declared_paths(const nlohmann::json &node, const std::string &prefix, std::vector<std::string> &paths)
    {
      for (auto it = node.begin(); it != node.end(); ++it)
        if (it.value().is_object())
          {
            const std::string path = prefix + demangle(it.key());
            if (it.value().contains("value") && it.value().at("value").is_string())
              paths.push_back(path);
            else
              declared_paths(it.value(), path + "/", paths);
          }
    }

    /// A "set" line of a .prm text: its index among the lines, how many lines it spans (a trailing backslash
    /// continues it), "Section/entry" and the value.
    struct SetLine
    {
      std::size_t line, count;
      std::string path, value;
    };

    /// The "set" lines of a .prm text under their "subsection"s (comments dropped).
    std::vector<SetLine> set_lines(const std::vector<std::string> &lines)
    {
      std::vector<SetLine>     found;
      std::vector<std::string> stack;
      for (std::size_t i = 0; i < lines.size(); ++i)
        {
          const auto        uncommented = [&](const std::size_t j) { return trim(lines[j].substr(0, lines[j].find('#'))); };
          std::string       line        = uncommented(i);
          const std::size_t first       = i;
          while (!line.empty() && line.back() == '\\' && i + 1 < lines.size())
            {
              ++i;
              line = trim(line.substr(0, line.size() - 1) + " " + uncommented(i));
            }
          if (line.rfind("subsection ", 0) == 0)
            stack.push_back(trim(line.substr(11)));
          else if (line == "end" && !stack.empty())
            stack.pop_back();
          else if (line.rfind("set ", 0) == 0)
            {
              std::string path;
              for (const std::string &section : stack)
                path += section + "/";
              const std::size_t eq = line.find('=');
              found.push_back({first, i + 1 - first, path + trim(line.substr(4, eq - 4)),
                               eq == std::string::npos ? "" : trim(line.substr(eq + 1))});
            }
        }
      return found;
    }

    std::vector<std::string> lines_of(const std::string &file)
    {
      std::vector<std::string> lines;
      std::ifstream            in(file);
      for (std::string line; std::getline(in, line);)
        lines.push_back(line);
      return lines;
    }

    /// The entries a .prm file sets, as "Section/entry".
    std::vector<std::string> paths_set_in(const std::string &file)
    {
      std::vector<std::string> paths;
      for (const SetLine &set : set_lines(lines_of(file)))
        paths.push_back(set.path);
      return paths;
    }

    /// " (did you mean 'Section/entry'?)" for the first path in `used` that is not declared, when a declared one
    /// is close to it; else "".
    std::string did_you_mean(const std::vector<std::string> &used)
    {
      ParameterHandler prm;
      Scene            unread;
      declare_all(prm, unread);
      std::ostringstream tree;
      prm.print_parameters(tree, ParameterHandler::JSON);
      std::vector<std::string> declared;
      declared_paths(nlohmann::json::parse(tree.str()), "", declared);
      for (const std::string &path : used)
        {
          if (std::find(declared.begin(), declared.end(), path) != declared.end() || deprecated(path))
            continue;
          std::string best;
          std::size_t best_distance = std::numeric_limits<std::size_t>::max();
          for (const std::string &candidate : declared)
            if (const std::size_t d = edit_distance(path, candidate); d < best_distance)
              best = candidate, best_distance = d;
          if (best_distance <= std::max<std::size_t>(2, path.size() / 4))
            return " ('" + path + "' is no scene entry; did you mean '" + best + "'?)";
          return " ('" + path + "' is no scene entry; `gradcontact run --help-scene` lists them)";
        }
      return "";
    }
  } // namespace

  namespace
  {
    std::vector<std::string> split_path(const std::string &name)
    {
      std::vector<std::string> path;
      std::stringstream        in(name);
      for (std::string part; std::getline(in, part, '/');)
        path.push_back(part);
      return path;
    }

    std::string joined(const std::vector<std::string> &path)
    {
      std::string name;
      for (const std::string &p : path)
        name += (name.empty() ? "" : "/") + p;
      return name;
    }

    /// A scene file's entry under a deprecated name, to be set under its new one after the file is read.
    struct Renamed
    {
      DeprecatedName name;
      std::string    value;
    };

    /// An old name set beside its new one is ambiguous: which value was meant?
    void refuse_both(const DeprecatedName &d)
    {
      throw std::invalid_argument(d.old_name + " is the deprecated name of " + d.new_name +
                                  ", which the file also sets: keep " + d.new_name + " only");
    }

    /// Reads a .prm file into `prm` but for the lines setting a deprecated name, which are blanked (every other
    /// line keeps its number for deal.II's errors) and returned.
    std::vector<Renamed> parse_prm(ParameterHandler &prm, const std::string &file)
    {
      std::vector<std::string> lines = lines_of(file);
      const std::vector<SetLine> sets = set_lines(lines);
      std::vector<Renamed>       renamed;
      for (const SetLine &set : sets)
        if (const DeprecatedName *d = deprecated(set.path))
          {
            if (std::any_of(sets.begin(), sets.end(), [&](const SetLine &t) { return t.path == d->new_name; }))
              refuse_both(*d);
            renamed.push_back({*d, set.value});
            std::fill_n(lines.begin() + set.line, set.count, std::string());
          }
      std::ostringstream text;
      for (const std::string &line : lines)
        text << line << '\n';
      std::istringstream in(text.str());
      prm.parse_input(in, file, "", false);
      return renamed;
    }

    /// The same for a JSON file, an object of subsections ({"Material": {"k": "0.5"}, ...}).
    std::vector<Renamed> parse_json(ParameterHandler &prm, const std::string &file)
    {
      std::ifstream        in(file);
      nlohmann::json       tree = nlohmann::json::parse(in);
      std::vector<Renamed> renamed;
      const auto find = [&](const std::vector<std::string> &path) -> nlohmann::json * {
        if (!tree.contains(path[0]) || !tree[path[0]].is_object() || !tree[path[0]].contains(path[1]))
          return nullptr;
        return &tree[path[0]][path[1]];
      };
      for (const DeprecatedName &d : deprecated_names())
        if (const nlohmann::json *value = find(split_path(d.old_name)))
          {
            if (find(split_path(d.new_name)))
              refuse_both(d);
            renamed.push_back({d, value->is_string() ? value->get<std::string>() : value->dump()});
            tree[split_path(d.old_name)[0]].erase(split_path(d.old_name)[1]);
          }
      std::istringstream text(tree.dump());
      prm.parse_input_from_json(text, false);
      return renamed;
    }

    /// Reads `file` into `prm`. Errors name the file; a misspelt entry of a .prm file gets the closest one.
    std::vector<Renamed> parse_scene_file(ParameterHandler &prm, const std::string &file)
    {
      const bool json = std::filesystem::path(file).extension() == ".json";
      try
        {
          if (!std::filesystem::is_regular_file(file))
            throw std::invalid_argument("no such file");
          return json ? parse_json(prm, file) : parse_prm(prm, file);
        }
      catch (const std::invalid_argument &e)
        {
          throw std::invalid_argument("scene " + file + ": " + concise(e));
        }
      catch (const std::exception &e)
        {
          // deal.II names the line, the entry and the pattern it violates
          throw std::invalid_argument("scene " + file + ": " + concise(e) + (json ? "" : did_you_mean(paths_set_in(file))));
        }
    }

    /// Sets `name` = `value` in `prm`; an error names `origin` (where the value came from) and the closest entry.
    void set_entry(ParameterHandler &prm, const std::string &name, const std::string &value, const std::string &origin)
    {
      const std::vector<std::string> path = split_path(name);
      try
        {
          for (std::size_t i = 0; i + 1 < path.size(); ++i)
            prm.enter_subsection(path[i]);
          prm.set(path.back(), value);
          for (std::size_t i = 0; i + 1 < path.size(); ++i)
            prm.leave_subsection();
        }
      catch (const std::exception &e)
        {
          throw std::invalid_argument(origin + ": " + concise(e) + did_you_mean({name}));
        }
    }

    /// The scene `s`, whose members the file and the overrides have set, finished: the entries whose text needs
    /// translating, the candidate's FE tolerance as the Tolerances, the report's name, the resolved entries.
    void finish_scene(ParameterHandler &prm, Scene &s)
    {
      try
        {
          s.discretization.parse(prm);
          s.candidate.parse(prm);
          s.friction.parse(prm);
        }
      catch (const std::exception &e)
        {
          throw std::invalid_argument("scene " + s.file + ": " + concise(e));
        }
      if (s.candidate.fe_tolerance > 0.)
        s.tolerances = {s.candidate.fe_tolerance, s.candidate.fe_tolerance, s.candidate.fe_tolerance,
                        s.candidate.fe_tolerance, s.candidate.fe_tolerance};
      if (s.info.name.empty())
        s.info.name = std::filesystem::path(s.file).stem().string();
      std::ostringstream out;
      prm.print_parameters(out, ParameterHandler::ShortPRM);
      s.resolved = out.str();
    }
  } // namespace

  Override parse_override(const std::string &text)
  {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("--set '" + text + "': expected Section/key=value");
    Override o;
    o.path = split_path(text.substr(0, eq));
    if (o.path.size() < 2)
      throw std::invalid_argument("--set '" + text + "': expected Section/key=value (the section is missing)");
    o.value = text.substr(eq + 1);
    return o;
  }

  Scene read_scene(const std::string &file, const std::vector<Override> &overrides)
  {
    Scene s;
    s.file = file;
    ParameterHandler prm;
    declare_all(prm, s);
    // a deprecated name, in the file or an override, sets its new name (after the file, before the overrides)
    const auto note = [&](const DeprecatedName &d) {
      s.notes.push_back(d.old_name + " is a deprecated name, read as " + d.new_name + ": write " + d.new_name);
    };
    for (const Renamed &r : parse_scene_file(prm, file))
      {
        set_entry(prm, r.name.new_name, r.value,
                  "scene " + file + ": " + r.name.old_name + " = " + r.value + " (the deprecated name of " +
                    r.name.new_name + ")");
        note(r.name);
      }
    for (const Override &o : overrides)
      {
        const std::string     name = joined(o.path);
        const DeprecatedName *d    = deprecated(name);
        set_entry(prm, d ? d->new_name : name, o.value, "scene " + file + ": --set " + name + "=" + o.value);
        if (d)
          note(*d);
      }
    finish_scene(prm, s);
    s.kind = decide_kind(s);
    validate(s, s.kind);
    return s;
  }

  std::string scene_documentation()
  {
    ParameterHandler prm;
    Scene            unread;
    declare_all(prm, unread);
    std::ostringstream out;
    prm.print_parameters(out, ParameterHandler::PRM);
    out << "\n# Deprecated names, still read as their new ones:\n";
    for (const DeprecatedName &d : deprecated_names())
      out << "#   " << d.old_name << " -> " << d.new_name << "\n";
    return out.str();
  }
} // namespace gradcontact::cases
