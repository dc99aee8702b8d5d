#include "cylinder_3d.h"

#include <fem/base/boundary_ids.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <chrono>
#include <cmath>

namespace gradcontact::fem::testing
{
  using namespace dealii;

  namespace
  {
    // Boundary ids of the 3D mesh (local to this check).
    constexpr types::boundary_id lateral = 0, top = 1, bottom = 2;
    constexpr types::manifold_id cylinder_manifold = 0;
    // Up to this many DoFs UMFPACK, above CG + SSOR (the fill-in of a 3D sparse LU makes it slow well before
    // memory runs out).
    constexpr unsigned int direct_limit = 5000;
  } // namespace

  namespace
  {
    /// The 2D disc of radius R (5 cells) extruded to 0 <= z <= H in 4 slices, the lateral surface on a
    /// CylindricalManifold, refined globally `refinements` times.
    void make_cylinder(const Cylinder3D &p, Triangulation<3> &tria)
    {
      Triangulation<2> disc;
      GridGenerator::hyper_ball(disc, Point<2>(), p.R);
      GridGenerator::extrude_triangulation(disc, 4, p.H, tria);
      tria.reset_all_manifolds();
      tria.set_all_manifold_ids(numbers::flat_manifold_id);
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<3> c = cell->face(f)->center();
              if (std::abs(c[2]) < 1e-12 * p.H)
                cell->face(f)->set_boundary_id(top);
              else if (std::abs(c[2] - p.H) < 1e-12 * p.H)
                cell->face(f)->set_boundary_id(bottom);
              else
                {
                  cell->face(f)->set_boundary_id(lateral);
                  cell->face(f)->set_all_manifold_ids(cylinder_manifold);
                }
            }
      tria.set_manifold(cylinder_manifold, CylindricalManifold<3>(2));
      tria.refine_global(p.refinements);
    }

