// The surface compliance of the 3D half body: what the 3D solver (fem/bodies/half_space_3d.h) gives the 3D contact
// models (fem/tangential/coulomb_contact_3d.h), so that neither header includes the other.
#ifndef GRADCONTACT_FEM_SURFACE_COMPLIANCE_3D_H
#define GRADCONTACT_FEM_SURFACE_COMPLIANCE_3D_H

#include <deal.II/base/point.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <vector>

namespace gradcontact::fem
{
  /// The compliance of the candidate surface nodes of the half body (HalfSpace3DSolver::surface_compliance).
  struct SurfaceCompliance3D
  {
    std::vector<dealii::Point<2>> nodes; ///< (x, y) on z = 0, y >= 0, physical units
    /// index of component c of node i among the unknowns, or -1: u_y on the symmetry plane (and everywhere in a
    /// compliance along_load), whose force Q_y is then zero and whose slip is along x
    std::vector<std::array<int, 3>> unknown;
    dealii::FullMatrix<double>      C;    ///< u_k = sum_l C(k, l) F_l over the unknowns
    std::vector<double>             area; ///< \int_{z=0} phi_i dA of each node's shape function (half body)
  };
} // namespace gradcontact::fem

#endif
