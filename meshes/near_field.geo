// Near field of the axisymmetric graded half-space, in units of the contact radius a.
//
// The meridian plane (r, z), z pointing into the material, is the square [0, R1] x [0, R1].
// Its boundary carries the named physical groups that fem/boundary_ids.h maps to boundary ids:
//
//   axis          r = 0                         (u_r = 0)
//   contact       z = 0, 0 <= r <= 1            (the punch face / loaded zone / contact candidate)
//   free_surface  z = 0, 1 <= r <= R1           (traction free)
//   far_field     r = R1 or z = R1              (where deal.II glues the geometric far-field rings)
//
// The mesh is unstructured, recombined into quadrilaterals and split so that every cell is a quad
// (Mesh.SubdivisionAlgorithm = 1). Sizes: h_edge at the contact edge (r, z) = (1, 0), h_surface at
// the axis, h_outer at (R1, 0), h_far on the far-field lines. deal.II refines further (isotropic
// refinement at the contact edge, z-only halvings of the surface layer) and adds the far field:
// gmsh's geometric tolerances are relative to the model size, so the 1e-9 a .. 1e12 a span is not
// asked of gmsh.
//
// Parameters (override with gmsh -setnumber NAME VALUE):
DefineConstant[ R1 = 4.0 ];         // near-field size / a
DefineConstant[ h_edge = 0.02 ];    // cell size at the contact edge / a
DefineConstant[ h_surface = 0.15 ]; // cell size at r = 0 and r = R1 on the surface / a
DefineConstant[ h_far = 1.0 ];      // cell size on the far-field lines / a
DefineConstant[ h_outer = 0.15 ];   // cell size at r = R1 on the surface / a (the driver passes h_surface unless told)

Point(1) = {0, 0, 0, h_surface};
Point(2) = {1, 0, 0, h_edge};
Point(3) = {R1, 0, 0, h_outer};
Point(4) = {R1, R1, 0, h_far};
Point(5) = {0, R1, 0, h_far};

Line(1) = {1, 2};   // contact
Line(2) = {2, 3};   // free surface
Line(3) = {3, 4};   // far field, r = R1
Line(4) = {4, 5};   // far field, z = R1
Line(5) = {5, 1};   // axis

Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

// The ids must match fem/boundary_ids.h.
Physical Curve("contact", 1) = {1};
Physical Curve("free_surface", 2) = {2};
Physical Curve("far_field", 3) = {3, 4};
Physical Curve("axis", 4) = {5};
Physical Surface("material", 0) = {1};

// Frontal-Delaunay for quads (algorithm 8 crashed on recombined surfaces with gmsh 4.8; 6 is safe),
// Blossom recombination, then full subdivision into quads.
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
Mesh.ElementOrder = 1;
Mesh.MshFileVersion = 2.2;
Mesh.CharacteristicLengthExtendFromBoundary = 1;
