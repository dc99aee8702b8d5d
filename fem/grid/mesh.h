// Meshes of the meridian plane (r, z) of the graded half-space. deal.II coordinates: x = r, y = z, z
// pointing into the material, so the body is the quarter plane x >= 0, y >= 0 truncated at
// max(r, z) = L (an L-infinity "quarter disc").
//
// A mesh is built in three steps:
//  1. the near field [0, R1 a]^2 with the named boundaries of fem/base/boundary_ids.h, graded toward the
//     contact edge (a, 0): from meshes/near_field.geo by gmsh (cached by its parameters, never
//     committed), or, as fallback, a deal.II tensor-product grid with geometric steps;
//  2. far-field rings: the outer boundary polyline P_i of the near field scaled by g, g^2, ..., g^n,
//     g^n R1 = L / a, each ring one layer of quads between the polylines g^{j-1} P_i and g^j P_i.
//     The truncation error of the force falls like (a/L)^{1+k}, so L/a = 1e8..1e14 is wanted
//     and costs only n = log(L / (R1 a)) / log g rings;
//  3. deal.II refinement: `edge_refinements` isotropic refinements of the cells at (a, 0), then z-only
//     halvings (anisotropic, parallel to the surface) of the surface cells with r <= halving_radius a
//     until they are at most surface_layer_thickness a thick: E vanishes (k > 0) or blows up (k < 0)
//     at z = 0 under the whole loaded zone.
#ifndef GRADCONTACT_FEM_MESH_H
#define GRADCONTACT_FEM_MESH_H

#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace gradcontact::fem
{
  enum class NearFieldMesher
  {
    gmsh,   ///< meshes/near_field.geo through the gmsh executable
    deal_ii ///< GridGenerator::subdivided_hyper_rectangle with graded steps
  };

  /// Lengths relative to the contact radius a unless said otherwise.
  struct MeshParameters
  {
    double          contact_radius = 1.0;   ///< a, the length unit of the mesh (physical units)
    NearFieldMesher mesher         = NearFieldMesher::gmsh;
    double          near_field_size = 4.0;  ///< R1 / a
    double          h_edge          = 1e-5; ///< cell size at (a, 0) / a (gmsh; deal.II: first step)
    double          h_surface       = 0.25; ///< cell size at (0, 0) and (R1 a, 0) / a
    double          h_far           = 3.0;  ///< cell size on the near field's outer boundary / a
    /// Cell size at (R1 a, 0) / a when > 0 (else h_surface): a wide near field (a cohesive zone c >> a) with
    /// cells that grow away from the contact (gmsh only).
    double          h_surface_outer = 0.0;
    double          far_field_size  = 1e10; ///< L / a
    double          ring_growth     = 1.15; ///< target ratio g of consecutive far-field rings
    unsigned int    edge_refinements = 0;   ///< isotropic refinements at (a, 0)
    unsigned int    axis_refinements = 0;   ///< isotropic refinement cycles at (0, 0) (cone: p singular there)
    double          axis_grading     = 3.0; ///< per cycle, refine cells whose centre is within
                                            ///< axis_grading diameters of (0, 0); 0: the corner cell only
    double          surface_layer_thickness = 1.0; ///< target thickness of the surface cells / a
    double          halving_radius          = 1.05; ///< z-halvings where r <= halving_radius a
    unsigned int    global_refinements      = 0;    ///< uniform refinements after step 1 (h-studies)
    std::string     geo_file;        ///< empty: meshes/near_field.geo of the source tree
    std::string     cache_directory; ///< empty: $GRADCONTACT_MESH_CACHE, else <build>/mesh-cache
    std::string     gmsh_executable = "gmsh";

    /// Throws std::invalid_argument naming the member, its value and the valid range.
    void validate() const;
  };

  /// What make_mesh did, for reports.
  struct MeshInfo
  {
    unsigned int n_rings           = 0;
    double       ring_growth       = 0;  ///< the g actually used (L hit exactly)
    unsigned int n_halvings        = 0;  ///< refinement sweeps of the surface layer
    double       min_surface_cell  = 0;  ///< thinnest surface cell / a
    double       min_edge_cell     = 0;  ///< smallest cell at (a, 0) / a
    std::string  near_field_source;      ///< cached .msh path or "deal.II"
    bool         cache_hit         = false;
  };

  /// The defaults for a modulus that behaves like z^s at the surface:
  /// L/a such that the truncation error C (a/L)^{1+s}, C <= 1.1, is below `truncation_tolerance`
  /// (within [1e4, 1e16]); z-halvings to 1e-10 a for s > 0 (u_z ~ z^{1-s} is singular there), to
  /// 1e-4 a for s < 0 (sigma_rr ~ E is singular; thinner cells ruin the condition), none for s = 0.
  /// -1 < s <= 1 (s = 1: the Gibson medium, mixed formulation only; no surface layer, its displacement
  /// is regular at z = 0).
  MeshParameters recommended_mesh_parameters(double contact_radius, double surface_exponent,
                                             double truncation_tolerance = 1e-8);

  /// Builds the mesh of steps 1-3 into `tria` (which must be empty): make_coarse_mesh + refine_mesh.
  MeshInfo make_mesh(const MeshParameters &parameters, dealii::Triangulation<2> &tria);

  /// Steps 1-2 in physical units (scaled by the contact radius a): the coarse mesh that a serial and a
  /// distributed triangulation share (parallel::distributed::Triangulation::copy_triangulation).
  MeshInfo make_coarse_mesh(const MeshParameters &parameters, dealii::Triangulation<2> &tria);

  /// Step 3 on a coarse mesh from make_coarse_mesh, serial or parallel::distributed (each process flags
  /// its own cells by the same geometric rule, so the mesh does not depend on the partition). The
  /// z-only halvings are anisotropic refinement, which p4est cannot do: on a distributed triangulation a
  /// surface_layer_thickness that needs halvings throws std::invalid_argument (on every process).
  /// Fills n_halvings, min_surface_cell and min_edge_cell of `info`.
  void refine_mesh(const MeshParameters &parameters, dealii::Triangulation<2> &tria, MeshInfo &info);

  /// Step 1 only, in units of a (for tests and for inspecting the gmsh part).
  MeshInfo make_near_field(const MeshParameters &parameters, dealii::Triangulation<2> &near_field);

  /// Extra refinement of the surface mesh toward points (r, 0) that are no mesh nodes, e.g. the stick
  /// radius c where the partial-slip traction has a kink like (c - r)^{(1+k)/2}. Each level splits the
  /// cells within one cell width of (r, 0): in r only when they are thin (the z-halved surface layer),
  /// isotropically otherwise.
  ///
  /// Intervals r0 < r < r1 of the surface (the window around the end c of a cohesive zone over which its gap is
  /// averaged, fem/adhesion/cohesive_zone.h) are resolved first: the surface cells that overlap one are split until they are
  /// at most (r1 - r0) / cells wide; the levels toward the points then grade from that width.
  struct SurfaceInterval
  {
    double       r0 = 0, r1 = 0; ///< physical units, 0 <= r0 < r1
    unsigned int cells = 0;      ///< cells across [r0, r1], <= 1024
  };

  struct SurfaceRefinement
  {
    std::vector<double> radii;      ///< physical units, > 0
    unsigned int        levels = 0; ///< <= 30
    std::vector<SurfaceInterval> intervals = {};
  };

  /// Applies `refinement` to a meridian mesh (serial triangulation).
  void refine_toward_surface_points(const SurfaceRefinement &refinement, dealii::Triangulation<2> &tria);
} // namespace gradcontact::fem

#endif
