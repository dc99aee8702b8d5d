// The sign check of a frictionless contact state from its nodal contact forces (both solvers).
//
// A frictionless contact transmits compression only, so a state is consistent when no part of the contact carries
// tension. The nodal forces R_i = \int p phi_i r dr of Lagrange elements of degree >= 2 are not sign-definite,
// though: where p is steep (the (a - r)^{(k-1)/2} edge of a flat punch, k < 0) the nodes inside an edge cell carry
// negative forces next to a large positive one although p > 0 everywhere (the flat punch at k = -0.5, degree 3: a
// negative nodal force of the order of a tenth of the largest in a state whose total force is accurate). A tensile
// zone of the solution shows differently: the net force of the contact between the node and the centre, or between
// the node and the edge, is tensile as well. So a node counts as tensile when its own force and the smaller of
// those two partial sums are both below -tolerance * max |R|.
#ifndef GRADCONTACT_FEM_CONTACT_CHECK_H
#define GRADCONTACT_FEM_CONTACT_CHECK_H

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace gradcontact::fem
{
  /// `forces`: the nodal contact forces ordered by radius, centre first. Returns the most tensile
  /// max(R_i, min(sum_{j <= i} R_j, sum_{j >= i} R_j)) / max_j |R_j| over the nodes (0 when there is no
  /// force at all): below -tolerance the state is inconsistent (a tensile zone), above it is not.
  inline double min_relative_contact_force(const std::vector<double> &forces)
  {
    double max_force = 0, total = 0;
    for (const double R : forces)
      {
        max_force = std::max(max_force, std::abs(R));
        total += R;
      }
    if (!(max_force > 0))
      return 0;
    double worst = std::numeric_limits<double>::max(), inner = 0;
    for (const double R : forces)
      {
        inner += R;                         // sum_{j <= i}
        const double outer = total - inner + R; // sum_{j >= i}
        worst = std::min(worst, std::max(R, std::min(inner, outer)));
      }
    return worst / max_force;
  }
} // namespace gradcontact::fem

#endif
