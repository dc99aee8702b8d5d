// The trace of an FE field on the surface z = 0 of the meridian mesh: the boundary faces on z = 0 with
// their DoFs, evaluation of a nodal field at any r, integrals of a surface load against the basis, and
// the consistent recovery of a line density (a pressure) from nodal forces. Every model that loads the
// surface or reads it (contact, tractions, displacements) uses these, not a copy.
//
// The trace of FE_Q(p) on a face is the 1D Lagrange polynomial through the face's support points, so
// a face is described by its support radii r_0 < ... < r_p and, per displacement component, the DoFs
// at those points in the same order.
#ifndef GRADCONTACT_FEM_SURFACE_TRACE_H
#define GRADCONTACT_FEM_SURFACE_TRACE_H

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace gradcontact::fem
{
  /// Value at r of the Lagrange interpolant through (x_i, y_i).
  double lagrange(const std::vector<double> &x, const std::vector<double> &y, double r);

  /// The radius of the support point of every DoF (serial DoF handler).
  std::vector<double> support_radii(const dealii::Mapping<2> &mapping, const dealii::DoFHandler<2> &dof_handler);

  /// A boundary face on z = 0.
  struct SurfaceFace
  {
    double              r0 = 0, r1 = 0; ///< its ends
    bool                contact = false; ///< boundary id `contact` (the mesh's contact zone r <= a)
    std::vector<double> r;               ///< support radii, ascending
    /// dofs[c][i]: the DoF of displacement component c at r[i].
    std::vector<std::vector<dealii::types::global_dof_index>> dofs;
  };

  /// The faces on z = 0 (boundary ids contact and free_surface), ordered by r0, with the DoFs of the
  /// first `n_components` components of `fe` (the displacement; a pressure of the mixed formulation
  /// has other support points and is left out). `support_r[i]` is the radius of DoF i.
  std::vector<SurfaceFace> collect_surface_faces(const dealii::DoFHandler<2> &dof_handler,
                                                 const std::vector<double> &support_r, unsigned int n_components);

  /// The face with r0 <= r <= r1 among those with r1 <= limit (1 + node_tolerance); null if none.
  const SurfaceFace *find_face(const std::vector<SurfaceFace> &faces, double r,
                               double limit = std::numeric_limits<double>::max());

  /// Component c of a nodal field (indexed by global DoF) at r on `face`.
  template <class NodalVector>
  double face_value(const SurfaceFace &face, const unsigned int c, const NodalVector &nodal, const double r)
  {
    std::vector<double> y;
    y.reserve(face.dofs[c].size());
    for (const auto d : face.dofs[c])
      y.push_back(nodal[d]);
    return lagrange(face.r, y, r);
  }

  /// Gauss points (x, weight) of a `n_points` rule on [x0, x1]; an end flagged `graded_*` is
  /// approached by `pieces` sub-intervals shrinking geometrically by `ratio` (a kink or an integrable
  /// singularity of the integrand there).
  struct GradedRule
  {
    unsigned int n_points = 8;
    unsigned int pieces   = 16;
    double       ratio    = 0.25;
  };
  void add_graded_interval(double x0, double x1, bool graded_left, bool graded_right, const GradedRule &rule,
                           std::vector<std::pair<double, double>> &points);

  /// For every face, \int_{face, r <= radius} t(r) phi_i(r) r dr for its nodes i (phi_i the Lagrange
  /// basis of the face), split at `breakpoints` (kinks of t) and at `radius`, graded toward them, also
  /// where one lies in a neighbouring face within two piece lengths of the end (a nearby singularity
  /// outside a piece slows Gauss down as much as one at its end).
  /// `where` names the load in the error thrown when t is not finite.
  std::vector<std::vector<double>> traction_integrals(const std::vector<SurfaceFace> &faces,
                                                      const std::function<double(double)> &t, double radius,
                                                      std::vector<double> breakpoints, const GradedRule &rule,
                                                      const char *where);

  /// The r-weighted mass matrix M_ij = \int phi_i phi_j r dr of component c over the faces with
  /// r1 <= limit (1 + node_tolerance), Gauss with `n_gauss` points per face; `dofs` are the global DoFs of
  /// its rows and columns, ascending r.
  struct LineMass
  {
    std::vector<dealii::types::global_dof_index> dofs;
    dealii::FullMatrix<double>                   matrix;
  };
  LineMass line_mass_matrix(const std::vector<SurfaceFace> &faces, unsigned int c, double limit, unsigned int n_gauss);

  /// The coupling of a piecewise linear density on the surface vertices (hat functions psi_k) with the
  /// trace of component c (phi_i): D_ik = \int phi_i psi_k r dr over the faces with r1 <= limit
  /// (1 + node_tolerance), Gauss with `n_gauss` points per face. `dofs` (rows) and `vertex_r` (columns)
  /// ascend in r. The nodal forces of the density p = sum p_k psi_k are D p.
  struct SurfaceCoupling
  {
    std::vector<dealii::types::global_dof_index> dofs;
    std::vector<double>                          vertex_r;
    dealii::FullMatrix<double>                   matrix;
    /// M_kl = \int psi_k psi_l r dr (tridiagonal, non-negative): the force of a vertex's share of p is (M p)_k.
    dealii::FullMatrix<double> vertex_mass;
  };
  SurfaceCoupling linear_density_coupling(const std::vector<SurfaceFace> &faces, unsigned int c, double limit,
                                          unsigned int n_gauss);

  /// The same coupling for hats on given vertices (ascending, e.g. another body's surface vertices, so
  /// that the meshes need not match): D_ik = \int phi_i psi_k r dr over [vertex_r.front(), vertex_r.back()],
  /// every face split at the vertices inside it, Gauss with `n_gauss` points per piece (exact for a
  /// polynomial trace of degree n_gauss - 2). `dofs` are the DoFs of component c of the faces that overlap
  /// that interval; `vertex_mass` is left empty.
  SurfaceCoupling hat_coupling(const std::vector<SurfaceFace> &faces, unsigned int c,
                               const std::vector<double> &vertex_r, unsigned int n_gauss);

  /// Consistent recovery of a line density p from nodal forces R_i = \int p phi_i r dr on the faces
  /// with r1 <= limit: M p = R with M_ij = \int phi_i phi_j r dr (Gauss with `n_gauss` points per face).
  /// `forces` and the result are indexed by global DoF (size n_dofs); component c of the faces.
  std::vector<double> recover_line_density(const std::vector<SurfaceFace> &faces, unsigned int c,
                                           const dealii::Vector<double> &forces, double limit, unsigned int n_gauss,
                                           std::size_t n_dofs);
} // namespace gradcontact::fem

#endif