    /// The symmetric gradient and the divergence of every shape function of `fv` at quadrature point q.
    void strains(const FESystem<3> &fe, const FEValues<3> &fv, const unsigned int q,
                 std::vector<SymmetricTensor<2, 3>> &eps, std::vector<double> &div)
    {
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const unsigned int  c = fe.system_to_component_index(i).first;
          const Tensor<1, 3> &g = fv.shape_grad(i, q);
          eps[i]                = SymmetricTensor<2, 3>();
          for (unsigned int d = 0; d < 3; ++d)
            eps[i][c][d] += (c == d ? 1.0 : 0.5) * g[d];
          div[i] = g[c];
        }
    }

    /// The stiffness matrix of the graded body and the load vector of tau(r) e_x on the top, u = 0 on the lateral
    /// surface and the bottom (in `constraints`).
    void assemble(const Cylinder3D &p, const MappingQ<3> &mapping, const FESystem<3> &fe,
                  const DoFHandler<3> &dof_handler, const AffineConstraints<double> &constraints,
                  SparseMatrix<double> &A, Vector<double> &b)
    {
      const double nu = p.material.nu;
      const double c_lambda = nu / ((1 + nu) * (1 - 2 * nu)), c_mu = 1 / (2 * (1 + nu));
      FEValues<3>     fv(mapping, fe, QGauss<3>(4), update_values | update_gradients | update_quadrature_points |
                                                      update_JxW_values);
      FEFaceValues<3> ffv(mapping, fe, QGauss<2>(4), update_values | update_quadrature_points | update_JxW_values);
      const unsigned int n = fe.n_dofs_per_cell();
      FullMatrix<double> cell_matrix(n, n);
      Vector<double>     cell_rhs(n);
      std::vector<types::global_dof_index> dofs(n);
      std::vector<SymmetricTensor<2, 3>>   eps(n);
      std::vector<double>                  div(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fv.reinit(cell);
          cell_matrix = 0;
          cell_rhs    = 0;
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              const double E = p.material.modulus->value(fv.quadrature_point(q)[2]);
              const double lambda = c_lambda * E, mu = c_mu * E;
              strains(fe, fv, q, eps, div);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) += (lambda * div[i] * div[j] + 2 * mu * (eps[i] * eps[j])) * fv.JxW(q);
            }
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == top)
              {
                ffv.reinit(cell, f);
                for (const unsigned int q : ffv.quadrature_point_indices())
                  {
                    const Point<3> &x = ffv.quadrature_point(q);
                    const double    t = p.traction(std::hypot(x[0], x[1]));
                    for (unsigned int i = 0; i < n; ++i)
                      if (fe.system_to_component_index(i).first == 0)
                        cell_rhs(i) += t * ffv.shape_value(i, q) * ffv.JxW(q);
                  }
              }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, A, b);
        }
    }

    /// UMFPACK up to direct_limit DoFs, above CG with SSOR to a relative residual of 1e-12; the CG iterations
    /// (0: direct).
    unsigned int solve(const SparseMatrix<double> &A, const Vector<double> &b, Vector<double> &u)
    {
      if (b.size() <= direct_limit)
        {
          SparseDirectUMFPACK direct;
          direct.initialize(A);
          direct.vmult(u, b);
          return 0;
        }
      SolverControl            control(20000, 1e-12 * b.l2_norm());
      SolverCG<Vector<double>> cg(control);
      PreconditionSSOR<SparseMatrix<double>> ssor;
      ssor.initialize(A, 1.2);
      cg.solve(A, u, b, ssor);
      return control.last_step();
    }
  } // namespace

  Cylinder3DResult solve_cylinder_3d(const Cylinder3D &p, const std::vector<double> &radii)
  {
    const auto start = std::chrono::steady_clock::now();
    p.material.validate();
    Triangulation<3> tria;
    make_cylinder(p, tria);

    const FESystem<3> fe(FE_Q<3>(2), 3);
    DoFHandler<3>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<3> mapping(2);

    AffineConstraints<double> constraints;
    VectorTools::interpolate_boundary_values(mapping, dof_handler, lateral, Functions::ZeroFunction<3>(3),
                                             constraints);
    VectorTools::interpolate_boundary_values(mapping, dof_handler, bottom, Functions::ZeroFunction<3>(3),
                                             constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    SparseMatrix<double> A(sparsity);
    Vector<double>       b(dof_handler.n_dofs()), u(dof_handler.n_dofs());
    assemble(p, mapping, fe, dof_handler, constraints, A, b);

    Cylinder3DResult result;
    result.n_dofs     = dof_handler.n_dofs();
    result.iterations = solve(A, b, u);
    constraints.distribute(u);

    Vector<double> value(3);
    for (const double r : radii)
      {
        VectorTools::point_value(mapping, dof_handler, u, Point<3>(r, 0, 0), value);
        result.at_x.push_back({{value[0], value[1], value[2]}});
        VectorTools::point_value(mapping, dof_handler, u, Point<3>(0, r, 0), value);
        result.at_y.push_back({{value[0], value[1], value[2]}});
      }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }

  void make_meridian_rectangle(const double R, const double H, const double a, const unsigned int n_r,
                               const unsigned int n_z, const unsigned int refinements, Triangulation<2> &tria)
  {
    GridGenerator::subdivided_hyper_rectangle(tria, {n_r, n_z}, Point<2>(0, 0), Point<2>(R, H));
    const double tol = 1e-12 * R;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<2> c = cell->face(f)->center();
            if (c[0] < tol)
              cell->face(f)->set_boundary_id(boundary_id::axis);
            else if (c[1] < tol)
              cell->face(f)->set_boundary_id(c[0] < a ? boundary_id::contact : boundary_id::free_surface);
            else
              cell->face(f)->set_boundary_id(boundary_id::far_field);
          }
    tria.refine_global(refinements);
  }
} // namespace gradcontact::fem::testing
