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

#include "scene/scene.h"

#include <fem/accuracy/accuracy.h>

#include <array>
#include <memory>
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
  /// The same for several measures, which share the search's first grid (one ladder run for all). `surface`: the
  /// grids take the surface z = 0 too (a modulus finite there, whose largest stress may lie on it; the place's
  /// estimate is then at least the last grid's step in depth).
  std::vector<FeStressMaximum> largest_fe_stresses(fem::ContractSolver &solver, const fem::LoadCase &load,
                                                   const std::vector<std::string> &names, bool surface);

  /// The unit sphere, R = a = 1 on E0 = c0 = 1, on one of the scene's gradings: the power law (9.1), a finite surface
  /// modulus ((z + z0)/c0)^k or a power-law coating of thickness H on its substrate (fem/modulus/modulus.h; `length`
  /// is z0 or H over a). The normalised stresses depend on k, nu and that length alone, so the unit problem answers
  /// every scale. One ladder, which every search and sample on it shares.
  class UnitSphere
  {
  public:
    /// `largest_radius`: the largest radius asked of the surface (fem::contract_settings; 0: the mesh's own).
    UnitSphere(MaterialParameters::Modulus modulus, double k, double nu, double length, double tolerance,
               double largest_radius = 0);
    ~UnitSphere();

    fem::ContractSolver &solver() { return *contract; }
    const fem::LoadCase &load() const { return indenter; }
    /// Whether the surface is part of the search: a finite surface modulus, whose largest stress may lie on it (on
    /// the power law the surface stresses vanish, k > 0, are unbounded, k < 0, or are Hertz's, k = 0).
    bool finite_surface() const { return surface; }

  private:
    bool                                 surface = false;
    fem::LoadCase                        indenter;
    std::unique_ptr<fem::ContractSolver> contract;
  };

  /// The search of largest_fe_stresses on `sphere`, the surface included where its modulus is finite there.
  std::vector<FeStressMaximum> largest_fe_stresses(UnitSphere &sphere, const std::vector<std::string> &names);

  /// The radial stress on the surface outside a sphere (cases/tools/ring_stress.h).
  struct SurfaceRadialStress
  {
    std::vector<fem::Estimated> sigma_rr; ///< at the asked radii, over p_m
    double                      p_m = 0;  ///< F / pi of the FE's force
    fem::ContractResult         run;      ///< what the contract met or what limited it
  };

  /// The recovered sigma_rr(r, 0) at `radii` below `sphere` (made with a largest_radius that covers them).
  SurfaceRadialStress surface_radial_stress(UnitSphere &sphere, const std::vector<double> &radii);
} // namespace gradcontact::cases

#endif
