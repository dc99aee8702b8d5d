#include <fem/elasticity/stress_recovery.h>
#include <fem/elasticity/graded_elasticity.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    std::string point_text(const double r, const double z)
    {
      std::ostringstream s;
      s.precision(6);
      s << "(r, z) = (" << r << ", " << z << ")";
      return s.str();
    }
  } // namespace



  struct StressFit::Factorised
  {
    SparsityPattern      sparsity;
    SparseMatrix<double> matrix;
    SparseDirectUMFPACK  direct;
  };



  StressFit::StressFit(const DoFHandler<2> &dof_handler_, const Mapping<2> &mapping_, const Material &material_,
                       const SurfaceMap<2> &map_, const double contact_radius)
    : dof_handler(dof_handler_)
    , mapping(mapping_)
    , material(material_)
    , map(map_)
    , mixed(dof_handler_.get_fe().n_components() == 3)
    , weighted_pressure(mixed && depth_weighted_pressure(material_))
    , over_modulus(material_.modulus->surface_exponent() < 0)
    , pressure_scale(mixed ? mixed_pressure_scale(material_, contact_radius) : 1.0)
    , lambda_factor(material_.nu / ((1 + material_.nu) * (1 - 2 * material_.nu)))
    , mu_factor(1 / (2 * (1 + material_.nu)))
    , scalar_fe(dof_handler_.get_fe().base_element(0).degree)
    , scalar_dofs(dof_handler_.get_triangulation())
    , mass(std::make_unique<Factorised>())
  {
    scalar_dofs.distribute_dofs(scalar_fe);
    DoFTools::make_hanging_node_constraints(scalar_dofs, scalar_constraints);
    scalar_constraints.close();
    cache = std::make_unique<GridTools::Cache<2>>(dof_handler.get_triangulation(), mapping);

    // M of the header: the r-weighted mass matrix of Q_p in the mesh coordinates.
    DynamicSparsityPattern dsp(scalar_dofs.n_dofs());
    DoFTools::make_sparsity_pattern(scalar_dofs, dsp, scalar_constraints, false);
    mass->sparsity.copy_from(dsp);
    mass->matrix.reinit(mass->sparsity);
    const QGauss<2>    quadrature(scalar_fe.degree + 1);
    FEValues<2>        values(mapping, scalar_fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
    const unsigned int n = scalar_fe.n_dofs_per_cell();
    FullMatrix<double> cell_mass(n, n);
    std::vector<types::global_dof_index> indices(n);
    for (const auto &cell : scalar_dofs.active_cell_iterators())
      {
        values.reinit(cell);
        cell_mass = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const double w = values.quadrature_point(q)[0] * values.JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                cell_mass(i, j) += values.shape_value(i, q) * w * values.shape_value(j, q);
          }
        cell->get_dof_indices(indices);
        scalar_constraints.distribute_local_to_global(cell_mass, indices, mass->matrix);
      }
    // A direct solve: the cells span many orders of magnitude of size, so the entries of M do too, and an iterative
    // solve stopped at a residual relative to the whole right-hand side would leave the small cells' values
    // unresolved; the factorisation's accuracy depends on the condition of the diagonally scaled M only.
    mass->direct.initialize(mass->matrix);
  }

  StressFit::~StressFit()
  {
    mass.reset();
    scalar_dofs.clear();
  }

  std::size_t StressFit::bytes() const
  {
    return mass->matrix.memory_consumption() + mass->sparsity.memory_consumption();
  }



  StressRecovery::StressRecovery(const StressFit &fit_, const Vector<double> &u)
    : fit(fit_)
  {
    if (u.size() != fit.dof_handler.n_dofs())
      throw std::invalid_argument("StressRecovery: the solution has " + std::to_string(u.size()) +
                                  " entries, the DoF handler " + std::to_string(fit.dof_handler.n_dofs()));
    project(u);
  }



  std::string StressRecovery::name(const unsigned int c) const
  {
    static const char *names[4] = {"sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz"};
    return std::string(names[c]) + (fit.over_modulus ? "_over_E" : "");
  }



  StressValue StressRecovery::from_gradients(const Point<2> &x, const std::array<double, 2> &u_value,
                                             const std::array<Tensor<1, 2>, 2> &grad, const double q_hat) const
  {
    const SurfaceMap<2>::Value m = fit.map.at(x);
    const double               E = fit.material.modulus->value(m.z);
    // Physical derivatives of the mesh gradients (fem/modulus/surface_map.h).
    const double dur_dz = grad[0][1] / m.dz, dur_dr = grad[0][0] - m.shift[0] * grad[0][1];
    const double duz_dz = grad[1][1] / m.dz, duz_dr = grad[1][0] - m.shift[0] * grad[1][1];
    const double eps_rr = dur_dr, eps_zz = duz_dz, eps_tt = x[0] > 0 ? u_value[0] / x[0] : dur_dr;
    const double mu     = fit.mu_factor * E;
    const double volumetric = fit.mixed ? (fit.weighted_pressure ? E * q_hat : fit.pressure_scale * q_hat) :
                                          fit.lambda_factor * E * (eps_rr + eps_zz + eps_tt);
    return {volumetric + 2 * mu * eps_rr, volumetric + 2 * mu * eps_zz, volumetric + 2 * mu * eps_tt,
            mu * (dur_dz + duz_dr)};
  }



  void StressRecovery::project(const Vector<double> &u)
  {
    // The right-hand sides b_c of the header's fit M s_c = b_c, then back substitutions with the fit's M.
    for (auto &f : fields)
      f.reinit(fit.scalar_dofs.n_dofs());
    const FiniteElement<2> &fe = fit.dof_handler.get_fe();
    const QGauss<2>         quadrature(fit.scalar_fe.degree + 1);
    FEValues<2>             values(fit.mapping, fe, quadrature,
                                   update_values | update_gradients | update_quadrature_points | update_JxW_values);
    FEValues<2>             scalar_values(fit.mapping, fit.scalar_fe, quadrature, update_values);
    const unsigned int      n = fit.scalar_fe.n_dofs_per_cell(), n_q = quadrature.size();
    std::array<Vector<double>, 4> cell_rhs;
    for (auto &v : cell_rhs)
      v.reinit(n);
    std::vector<Vector<double>>              value(n_q, Vector<double>(fe.n_components()));
    std::vector<std::vector<Tensor<1, 2>>>   gradient(n_q, std::vector<Tensor<1, 2>>(fe.n_components()));
    std::vector<types::global_dof_index>     indices(n);

    auto scalar_cell = fit.scalar_dofs.begin_active();
    for (const auto &cell : fit.dof_handler.active_cell_iterators())
      {
        values.reinit(cell);
        scalar_values.reinit(scalar_cell);
        values.get_function_values(u, value);
        values.get_function_gradients(u, gradient);
        for (auto &v : cell_rhs)
          v = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Point<2>   &x = values.quadrature_point(q);
            const StressValue s = from_gradients(x, {{value[q][0], value[q][1]}}, {{gradient[q][0], gradient[q][1]}},
                                                 fit.mixed ? value[q][2] : 0.0);
            const double      f    = fit.over_modulus ? 1 / fit.material.modulus->value(fit.map.at(x).z) : 1.0;
            const double      c[4] = {f * s.rr, f * s.zz, f * s.tt, f * s.rz};
            const double      w    = x[0] * values.JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              {
                const double phi_i = scalar_values.shape_value(i, q) * w;
                for (unsigned int k = 0; k < 4; ++k)
                  cell_rhs[k](i) += phi_i * c[k];
              }
          }
        scalar_cell->get_dof_indices(indices);
        for (unsigned int k = 0; k < 4; ++k)
          fit.scalar_constraints.distribute_local_to_global(cell_rhs[k], indices, fields[k]);
        ++scalar_cell;
      }
    for (auto &f : fields)
      {
        fit.mass->direct.solve(f);
        fit.scalar_constraints.distribute(f);
      }
  }



  std::pair<DoFHandler<2>::active_cell_iterator, Point<2>>
  StressRecovery::locate(const double r, const double z, const std::string &who) const
  {
    if (!(r >= 0) || !(z >= 0) || !std::isfinite(r) || !std::isfinite(z))
      throw std::invalid_argument(who + ": the point " + point_text(r, z) +
                                  " must have r >= 0 and z >= 0 (z into the material)");
    const Point<2> x = fit.map.mesh_point(Point<2>(r, z));
    auto           found = GridTools::find_active_cell_around_point(*fit.cache, x);
    if (found.first.state() != IteratorState::valid)
      throw std::invalid_argument(who + ": the point " + point_text(r, z) +
                                  " lies outside the meshed body (the truncation at max(r, z) = L)");
    const DoFHandler<2>::active_cell_iterator cell(&fit.dof_handler.get_triangulation(), found.first->level(),
                                                  found.first->index(), &fit.dof_handler);
    return {cell, GeometryInfo<2>::project_to_unit_cell(found.second)};
  }



  StressValue StressRecovery::at(const double r, const double z) const
  {
    if (fit.over_modulus && !(z > 0))
      throw std::invalid_argument("StressRecovery::at: the point " + point_text(r, z) +
                                  " lies on a stiff surface (E infinite at z = 0), where the skin's stresses are "
                                  "infinite; valid: z > 0");
    const auto [cell, unit] = locate(r, z, "StressRecovery::at");
    const DoFHandler<2>::active_cell_iterator scalar_cell(&fit.dof_handler.get_triangulation(), cell->level(),
                                                         cell->index(), &fit.scalar_dofs);
    std::vector<types::global_dof_index> indices(fit.scalar_fe.n_dofs_per_cell());
    scalar_cell->get_dof_indices(indices);
    double c[4] = {0, 0, 0, 0};
    for (unsigned int i = 0; i < indices.size(); ++i)
      {
        const double phi = fit.scalar_fe.shape_value(i, unit);
        for (unsigned int k = 0; k < 4; ++k)
          c[k] += fields[k][indices[i]] * phi;
      }
    const double E = fit.over_modulus ? fit.material.modulus->value(z) : 1.0;
    return {E * c[0], E * c[1], E * c[2], E * c[3]};
  }
} // namespace gradcontact::fem
