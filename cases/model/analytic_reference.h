// gradcontact/cases: the analytic side of a scene. One builder turns a scene's material and load into a
// typed request (analytic/request.h) of the closed forms or of the numerical MDR, for the normal, adhesive
// and tangential runners alike; a comparison adds only its own inputs (a radius, a force, a branch).
#ifndef GRADCONTACT_CASES_ANALYTIC_REFERENCE_H
#define GRADCONTACT_CASES_ANALYTIC_REFERENCE_H

#include "scene/scene.h"

#include <analytic/request.h>

#include <functional>
#include <string>

namespace gradcontact::cases
{
  /// What a comparison adds to the scene's request: r, Fx, control, ...
  using Inputs = std::function<void(batch::Request &)>;

  /// The inputs comparisons add most often.
  namespace input
  {
    Inputs r(double r);
    Inputs a(double a);
    Inputs a_r(double a, double r);
    Inputs control(Control control);
    Inputs mechanism(Mechanism mechanism);
    /// first, then second (either may be empty).
    Inputs both(Inputs first, Inputs second);
  } // namespace input

  class AnalyticReference
  {
  public:
    /// Which of the chapter's problems the scene's load is read as.
    enum class Problem
    {
      normal,    ///< frictionless normal contact (9.14-9.44): flat_punch, cone, ..., constant_pressure
      adhesive,  ///< JKR (9.45-9.74): jkr_flat_punch, jkr_paraboloid, jkr_power_law, jkr_concave, optimal_profile
      tangential ///< the sphere of the scene (9.75-9.87); the case is named at each call
    };

    /// The request of the scene. For a curved indenter under depth or force control (normal problem) the
    /// reference state's contact radius is solved here, by the same method: DomainError when it has none.
    AnalyticReference(const Scene &scene, batch::Method method, Problem problem);

    /// The value of `quantity` of the scene's case, with the comparison's inputs.
    double get(const std::string &quantity, const Inputs &inputs = {}) const;
    /// The same at the radius r (pressure, displacement, profile, traction).
    double at(const std::string &quantity, double r) const;
    /// The value of `quantity` of another case with the scene's material, contact radius and sphere
    /// (coefficients, flat_punch, paraboloid, tangential_sphere, oscillating_sphere).
    double get(const std::string &case_name, const std::string &quantity, const Inputs &inputs) const;

    /// The contact radius of the reference state (given, or solved from d or F).
    double radius() const;
    batch::Method method() const { return base.method; }
    /// "closed form" or "numerical MDR", for report rows; when the scene's modulus is not the power law
    /// (layered, an expression, ...), followed by " (power-law idealisation E0, c0, k)": the chapter's
    /// material, not the scene's; when the scene's elastic indenter is not covered by 9.4 (a homogeneous one
    /// on a graded half-space), by " (rigid-indenter idealisation)"; with Friction/coefficient > 0, by
    /// " (frictionless idealisation)".
    std::string label() const;
    /// Whether the reference assumes another material, indenter or surface than the scene's.
    bool idealised() const { return idealised_material || idealised_indenter || idealised_surface || idealised_adhesion; }

  private:
    batch::Request base;
    bool idealised_material = false, idealised_indenter = false, idealised_surface = false, idealised_adhesion = false;
  };
} // namespace gradcontact::cases

#endif
