// gradcontact/cases: the FE stresses below a contact as the suite reports them: a measure of the recovered stress with
// the bound its components' estimates give, and the largest measure with its place (fem/elasticity/stress_recovery.h,
// fem/accuracy/accuracy.h).
//
// A measure (principal stresses, von Mises, largest shear) carries the bound its components' estimates give: a
// principal stress moves by at most the Frobenius norm F of the components' errors (Weyl's inequality;
// F^2 = e_rr^2 + e_zz^2 + e_tt^2 + 2 e_rz^2), the largest shear by at most F, von Mises by at most sqrt(3/2) F.
//
// The largest measure below a contact of radius 1: the recovered field on the grid r = 0, 1/20, ..., 2 by 30 depths
// geometric from 1e-3 to 2, all in one ladder run, then four runs of a 7 x 7 grid about the best point with a third
// of the steps each time, then a parabola through the best point and its neighbours in r and in z (the measure is
// even in r, so the axis is its own mirror). The value's estimate is the measure's at the best grid point plus the
// parabola's rise and its change between one and two grid steps; the location's is the larger of its change between
// one and two steps and its change from the ladder's level below to the finest (relative to the contact radius for
// the radius, to the depth for the depth).
#ifndef GRADCONTACT_CASES_FE_STRESS_H
#define GRADCONTACT_CASES_FE_STRESS_H

#include <fem/accuracy/accuracy.h>

#include <array>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// The measure `name` (rr, zz, tt, rz, principal_max, principal_min, von_mises, max_shear) of estimated stress
  /// components (sigma_rr, sigma_zz, sigma_tt, sigma_rz) and its error bound (header). A DomainError naming the valid
  /// ones when `name` is none of them.
  fem::Estimated stress_measure(const std::array<fem::Estimated, 4> &components, const std::string &name);

  /// The largest measure below a contact and where it is.
  struct FeStressMaximum
  {
    fem::Estimated      value;    ///< of the measure, with the parabola's rise (header)
    fem::Estimated      r, z;     ///< its place (contact radii)
    fem::Estimated      at_point; ///< the measure at the best grid point, as the contract estimated it
    fem::ContractResult run;      ///< the ladder run of the last grid: what the contract met or what limited it
  };

  /// The search of the header for the measure `name` (von_mises or max_shear) below `load` on `solver`'s ladder (a
  /// body whose contact radius is 1).
  FeStressMaximum largest_fe_stress(fem::ContractSolver &solver, const fem::LoadCase &load, const std::string &name);
  /// The same for several measures, which share the search's first grid (one ladder run for all).
  std::vector<FeStressMaximum> largest_fe_stresses(fem::ContractSolver &solver, const fem::LoadCase &load,
                                                   const std::vector<std::string> &names);
} // namespace gradcontact::cases

#endif
