// gradcontact/cases: the one translation of a scene into the FE model of the graded half-space.
//
// Every runner (normal, candidate, adhesive, tangential scenes, the figures' FE points) asks here for
//   - the material: the modulus field of Material/modulus (power law, N layers of exact averages, or an
//     expression) with Material/nu;
//   - the load: Load/type and Load/control as an fem::LoadCase;
//   - the settings: fem::recommended_settings for the surface exponent s of that modulus field
//     (ModulusField::surface_exponent(): E ~ z^s as z -> 0), never for Material/k. The two differ for a
//     layered modulus, whose top layer is a constant (s = 0): its surface needs no z-halvings (those of
//     k = 0.5, 1e-10 a thin, make the solve unreliable at one refinement: the energy check flags it). The far
//     field L/a follows the exponent deep below (the layers' base power law: k). Then Discretization/degree,
//     formulation, far field (L/a, 0: the recommended one) and the uniform refinement level of the run.
#ifndef GRADCONTACT_CASES_FE_MODEL_H
#define GRADCONTACT_CASES_FE_MODEL_H

#include "scene/scene.h"

#include <fem/bodies/axisymmetric_solver.h>
#include <fem/modulus/modulus.h>
#include <fem/contact/unilateral_contact.h>

#include <analytic/mdr.h>

#include <optional>

namespace gradcontact::cases
{
  /// The FE material of the scene (power law, layered or expression modulus). The layered zone is
  /// Material/layered depth times Load/a deep.
  fem::Material fe_material(const Scene &scene);

  /// The elastic indenter of Indenter/elasticity as the second body of fem::UnilateralContactSolver: a
  /// homogeneous E, nu, or the power law E (z/c0)^k with the Material's k and c0; none when rigid.
  std::optional<fem::Material> fe_indenter_body(const Scene &scene);

  /// Discretization/formulation as the FE enum.
  fem::Formulation fe_formulation(const Scene &scene);

  /// Load/type as a rigid indenter (the adhesive models take it as their profile): paraboloid, cone, power law,
  /// concave punch; none for the flat punch and the constant pressure.
  std::optional<fem::Profile> fe_indenter_profile(const LoadParameters &l);

  /// Load/type and Load/control as an FE load: flat punch (depth d), concave punch (d0), constant
  /// pressure (p0), or a curved indenter under contact-radius, depth or force control.
  fem::LoadCase fe_load(const Scene &scene);

  /// The mesh and discretisation of the scene at contact radius `contact_radius` (the adhesive searches
  /// solve at many radii) and `refinement` uniform refinements: the recommended settings for the
  /// surface exponent of `material.modulus` and Discretization/force tolerance, the far field L/a for its
  /// deep exponent (unless Discretization/far field gives one), with the scene's degree and formulation.
  fem::Settings fe_settings(const Scene &scene, const fem::Material &material, double contact_radius,
                            unsigned int refinement);

  /// The last (finest) entry of Discretization/refinements: the level of the runs that solve once (the
  /// candidate's FE check, the tangential model, the figures' FE points).
  unsigned int finest_refinement(const Scene &scene);

  /// Material, load and settings of one FE run of the scene at contact radius Load/a.
  struct FeModel
  {
    fem::Material material;
    std::optional<fem::Material> indenter_body; ///< fe_indenter_body
    fem::LoadCase load;
    fem::Settings settings;
  };
  FeModel fe_model(const Scene &scene, unsigned int refinement);

  /// Discretization/far field condition = auto: the condensed far field of fem::use_condensed_far_field for the
  /// runs of the axisymmetric and mode-1 solvers (L / a = Discretization/far field if given, else 100 or 1.5 times the largest
  /// Outputs/displacement radii); returns whether it applied.
  bool condense_far_field(const Scene &scene, const fem::Material &material, fem::Settings &settings);

  /// A candidate's profile f(r) as a rigid FE indenter; its growth exponent 2 only seeds the depth and force
  /// searches of a depth- or force-controlled indenter.
  fem::Profile candidate_indenter(const mdr::Profile &profile);

  /// The FE model of a candidate scene (Candidate/profile): `profile`, the user's f(r), as a rigid indenter
  /// under contact-radius control at Load/a, at the finest refinement level.
  FeModel candidate_fe_model(const Scene &scene, const fem::Profile &profile);

  /// The FE solve of candidate_fe_model for the user's f(r) (candidate_indenter), with the condensed far field of
  /// Discretization/far field condition, sampled at output_request(scene).
  fem::Result solve_candidate(const Scene &scene, const mdr::Profile &profile);

  /// The largest |value| of FE samples (the scale of p(r)'s relative errors); 0 for none.
  double largest_magnitude(const std::vector<fem::Sample> &samples);

  /// Outputs/pressure radii and displacement radii (in units of Load/a) as FE sample radii.
  fem::OutputRequest output_request(const Scene &s);

  /// The unilateral solve of a scene with `indenter`: Load/control force or depth (Load/force, Load/depth), the
  /// scene's elastic indenter, meshes graded from Load/a toward the edge found.
  fem::UnilateralResult solve_unilateral(const Scene &s, const FeModel &model, fem::Indenter indenter, bool by_force,
                                         const fem::OutputRequest &out);

  /// The rigid indenter of a unilateral candidate scene (Load/contact = unilateral): Candidate/profile table (a CSV
  /// file of r, f rows; a relative path is taken from the scene's folder) or, without one, `profile` (the user's
  /// f(r)), bounded by Candidate/indenter radius.
  fem::Indenter candidate_unilateral_indenter(const Scene &s, const std::function<double(double)> &profile);
} // namespace gradcontact::cases

#endif
