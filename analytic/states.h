// gradcontact/analytic: the names of the contact states that the closed forms (adhesion.h,
// tangential.h) and the numerical MDR (mdr.h, mdr_contact.h) both speak of. One enum each, so that
// a request, a scene or a test names a state once, whichever path evaluates it.
#ifndef GRADCONTACT_ANALYTIC_STATES_H
#define GRADCONTACT_ANALYTIC_STATES_H

namespace gradcontact
{
  /// What is prescribed in an adhesive contact: the force (the critical state is the minimum of
  /// F_N(a)) or the depth (the minimum of d(a)), chapter 9.2.1.
  enum class Control
  {
    force,
    displacement
  };

  /// How a concave punch in complete adhesive contact separates (9.64-9.68).
  enum class Mechanism
  {
    periphery, ///< separation from the edge singularity (9.65-9.66)
    centre,    ///< the tensile strength sigma_th reached at r = 0 (9.67-9.68)
    governing  ///< whichever happens first on unloading (the larger critical depth)
  };

  /// The branches of a tangential force that oscillates between +-F_A after loading (9.80-9.86).
  enum class Branch
  {
    loading,   ///< O -> A, the initial loading (9.80)
    unloading, ///< A -> E, F_x falling from F_A to -F_A (9.81-9.83)
    reloading  ///< E -> F, F_x rising from -F_A to F_A
  };
} // namespace gradcontact

#endif
