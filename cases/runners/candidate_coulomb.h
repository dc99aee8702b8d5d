// gradcontact/cases: a tangential candidate against the 3D Coulomb model (fem/tangential/coulomb_contact_3d.h).
//
// The candidate's closed forms assume Cattaneo-Mindlin's idealisation (9.75-9.87): the normal and the tangential
// problems decouple, and the tangential traction is along the load. The 3D Coulomb model has neither: friction
// couples the two where nu != 1/(2 + k) (Holl's ratio), and each node slips in its own direction. One loading path
// of that model with the candidate's profile (normal loading to the numerical MDR's d(a), then the tangential
// displacement of F_A = Tangential/amplitude mu F_N(a), one cycle to -delta_A and back) is compared with the
// candidate, so its rows say how far Coulomb's law is from the candidate; at Holl's ratio they check it.
#ifndef GRADCONTACT_CASES_CANDIDATE_COULOMB_H
#define GRADCONTACT_CASES_CANDIDATE_COULOMB_H

#include "report/report.h"
#include "scene/scene.h"

#include <analytic/mdr_contact.h>

#include <map>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// The rows of the tangential candidate `s.candidate` (with its `constants`) against the 3D Coulomb path of its
  /// `profile`, whose normal depth and tangential amplitude come from the numerical MDR's `slip`:
  ///  - on loading, the candidate's F_x at the stick radius whose u0 is the FE's delta (both of its c-forms),
  ///    relative; its u0 at its own stick radius of the FE's F_x, relative; its stick radius of the FE's F_x
  ///    against the FE's stick zone (the mean of the rays' brackets), relative to a, within the
  ///    tolerance plus the brackets' half-width;
  ///  - on the branches, its u0(F_x, F_A) at the FE's F_x and F_A against the FE's delta, relative to delta_A;
  ///  - its dissipated energy at the FE's F_A against the FE's friction work over the cycle, relative.
  /// Tolerances (or Candidate/FE tolerance) of force, displacement and contact radius. A path that fails is one
  /// failed row. Collective under MPI (every process runs the path).
  void coulomb_3d_candidate_rows(const Scene &s, const mdr::Profile &profile, const mdr::PartialSlip &slip,
                                 const std::map<std::string, double> &constants, std::vector<Row> &rows);
} // namespace gradcontact::cases

#endif
