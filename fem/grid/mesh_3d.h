// The mesh of the 3D half-space model (fem/bodies/half_space_3d.h): the half cylinder
//   x^2 + y^2 <= L^2,  y >= 0,  0 <= z <= L        (z into the material, y = 0 the symmetry plane),
// i.e. the revolution of the meridian domain max(r, z) <= L of fem/grid/mesh.h, so that the 3D model and the
// axisymmetric and mode-1 models solve the same truncated problem and differ by discretisation only.
//
// Construction (lengths in units of the contact radius a):
//  1. the surface plane: a half disc of radius L made of a core (the half ball layout: a half square of
//     (n/2) x (n/4) cells and n cells between it and the arc at the core radius R0) and rings of n sectors
//     (n = `sectors`) at radii graded
//     geometrically toward the contact circle r = 1 from both sides (distances h_edge, h_edge (1 + q),
//     h_edge (1 + q + q^2), ...; inside at most inner_ring_width apart when it is set) and beyond that growing
//     by the factor g out to L;
//  2. extrusion in z through slices graded the same way from z = 0, the first one surface_layer_thickness thin
//     (GridGenerator::extrude_triangulation).
//     The cells at the contact edge (r = a, z = 0), where the stresses are singular, are then h_edge thin
//     in r and z and long along the circle, where the fields are smooth (constant or cos theta): the
//     anisotropic geometric grading toward a singular line that isotropic refinement (all p4est can do)
//     would pay for with cells along the whole circle;
//  3. the ring cells on a CylindricalManifold about the z axis (manifold id `cylindrical_manifold_id`; exact:
//     in cylindrical coordinates the rings are boxes), the core cells flat with their faces at r = R0 on the
//     cylinder, so that refinement keeps the contact circle and the lateral far field exact;
//  4. refinement (isotropic, the only kind p4est makes): `edge_refinements` cycles toward the contact
//     circle (r = a, z = 0), each refining the cells whose centre lies within `edge_grading` of their
//     diameters from it; `contact_refinements` cycles of every cell with a face on the contact disc (the
//     surface layer under the load); `global_refinements` uniform cycles (h-studies).
//
// Boundary ids (fem/base/boundary_ids.h): contact (z = 0, r <= a), free_surface (z = 0, r > a), symmetry_plane
// (y = 0), far_field (r = L and z = L). The refinement rules use the geometry only, so a serial and a
// distributed triangulation (every process flags its own cells) get the same mesh.
#ifndef GRADCONTACT_FEM_MESH_3D_H
#define GRADCONTACT_FEM_MESH_3D_H

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

namespace gradcontact::fem
{
  struct HalfSpaceMesh3DParameters
  {
    double       contact_radius      = 1.0; ///< a (physical units)
    double       core_radius         = 0.5; ///< R0 / a, (0.1, 0.9)
    unsigned int sectors             = 8;   ///< cells around the half circle: 4, 8, 16 or 32
    double       far_field_size      = 8.0; ///< L / a, [2, 1e8]
    double       ring_growth         = 1.6; ///< target ratio of consecutive rings beyond a, [1.1, 4]
    double       h_edge              = 1e-3; ///< smallest ring width and slice thickness at the edge / a, [1e-8, 0.25]
    double       edge_ratio          = 2.0;  ///< ratio q of consecutive graded steps, [1.2, 4]
    /// The largest ring width inside the contact circle / a, 0 (none: the rings grow by q down to the core) or
    /// [h_edge, 0.25]: rings of at most this width over R0 < r < a resolve a stick-slip boundary anywhere there.
    double       inner_ring_width    = 0;
    /// Thickness of the first slice / a (0: h_edge), 0 or [1e-12, 0.25]: thinner for k > 0, where u_z ~ z^(1-k)
    /// under the load (the slices grow from it by q, so a thin layer costs log(h_edge / thickness) / log q slices).
    double       surface_layer_thickness = 0;
    unsigned int edge_refinements    = 0;   ///< cycles toward the contact circle, <= 12
    double       edge_grading        = 1.0; ///< refine within this many diameters of the circle, [0, 4]
    unsigned int contact_refinements = 0;   ///< cycles of the cells on the contact disc, <= 6
    unsigned int global_refinements  = 0;   ///< uniform cycles, <= 3

    /// Throws std::invalid_argument naming the member, its value and the valid range.
    void validate() const;
  };

  struct HalfSpaceMesh3DInfo
  {
    unsigned int n_rings       = 0; ///< rings growing by g (beyond the graded zone) in the depth direction
    double       ring_growth   = 0; ///< the g used there (L hit exactly)
    unsigned int coarse_cells  = 0;
    double       min_edge_cell = 0; ///< smallest cell diameter at the contact circle / a
  };

  /// The manifold id of the ring cells (CylindricalManifold about the z axis).
  constexpr dealii::types::manifold_id cylindrical_manifold_id = 1;

  /// Steps 1-3 into `tria` (empty; serial or parallel::distributed), manifold attached.
  HalfSpaceMesh3DInfo make_coarse_mesh_3d(const HalfSpaceMesh3DParameters &parameters, dealii::Triangulation<3> &tria);

  /// Step 4; fills min_edge_cell (the minimum over all processes when `tria` is distributed).
  void refine_mesh_3d(const HalfSpaceMesh3DParameters &parameters, dealii::Triangulation<3> &tria,
                      HalfSpaceMesh3DInfo &info);
} // namespace gradcontact::fem

#endif
