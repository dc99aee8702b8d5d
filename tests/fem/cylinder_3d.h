// An independent 3D deal.II model of a graded cylinder under a tangential surface traction: the check of
// the Fourier-mode-1 weak form (fem/tangential/fourier_mode1_solver.h). It exists for that check (test_mode1.cc), which
// mode1_study load=cylinder runs at any refinement.
//
// Body: the cylinder x^2 + y^2 <= R^2, 0 <= z <= H (z into the material), E = E(z) of any ModulusField,
// constant nu. Weak form: \int_\Omega [lambda div u div v + 2 mu eps(u) : eps(v)] dV = \int_{z=0} tau(r) v_x dA,
// with FE_Q(2)^3 and MappingQ(2) on a mesh extruded from GridGenerator::hyper_ball (2D), the lateral
// surface on a CylindricalManifold, the rest on a TransfiniteInterpolationManifold, refined globally (20 base cells: 5 in the disc, 4 slices).
// Boundary conditions: u = 0 on the lateral surface r = R and on the bottom z = H; traction tau(r) e_x
// on the top z = 0 (tau = 0 outside the loaded zone).
// Solver: UMFPACK up to 5000 DoFs, above CG with SSOR to a relative residual of 1e-12.
//
// Output: u at (r, 0, 0) and at (0, r, 0) on the top. The mode-1 counterpart is U(r, 0) = u_x(r, 0, 0),
// W(r, 0) = u_z(r, 0, 0), V(r, 0) = u_x(0, r, 0), and u_y = u_z = 0 at (0, r, 0).
#ifndef GRADCONTACT_TESTS_FEM_CYLINDER_3D_H
#define GRADCONTACT_TESTS_FEM_CYLINDER_3D_H

#include <fem/modulus/modulus.h>

#include <deal.II/grid/tria.h>

#include <array>
#include <functional>
#include <vector>

namespace gradcontact::fem::testing
{
  struct Cylinder3D
  {
    Material                      material;
    double                        R = 1, H = 1;
    std::function<double(double)> traction; ///< tau(r)
    unsigned int                  refinements = 1; ///< global refinements of the 20-cell base mesh
  };

  struct Cylinder3DResult
  {
    std::vector<std::array<double, 3>> at_x; ///< u at (r, 0, 0)
    std::vector<std::array<double, 3>> at_y; ///< u at (0, r, 0)
    unsigned int n_dofs = 0, iterations = 0;
    double       seconds = 0;
  };

  Cylinder3DResult solve_cylinder_3d(const Cylinder3D &problem, const std::vector<double> &radii);

  /// The meridian rectangle [0, R] x [0, H] of the same cylinder for FourierMode1Solver: n_r x n_z
  /// cells refined `refinements` times; ids axis (r = 0), contact (z = 0, r <= a), free_surface
  /// (z = 0, r > a), far_field (r = R and z = H, the clamped faces). a must be a multiple of R / n_r.
  void make_meridian_rectangle(double R, double H, double a, unsigned int n_r, unsigned int n_z,
                               unsigned int refinements, dealii::Triangulation<2> &tria);
} // namespace gradcontact::fem::testing

#endif
