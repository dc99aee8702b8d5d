// Boundary ids of the meridian-plane meshes (and of the 3D half-space mesh, fem/grid/mesh_3d.h). They are the physical-group tags of meshes/near_field.geo
// (gmsh writes them into the .msh and GridIn turns them into boundary ids); the deal.II-built near field
// and the far-field rings use the same constants. Id 0 is deliberately unused: deal.II gives it to every
// boundary face it was not told about, so a face that still carries 0 after mesh generation is a bug.
#ifndef GRADCONTACT_FEM_BOUNDARY_IDS_H
#define GRADCONTACT_FEM_BOUNDARY_IDS_H

#include <deal.II/base/types.h>

namespace gradcontact::fem::boundary_id
{
  using dealii::types::boundary_id;

  /// z = 0, 0 <= r <= a: punch face, loaded zone or contact candidate zone.
  constexpr boundary_id contact = 1;
  /// z = 0, r > a: traction free.
  constexpr boundary_id free_surface = 2;
  /// The truncation boundary at distance L (u = 0 there).
  constexpr boundary_id far_field = 3;
  /// r = 0: symmetry axis, u_r = 0.
  constexpr boundary_id axis = 4;
  /// y = 0 of the 3D half-space model (fem/bodies/half_space_3d.h): symmetry plane, u_y = 0.
  constexpr boundary_id symmetry_plane = 5;
  /// What deal.II assigns to boundary faces nobody named.
  constexpr boundary_id unassigned = 0;

  /// The surface z = 0 (contact zone or free surface).
  constexpr bool is_surface(const boundary_id id)
  {
    return id == contact || id == free_surface;
  }
} // namespace gradcontact::fem::boundary_id

#endif
