// gradcontact/cases: a scene, i.e. one deal.II ParameterHandler file (.prm).
//
// One struct per subsection, whose declare() declares its entries and binds each to its member (deal.II's
// add_parameter pattern): ranges in the patterns, a doc string on every entry; check() the ranges a pattern
// cannot state. Variants of a scene are overrides on the command line
// (`--set Section/key=value`), never copied files. `gradcontact run --help-scene` prints every entry.
#ifndef GRADCONTACT_CASES_SCENE_H
#define GRADCONTACT_CASES_SCENE_H

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace gradcontact::cases
{
  struct SceneInfo
  {
    std::string name; ///< report folder; empty: the file's stem
    std::string description;
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
  };

  struct MaterialParameters
  {
    enum class Modulus
    {
      power_law,
      layered,
      expression,
      shifted_power_law, ///< E0 ((z + z0)/c0)^k: a finite surface modulus
      coating,           ///< the power law over 0 < z <= H on the homogeneous substrate E0 (H/c0)^k
      table,             ///< a measured E(z) from a CSV file (z [m], E [Pa])
      error_function     ///< E0 [1 + (m - 1) erfc(z/w)]: the surface modulus m E0 relaxing to E0 over w (k = 0)
    };
    double E0 = 1e9, c0 = 1e-3, k = 0.5, nu = 0.3;
    Modulus modulus = Modulus::power_law;
    unsigned int layers = 16;    ///< layered: number of layers
    double layered_depth = 10.;  ///< layered: depth of the layered zone / a (below: the power law)
    std::string expression;      ///< expression: E(z), constants E0, c0, k
    double surface_depth = 0.;   ///< shifted power law: z0 [m], > 0
    double coating_thickness = 0.; ///< coating: H [m], > 0
    std::string table_file;      ///< table: the CSV file (relative to the scene's folder)
    double surface_modulus_ratio = 10.; ///< error function: m = E(0) / E0, > 0
    double erf_width = 0.;       ///< error function: w [m], > 0
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
    /// The section's own ranges, those its patterns cannot state (open ends, entries that go together).
    void check() const;
  };

  struct LoadParameters
  {
    enum class Type
    {
      flat_punch,
      paraboloid,
      cone,
      power_law,
      concave_punch,
      constant_pressure
    };
    enum class Control
    {
      contact_radius,
      depth,
      force
    };
    enum class Contact
    {
      disc,      ///< the contact zone is the disc r <= a (fem::AxisymmetricSolver)
      unilateral ///< the contact set is found (Signorini; fem::UnilateralContactSolver)
    };
    Type type = Type::flat_punch;
    Control control = Control::contact_radius;
    Contact contact = Contact::disc;
    double a = 1e-4;      ///< contact radius (punch radius, loaded radius)
    double depth = 1e-6;  ///< d (flat punch, depth control), d0 (concave punch)
    double force = 1e-2;  ///< F_N (force control)
    double R = 1e-2, tan_theta = 0.1, n = 2., A = 1., h0 = 1e-7, p0 = 1e6;
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
  };

  /// The indenter's elasticity (Load/contact = unilateral, fem::UnilateralContactSolver): rigid, a homogeneous
  /// elastic body E, nu (a sphere of radius R >> a as a half-space), or a second graded body E (z/c0)^k with the
  /// Material's k and c0 (9.4: the equivalent medium is exact). The chapter's closed forms take the second
  /// graded body (and a homogeneous one at k = 0) through 9.4; a homogeneous body at k != 0 has no closed form,
  /// and the rows say they assume a rigid indenter.
  struct IndenterParameters
  {
    enum class Elasticity
    {
      rigid,
      homogeneous,
      graded
    };
    Elasticity elasticity = Elasticity::rigid;
    double E = 1e9;  ///< homogeneous: E [Pa]; graded: its E0 [Pa]
    double nu = 0.3; ///< Poisson's ratio of the indenter
    /// The chapter's closed forms hold for this pairing (rigid, a graded body of the Material's law, or a
    /// homogeneous one on a homogeneous half-space).
    bool covered_by_9_4(double k) const { return elasticity != Elasticity::homogeneous || k == 0.; }
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
    /// The section's own ranges, those its patterns cannot state (open ends, entries that go together).
    void check() const;
  };

  /// The Coulomb friction coefficient mu of the scene, the one entry Friction/coefficient whatever the scene:
  /// the mu of the tangential contact of 9.75-9.87 in a tangential scene (friction_is_tangential), else friction
  /// between a rigid indenter and the surface during normal loading (Load/contact = unilateral, fem::Friction):
  /// the frictionless assumption of the chapter (9.1-9.44) dropped. That answer depends on the loading path: the
  /// load grows from zero in `load_steps` steps; the closed-form rows then compare the chapter's frictionless
  /// idealisation with the frictional FE.
  struct FrictionParameters
  {
    double coefficient = 0.;       ///< mu in [0, inf]; 0: frictionless, inf: full stick
    unsigned int load_steps = 24;  ///< steps of the normal loading path (mu > 0)
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
    /// The entry whose text needs translating, read after the file and the overrides: Friction/coefficient (a number or inf).
    void parse(dealii::ParameterHandler &prm);
  };

  /// The largest Tabor parameter a Lennard-Jones path resolves: its edge's cells shrink like lambda^-2 from lambda = 5
  /// on, down to 1 / fem::max_edge_refinement (64) of theirs, so lambda <= 5 sqrt(64) (fe_cohesive.cc asserts the
  /// two agree).
  inline constexpr double largest_lennard_jones_lambda = 40;

  struct DiscretizationParameters
  {
    unsigned int degree = 3;
    std::vector<unsigned int> refinements = {0}; ///< uniform refinements; several = a convergence study
    double force_tolerance = 1e-6; ///< picks the recommended mesh (fem::recommended_settings); the contract's tolerance
    /// Discretization/accuracy = contract: the normal scene's FE answers come from the ladder of fem/accuracy/accuracy.h at
    /// force_tolerance (its degree; refinements and degree unused), every FE row with its estimate and verdict.
    bool contract = false;
    /// A level whose forecast factorisation exceeds 80 % of the machine's available memory is refused before it
    /// starts; `run --force` (memory guard = off) solves it anyway.
    bool memory_guard = true;
    double far_field = 0.;         ///< L/a; 0: the recommended one
    enum class Formulation
    {
      displacement, ///< (u_r, u_z)
      mixed,        ///< (u_r, u_z) and q = lambda div u (Taylor-Hood)
      automatic     ///< mixed from nu = 0.45 on (fem::automatic_mixed_threshold)
    };
    Formulation formulation = Formulation::displacement; ///< the FE unknowns (fem::Formulation)
    /// The surface map of fem/modulus/surface_map.h instead of z-halvings for 0 < k < 1 in the rigid frictionless
    /// normal scenes (fem::use_surface_map); off: the halvings everywhere.
    bool surface_map = true;
    /// The exterior of max(r, z) = L condensed onto it (fem::use_condensed_far_field) where it applies, in the
    /// scenes of fem::AxisymmetricSolver and fem::FourierMode1Solver; off: u = 0 at L.
    bool condensed_far_field = true;
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
    /// The entry whose text needs translating, read after the file and the overrides: Discretization/refinements (each in 0..10).
    void parse(dealii::ParameterHandler &prm);
  };

  struct OutputParameters
  {
    bool force = true, depth = true, contact_radius = true;
    std::vector<double> pressure_radii;     ///< / a
    std::vector<double> displacement_radii; ///< / a
    bool vtu = false;
    bool plots = true;
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
  };

  struct ReferenceParameters
  {
    bool closed_form = true;
    bool numerical_mdr = false;
    bool fem = true; ///< false: only the analytic references are compared (closed form vs MDR)
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
  };

  struct ToleranceParameters
  {
    double force = 1e-5, depth = 1e-4, contact_radius = 1e-4, pressure = 1e-3, displacement = 1e-4;
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
  };

  /// JKR adhesion (9.45-9.74) checked by the FE model (fem/adhesion/adhesion.h). A scene is adhesive when the work of
  /// adhesion is positive (flat punch, paraboloid, cone, power law, concave punch), or for the optimal profile:
  /// Load/type = constant pressure with a positive tensile strength (p = -sigma_th on r <= a, 9.69-9.74).
  struct AdhesionParameters
  {
    double work_of_adhesion = 0.;  ///< dgamma [J/m^2]
    bool force_control = true, displacement_control = true;
    double tensile_strength = 0.;  ///< sigma_th [Pa]
    double initial_radius = 0.;    ///< a0 of the critical search [m]; 0: Load/a
    double stencil_ratio = 1.05;
    bool local_stencil = true;
    std::vector<double> curve_points; ///< a / a_c of FE points on the force-depth curve (force control)
    /// The adhesive law of the FE.
    enum class Law
    {
      jkr,          ///< the chapter's (the FE from its energy release rate)
      dugdale,      ///< a cohesive zone of strength sigma_0 (given, or from the Tabor parameter lambda,
                    ///< cases/runners/fe_cohesive.h), fem/adhesion/cohesive_zone.h
      lennard_jones ///< fem/adhesion/smooth_cohesion.h, its largest stress the Dugdale sigma_0 of the Tabor parameter
                    ///< (Tabor-parameter maps only)
    };
    Law law = Law::jkr;
    double tabor_parameter = 0.;    ///< lambda > 0 (Dugdale; or cohesive_strength)
    double cohesive_strength = 0.;  ///< sigma_0 [Pa] > 0 (Dugdale; or tabor_parameter)
    bool enabled(const LoadParameters &load) const;
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
  };

  /// A user's candidate closed form for an axisymmetric profile, checked against the numerical MDR.
  struct CandidateParameters
  {
    std::string profile;                  ///< f(r); empty: no candidate check
    std::string slope, curvature;         ///< f'(r), f''(r); empty: fourth-order finite differences of f
    std::string constants;                ///< "R=0.01, A=2"
    std::string depth, force, pressure, displacement; ///< d(a), F(a), p(r, a), w(r, a); empty: not checked
    /// With Load/contact = unilateral (the contact set found; it may be an annulus or end at the indenter's
    /// edge): the expressions take the FE's load state d, F instead of a, and these two check the contact.
    std::string outer_radius, inner_radius; ///< the outer edge and the inner edge (0 for a disc), of d, F
    double indenter_radius = 0.;            ///< the indenter's radius [m] (unilateral); 0: unbounded
    std::string profile_table; ///< a CSV file of r, f(r) rows (unilateral only; instead of `profile`)
    /// Adhesive (JKR, Adhesion/work of adhesion) candidates: d(a), F(a) on the adhesive branch over `range`,
    /// p(r, a) at Load/a, and the critical state under `critical_control` (constants).
    std::string adhesive_depth, adhesive_force, adhesive_pressure;
    std::string critical_radius, critical_force, critical_depth;
    bool critical_force_control = true; ///< Candidate/critical control = force (else displacement)
    /// Tangential (Ciavarella-Jaeger, Friction/coefficient) candidates at Load/a: K_T(a) over `range`;
    /// F_x(c, a), u0(c, a) over stick radii; c(Fx, a) and the dissipated energy W(FA, a) over forces and
    /// amplitudes up to gross slip; u0(Fx, FA, a) on the unloading and reloading branches at Tangential/amplitude.
    std::string tangential_stiffness, tangential_force, tangential_displacement, stick_radius, dissipated_energy;
    std::string unloading_displacement, reloading_displacement;
    /// Contact radii of the curves in a: range[0] a .. range[1] a, a = Load/a; `points` points on every curve.
    std::vector<double> range{0.25, 4.};
    unsigned int points = 9;
    /// Which family the candidate's formulas belong to (one per scene).
    enum class Family
    {
      normal,
      adhesive,
      tangential
    };
    /// The family of the entries set; throws when both the adhesive and the tangential family's are set.
    Family family() const;
    bool has_adhesive_entries() const;   ///< an adhesive depth, force or pressure, or a critical state
    bool has_tangential_entries() const; ///< any of the tangential candidate formulas
    /// A candidate scene: a profile expression or a profile table.
    bool enabled() const { return !profile.empty() || !profile_table.empty(); }
    double tolerance = 1e-8; ///< relative, of every row against the numerical MDR
    /// Of every row against the FE, relative; 0: the Tolerances section's entry of the row's quantity (parse_scene
    /// writes a positive value into that section, the only one a candidate scene's FE rows read).
    double fe_tolerance = 0.;
    /// Tangential family: also one loading path of the 3D Coulomb model (cases/model/coulomb_sphere.h) with the candidate's
    /// profile, whose rows say how far Coulomb's law is from the candidate.
    bool coulomb_3d = false;
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
    /// The entry whose text needs translating, read after the file and the overrides: Candidate/FE tolerance (empty or a number).
    void parse(dealii::ParameterHandler &prm);
  };

  /// Tangential contact (9.75-9.87) checked by the Fourier mode-1 FE model (fem/tangential/fourier_mode1_solver.h). A scene
  /// is tangential when `study` is not none; cases/runners/fe_tangential.h runs it.
  struct TangentialParameters
  {
    enum class Study
    {
      none,
      stiffness,    ///< Load/type = flat punch: K_T (9.78-9.79), alpha = K_N / K_T, Mindlin at k = 0
      partial_slip, ///< Load/type = paraboloid: the Ciavarella-Jaeger traction (9.80), F_x(u0)
      oscillation   ///< Load/type = paraboloid: +-F_A after loading to A (9.81-9.87), hysteresis, dissipation
    };
    Study study = Study::none;
    double stick_radius = 0.5;         ///< c / a in (0, 1] (partial slip)
    double amplitude = 0.9;            ///< F_A / (mu F_N) in (0, 1) (oscillation)
    unsigned int load_steps = 5;       ///< FE points on the F_x(u0) curve or the unloading branch
    bool holl_ratio = false;           ///< nu = 1 / (2 + k) (the decoupled pairing), k > 0 only
    unsigned int stick_levels = 8;     ///< SurfaceRefinement levels toward the stick radii
    double assumption_tolerance = 1e-4; ///< of the measured assumption error (spread, |u_y|), against 0
    bool enabled() const { return study != Study::none; }
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
    /// The section's own ranges, those its patterns cannot state (open ends, entries that go together).
    void check() const;
  };

  /// An applicability map (cases/runners/fe_map.h): the FE model of a real grading (a finite surface modulus or a
  /// coating), of an elastic indenter, friction or a finite range of adhesion against the power-law closed forms,
  /// over the values of one variable and several k. `parameter` names the variable, `values` holds its values; a
  /// scene is a map when `parameter` is not none.
  struct MapParameters
  {
    enum class Parameter
    {
      none,
      surface_depth,    ///< Material/modulus = shifted power law; values a/z0
      coating_thickness, ///< Material/modulus = coating; values a/H
      erf_width,         ///< Material/modulus = error function (k = 0); values a/w
      indenter_modulus,  ///< a homogeneous elastic indenter (Indenter/nu) against the rigid one; values E1/E0
      friction_coefficient, ///< Coulomb friction (Friction/load steps) against the frictionless indenter; values mu
      tabor_parameter,      ///< a Dugdale cohesive zone against JKR (cases/runners/fe_cohesive.h); values lambda
      coulomb_3d,           ///< the 3D Coulomb sphere over k and nu against 9.80-9.86 (cases/runners/fe_coulomb_3d.h); values mu
      largest_stress        ///< the largest stresses below a sphere over k and nu, FE against closed form (cases/runners/stress_map.h)
    };
    Parameter parameter = Parameter::none;
    std::vector<double> values;     ///< of the variable `parameter` names: a/z0, a/H, a/w, E1/E0, mu or lambda, > 0
    std::vector<double> exponents;  ///< k values; empty: Material/k
    std::vector<double> poisson_ratios; ///< nu values of a friction or Coulomb 3D map; empty: Material/nu
    bool holl_ratio = true;         ///< friction and Coulomb 3D maps: also nu = 1/(2 + k) (the decoupled pairing)
    bool full_stick = true;         ///< friction map: also mu = inf
    std::vector<double> thresholds = {0.01, 0.001}; ///< deviations whose ratio the map reports
    bool enabled() const { return parameter != Parameter::none; }
    /// Declares the section's entries, each bound to its member (set as the file and the overrides are read).
    void declare(dealii::ParameterHandler &prm);
    /// The section's own ranges, those its patterns cannot state (open ends, entries that go together).
    void check() const;
  };

  /// What a scene checks, decided once from its entries by decide_kind(); the runner dispatches on it.
  enum class SceneKind
  {
    normal,     ///< the FE model against the closed form and/or the numerical MDR (cases/runners/fe_scene.h)
    analytic,   ///< References/fem = false: the closed form against the numerical MDR only (cases/runners/fe_scene.h)
    candidate,  ///< Candidate/profile set: a user's closed forms against the numerical MDR and the FE model
    adhesion,   ///< Adhesion/work of adhesion > 0, or the optimal profile (cases/runners/fe_adhesion.h)
    tangential, ///< Tangential/study != none (cases/runners/fe_tangential.h)
    map         ///< Map/parameter != none (cases/runners/fe_map.h)
  };

  /// The name of a kind, for reports ("normal", "analytic", "candidate", "adhesion", "tangential", "map").
  std::string to_string(SceneKind kind);
  /// The name of Material/modulus in a scene ("power law", "table", ...).
  std::string to_string(MaterialParameters::Modulus modulus);

  struct Scene
  {
    std::string file;
    SceneInfo info;
    MaterialParameters material;
    LoadParameters load;
    IndenterParameters indenter;
    DiscretizationParameters discretization;
    OutputParameters outputs;
    ReferenceParameters references;
    ToleranceParameters tolerances;
    CandidateParameters candidate;
    AdhesionParameters adhesion;
    TangentialParameters tangential;
    FrictionParameters friction;
    MapParameters map;
    std::string resolved; ///< every entry after overrides, as a .prm, stored with the report
    /// What reading the scene wants its author to know: each deprecated name it set, and the name now read.
    std::vector<std::string> notes;
    SceneKind kind = SceneKind::normal; ///< decide_kind() of the entries, set (and validated) by read_scene
  };

  /// Friction/coefficient is the mu of tangential contact (9.75-9.87): a tangential study (a Coulomb 3D map
  /// included, which needs one) or a tangential candidate; elsewhere it is friction during normal loading.
  bool friction_is_tangential(const Scene &scene);
  /// Coulomb friction during normal loading: Friction/coefficient > 0 outside the tangential scenes.
  bool frictional_loading(const Scene &scene);

  /// The kind of `scene`, from its entries only (no checks), in this order: map when Map/parameter is set; candidate
  /// when Candidate/profile (or profile table) is set with adhesive or tangential candidate entries; tangential when
  /// Tangential/study is set; adhesion when AdhesionParameters::enabled; candidate when Candidate/profile is set;
  /// analytic when References/fem is false; else normal.
  SceneKind decide_kind(const Scene &scene);

  /// Checks `scene` as a scene of `kind`: every section's own ranges, then the entries that are valid alone but
  /// not together, for that kind. Throws std::invalid_argument naming the scene file, the entries (Section/name),
  /// their values and what is valid.
  void validate(const Scene &scene, SceneKind kind);

  /// For the runner of one kind: throws std::invalid_argument naming `function`, the scene and its kind when
  /// decide_kind(scene) is not `kind`; then validate(scene, kind).
  void require_kind(const Scene &scene, SceneKind kind, const std::string &function);

  /// An override "Section/key=value" (Section may be nested: "A/B/key=value").
  struct Override
  {
    std::vector<std::string> path; ///< subsections, then the key
    std::string value;
  };
  Override parse_override(const std::string &text);

  /// An entry's former name ("Section/entry"), still read as its new one: one name per concept (the friction
  /// coefficient, the map's values). A scene that sets both names is an error.
  struct DeprecatedName
  {
    std::string old_name, new_name;
  };
  const std::vector<DeprecatedName> &deprecated_names();

  /// Reads a scene (a deprecated name read as its new one), applies the overrides, decides its kind and validates
  /// it. Errors name the file, the entry and the valid range.
  Scene read_scene(const std::string &file, const std::vector<Override> &overrides);

  /// Every entry with its documentation and default (for --help-scene).
  std::string scene_documentation();
} // namespace gradcontact::cases

#endif
