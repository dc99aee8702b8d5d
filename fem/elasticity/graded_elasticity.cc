#include <fem/base/boundary_ids.h>
#include <fem/base/gauss_jacobi.h>
#include <fem/elasticity/graded_elasticity.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    const UpdateFlags cell_flags =
      update_values | update_gradients | update_quadrature_points | update_JxW_values;

    unsigned int n_points(const DiscretizationParameters &d)
    {
      return d.degree + d.extra_quadrature_points;
    }
  } // namespace



  template <int dim>
  GradedCellRules<dim>::GradedCellRules(const Material &material, const FESystem<dim> &fe,
                                        const Mapping<dim> &mapping, const DiscretizationParameters &discretization,
                                        const bool inverse_rules, const double map_gamma)
    : s(material.modulus->surface_exponent())
    , jumps(material.modulus->discontinuities())
    , map_rules(map_gamma != 0.0)
  {
    const unsigned int n_q = n_points(discretization);
    regular    = std::make_unique<FEValues<dim>>(mapping, fe, QGauss<dim>(n_q), cell_flags);
    subdivided = std::make_unique<FEValues<dim>>(
      mapping, fe, QIterated<dim>(QGauss<1>(n_q), discretization.discontinuity_subdivisions), cell_flags);
    if constexpr (dim == 2)
      if (s != 0.0)
        for (unsigned int v = 0; v < 4; ++v)
          corner[v] = std::make_unique<FEValues<dim>>(mapping, fe, surface_corner_quadrature(n_q, s, v), cell_flags);
    for (unsigned int f = 0; f < 2 * dim; ++f)
      surface[f] = std::make_unique<FEValues<dim>>(
        mapping, fe, surface_cell_quadrature<dim>(n_q, s, f, distance[f]), cell_flags);
    // 1/E ~ z^{-s}: Gauss-Jacobi with exponent -s (needs s < 1; at s = 1, the Gibson medium, nu = 1/2
    // and no integrand carries 1/E).
    if (inverse_rules && s != 0.0)
      for (unsigned int f = 0; f < 2 * dim; ++f)
        surface_inverse[f] = std::make_unique<FEValues<dim>>(
          mapping, fe, surface_cell_quadrature<dim>(n_q, -s, f, distance_inverse[f]), cell_flags);
    if (map_rules)
      for (unsigned int part = 0; part < 2; ++part)
        for (unsigned int f = 0; f < 2 * dim; ++f)
          surface_mapped[part][f] = std::make_unique<FEValues<dim>>(
            mapping, fe, surface_cell_quadrature<dim>(n_q, (part + 1) * map_gamma, f, distance_mapped[part][f]),
            cell_flags);
  }



  template <int dim>
  typename GradedCellRules<dim>::Choice
  GradedCellRules<dim>::select(const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    Choice choice{regular.get(), nullptr, false, numbers::invalid_unsigned_int};
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() && boundary_id::is_surface(cell->face(f)->boundary_id()))
        choice.surface_face = f;
    double       z_min = std::numeric_limits<double>::max(), z_max = -z_min;
    unsigned int lowest = 0;
    for (const unsigned int v : cell->vertex_indices())
      {
        if (cell->vertex(v)[dim - 1] < z_min)
          lowest = v;
        z_min = std::min(z_min, cell->vertex(v)[dim - 1]);
        z_max = std::max(z_max, cell->vertex(v)[dim - 1]);
      }
    const bool straddles =
      std::any_of(jumps.begin(), jumps.end(), [&](const double z) { return z > z_min && z < z_max; });
    // A surface corner: z = 0 at a vertex of the cell, no face on the surface (Choice::subdivide).
    const bool at_corner = s != 0.0 && choice.surface_face == numbers::invalid_unsigned_int &&
                        z_min <= 1e-12 * (z_max - z_min);
    choice.subdivide = straddles || at_corner;

    // A jump inside the cell wins over the surface rule (QIterated resolves the jump; E is bounded
    // away from the surface there); a surface corner has no face rule, and takes the rule collapsed onto its
    // vertex in 2D, QIterated in 3D (its edge on z = 0 would need the collapse along a line) and under the
    // surface map (whose integrands carry powers of the mapped depth, not z^s).
    if (at_corner && !straddles && corner[0] && !map_rules)
      choice.values = corner[lowest].get();
    else if (choice.subdivide)
      choice.values = subdivided.get();
    else if (choice.surface_face != numbers::invalid_unsigned_int && s != 0.0 && !map_rules)
      {
        choice.values = surface[choice.surface_face].get();
        choice.xi     = &distance[choice.surface_face];
      }
    choice.values->reinit(cell);
    return choice;
  }



  template <int dim>
  FEValues<dim> &GradedCellRules<dim>::plain(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                             const bool subdivide)
  {
    FEValues<dim> &values = subdivide ? *subdivided : *regular;
    values.reinit(cell);
    return values;
  }



  template <int dim>
  FEValues<dim> &GradedCellRules<dim>::inverse(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                               const unsigned int face, const std::vector<double> *&xi)
  {
    Assert(surface_inverse[face], ExcMessage("inverse rules were not built"));
    surface_inverse[face]->reinit(cell);
    xi = &distance_inverse[face];
    return *surface_inverse[face];
  }



  template <int dim>
  FEValues<dim> &GradedCellRules<dim>::mapped(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                              const unsigned int face, const unsigned int part,
                                              const std::vector<double> *&xi)
  {
    Assert(map_rules && part < 2, ExcMessage("surface map rules were not built"));
    surface_mapped[part][face]->reinit(cell);
    xi = &distance_mapped[part][face];
    return *surface_mapped[part][face];
  }



  template class GradedCellRules<2>;
  template class GradedCellRules<3>;



  template <class Strain>
  GradedElasticityCell<Strain>::GradedElasticityCell(const Material &material_, const FESystem<dim> &fe_,
                                                     const Mapping<dim> &mapping,
                                                     const DiscretizationParameters &discretization,
                                                     const double contact_radius, const double h_edge)
    : material(material_)
    , fe(fe_)
    , mixed(fe_.n_components() == Strain::n_displacement_components + 1)
    , inverse_lambda_factor(mixed ? (1 + material_.nu) * (1 - 2 * material_.nu) / material_.nu : 0.0)
    , pressure_scale(mixed ? mixed_pressure_scale(material_, contact_radius) : 1.0)
    , weighted_pressure(mixed && depth_weighted_pressure(material_))
    , map(discretization.surface_map, *material_.modulus, contact_radius, h_edge)
    , rules(material_, fe_, mapping, discretization, mixed && inverse_lambda_factor != 0.0, map.gamma())
    , cell_matrix(fe_.n_dofs_per_cell(), fe_.n_dofs_per_cell())
    , B(fe_.n_dofs_per_cell())
    , B_b(fe_.n_dofs_per_cell())
    , trace(fe_.n_dofs_per_cell())
    , trace_b(fe_.n_dofs_per_cell())
    , psi(fe_.n_dofs_per_cell())
  {}



  template <class Strain>
  const FullMatrix<double> &
  GradedElasticityCell<Strain>::matrix(const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    const typename GradedCellRules<dim>::Choice choice = rules.select(cell);
    cell_matrix                                        = 0;
    if (map.active())
      {
        // Under the map no jump straddles a cell, so choice.values is the Gauss rule (the subdivided one in a
        // surface corner cell), reinit'ed on `cell`; a surface cell adds its three parts with their own rules
        // (fem/modulus/surface_map.h), the zeta^gamma rule serving the mixed blocks too.
        FEValues<dim>             *gamma_rule = nullptr;
        const std::vector<double> *xi_gamma   = nullptr;
        if (choice.surface_face != numbers::invalid_unsigned_int)
          {
            add_part(*choice.values, nullptr, 0.0, Part::zz);
            gamma_rule = &rules.mapped(cell, choice.surface_face, 0, xi_gamma);
            add_part(*gamma_rule, xi_gamma, map.gamma(), Part::mixed);
            const std::vector<double> *xi = nullptr;
            FEValues<dim>             &plane_rule = rules.mapped(cell, choice.surface_face, 1, xi);
            add_part(plane_rule, xi, 2 * map.gamma(), Part::plane);
          }
        else
          add_part(*choice.values, nullptr, 0.0, Part::all);
        if (mixed)
          add_mapped_mixed_blocks(*choice.values, gamma_rule, xi_gamma);
      }
    else
      {
        add_part(*choice.values, choice.xi, rules.surface_exponent(), Part::all);
        if (mixed)
          add_mixed_blocks(cell, choice);
      }
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);
    return cell_matrix;
  }



  template <class Strain>
  void GradedElasticityCell<Strain>::add_part(FEValues<dim> &fe_values, const std::vector<double> *xi,
                                              const double xi_exponent, const Part part)
  {
    const ModulusField &E        = *material.modulus;
    const double        nu       = material.nu;
    const double        c_lambda = nu / ((1 + nu) * (1 - 2 * nu));
    const double        c_mu     = 1 / (2 * (1 + nu));

    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    // The integrand lambda tr X tr Y + 2 mu X_n.Y_n + mu X_s.Y_s of two strain vectors, tr X given.
    const auto product = [](const typename Strain::Vector &X, const double tr_X, const typename Strain::Vector &Y,
                            const double tr_Y, const double lambda, const double mu) {
      const double normal = X[0] * Y[0] + X[1] * Y[1] + X[2] * Y[2];
      double       shear  = X[3] * Y[3];
      for (unsigned int m = 4; m < 3 + Strain::n_shear; ++m)
        shear += X[m] * Y[m];
      return lambda * tr_X * tr_Y + 2 * mu * normal + mu * shear;
    };
    // K_uu. The mixed formulation keeps only 2 mu eps:eps (lambda div u div v is replaced by the q blocks
    // of add_mixed_blocks), and the rows of its q shape functions are zero here.
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const Point<dim> &x = fe_values.quadrature_point(q);
        // The map (the identity without one): the physical depth, dz / dzeta and the tangential shift.
        const typename SurfaceMap<dim>::Value m = map.at(x);
        // With a Gauss-Jacobi rule JxW contains xi^e, so the integrand is divided by it. Unmapped, e = s
        // and E(z)/xi^s is the regular factor (E0 (h(x)/c0)^k for the power law, h the local cell height);
        // mapped, each part's power of zeta is e (fem/modulus/surface_map.h).
        double factor = E.value(m.z);
        if (xi)
          factor /= std::pow((*xi)[q], xi_exponent);
        switch (part)
          {
            case Part::all:
            case Part::plane:
              factor *= m.dz;
              break;
            case Part::zz:
              factor /= m.dz;
              break;
            case Part::mixed:
              break;
          }
        const double lambda = mixed ? 0.0 : c_lambda * factor;
        const double mu     = c_mu * factor;
        const double weight = Strain::weight(x) * fe_values.JxW(q);

        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          strain_parts(fe_values, i, q, m, part == Part::all);
        switch (part)
          {
            case Part::all:
            case Part::plane:
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                for (unsigned int j = 0; j <= i; ++j)
                  cell_matrix(i, j) += product(B[i], trace[i], B[j], trace[j], lambda, mu) * weight;
              break;
            case Part::zz:
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                for (unsigned int j = 0; j <= i; ++j)
                  cell_matrix(i, j) += product(B_b[i], trace_b[i], B_b[j], trace_b[j], lambda, mu) * weight;
              break;
            case Part::mixed:
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                for (unsigned int j = 0; j <= i; ++j)
                  cell_matrix(i, j) += (product(B[i], trace[i], B_b[j], trace_b[j], lambda, mu) +
                                        product(B_b[i], trace_b[i], B[j], trace[j], lambda, mu)) *
                                       weight;
              break;
          }
      }
  }



  template <class Strain>
  void GradedElasticityCell<Strain>::strain_parts(const FEValues<dim> &values, const unsigned int i,
                                                  const unsigned int q, const typename SurfaceMap<dim>::Value &m,
                                                  const bool whole)
  {
    const unsigned int c = fe.system_to_component_index(i).first;
    psi[i]               = (c == Strain::n_displacement_components) ? values.shape_value(i, q) : 0.0;
    if (c >= Strain::n_displacement_components)
      {
        B[i] = B_b[i] = typename Strain::Vector{}; // the pressure q of the mixed formulation
        trace[i] = trace_b[i] = 0.0;
        return;
      }
    const double          r   = values.quadrature_point(q)[0];
    const Tensor<1, dim> &g   = values.shape_grad(i, q);
    const double          g_z = g[dim - 1];
    // B_a: the tangential part of the physical gradient, g_t - shift_t g_zeta (and phi / r); whole: with
    // g_zeta / Phi_zeta in the depth slot, i.e. all of B. B_b: g_zeta in the depth slot (to be divided by
    // Phi_zeta).
    Tensor<1, dim> g_a = g - g_z * m.shift;
    g_a[dim - 1]       = whole ? g_z / m.dz : 0.0;
    B[i]               = Strain::of(c, values.shape_value(i, q), g_a, r);
    trace[i]           = B[i][0] + B[i][1] + B[i][2];
    if (whole)
      return;
    Tensor<1, dim> g_b;
    g_b[dim - 1] = g_z;
    B_b[i]       = Strain::of(c, 0.0, g_b, r);
    trace_b[i]   = B_b[i][0] + B_b[i][1] + B_b[i][2];
  }



  template <class Strain>
  void GradedElasticityCell<Strain>::add_mapped_mixed_blocks(FEValues<dim> &plain, FEValues<dim> *gamma_rule,
                                                             const std::vector<double> *xi)
  {
    // Under the surface map (fem/modulus/surface_map.h) dV = Phi_zeta r dr dzeta and tr B = tr B_a + tr B_b / Phi_zeta:
    //   K_uq = \int (tr B_a Phi_zeta + tr B_b) psi r dr dzeta   (~ zeta^gamma and zeta^0 in a surface cell),
    //   K_qq = -\int psi psi Phi_zeta / lambda r dr dzeta       (~ zeta^0: 1/E ~ zeta^-gamma).
    // Both with q = S q_hat (mixed_pressure_scale). In a surface cell (gamma_rule set) `plain` integrates the
    // zeta^0 terms and gamma_rule the zeta^gamma one; elsewhere `plain` all of them.
    const ModulusField &E             = *material.modulus;
    const unsigned int  dofs_per_cell = fe.n_dofs_per_cell();
    const bool          surface_cell  = gamma_rule != nullptr;
    const double        S             = pressure_scale;
    for (const unsigned int q : plain.quadrature_point_indices())
      {
        const Point<dim>                      &x = plain.quadrature_point(q);
        const typename SurfaceMap<dim>::Value m = map.at(x);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          strain_parts(plain, i, q, m, !surface_cell);
        const double weight = Strain::weight(x) * plain.JxW(q);
        const double qq = (inverse_lambda_factor != 0.0) ? S * S * inverse_lambda_factor * m.dz / E.value(m.z) : 0.0;
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const double t_i = S * (surface_cell ? trace_b[i] : trace[i] * m.dz);
            for (unsigned int j = 0; j <= i; ++j)
              {
                const double t_j = S * (surface_cell ? trace_b[j] : trace[j] * m.dz);
                cell_matrix(i, j) += (t_i * psi[j] + psi[i] * t_j - qq * psi[i] * psi[j]) * weight;
              }
          }
      }
    if (!surface_cell)
      return;
    // The zeta^gamma part of K_uq: tr B_a psi Phi_zeta, the weights containing xi^gamma.
    for (const unsigned int q : gamma_rule->quadrature_point_indices())
      {
        const Point<dim>                      &x = gamma_rule->quadrature_point(q);
        const typename SurfaceMap<dim>::Value m = map.at(x);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          strain_parts(*gamma_rule, i, q, m, false);
        const double weight = S * Strain::weight(x) * gamma_rule->JxW(q) * m.dz / std::pow((*xi)[q], map.gamma());
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            cell_matrix(i, j) += (trace[i] * psi[j] + psi[i] * trace[j]) * weight;
      }
  }



  template <class Strain>
  void GradedElasticityCell<Strain>::add_mixed_blocks(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                                      const typename GradedCellRules<dim>::Choice        &choice)
  {
    const ModulusField &E             = *material.modulus;
    const double        s             = rules.surface_exponent();
    const unsigned int  dofs_per_cell = fe.n_dofs_per_cell();
    const unsigned int  pressure      = Strain::n_displacement_components;
    // Surface cells with E ~ z^s, s != 0: K_qq needs its own rule (Gauss-Jacobi, exponent -s), unless the
    // unknown is q / E, whose blocks both carry E and take K_uu's rule (header).
    const bool singular_qq =
      !weighted_pressure && choice.surface_face != numbers::invalid_unsigned_int && s != 0.0 && !choice.subdivide;
    const bool qq_here = inverse_lambda_factor != 0.0 && !singular_qq;

    // K_uq = \int tr B_i psi_j r and, where 1/E is regular, K_qq = -\int psi_i psi_j / lambda r; weighted, both
    // times E(z) (q = E q_hat) with the cell's rule for E, whose weights contain xi^s where `xi` is set.
    FEValues<dim>             &plain = weighted_pressure ? *choice.values : rules.plain(cell, choice.subdivide);
    const std::vector<double> *xi_e  = weighted_pressure ? choice.xi : nullptr;
    for (const unsigned int q : plain.quadrature_point_indices())
      {
        const Point<dim> &x      = plain.quadrature_point(q);
        const double      r      = x[0];
        double            weight = Strain::weight(x) * plain.JxW(q);
        if (weighted_pressure)
          weight *= E.value(x[dim - 1]) / (xi_e ? std::pow((*xi_e)[q], s) : 1.0);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const unsigned int c   = fe.system_to_component_index(i).first;
            const double       phi = plain.shape_value(i, q);
            if (c < pressure)
              {
                const auto b = Strain::of(c, phi, plain.shape_grad(i, q), r);
                trace[i]     = b[0] + b[1] + b[2]; // div of the shape function
              }
            else
              trace[i] = 0.0;
            psi[i] = (c == pressure) ? phi : 0.0;
          }
        // q = S q_hat (mixed_pressure_scale): K_uq times S, K_qq times S^2; weighted: E / lambda, E in `weight`.
        const double S              = weighted_pressure ? 1.0 : pressure_scale;
        const double inverse_lambda = weighted_pressure ? inverse_lambda_factor :
                                      qq_here           ? S * S * inverse_lambda_factor / E.value(x[dim - 1]) :
                                                          0.0;
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            cell_matrix(i, j) +=
              (S * (trace[i] * psi[j] + psi[i] * trace[j]) - inverse_lambda * psi[i] * psi[j]) * weight;
      }
    if (!(singular_qq && inverse_lambda_factor != 0.0))
      return;

    // K_qq in a surface cell: the weights contain xi^{-s}, so the integrand is multiplied by xi^s:
    // xi^s / E(z) = 1 / (E(z) / xi^s) is the regular factor.
    const std::vector<double> *xi      = nullptr;
    FEValues<dim>             &inverse = rules.inverse(cell, choice.surface_face, xi);
    for (const unsigned int q : inverse.quadrature_point_indices())
      {
        const Point<dim> &x      = inverse.quadrature_point(q);
        const double      factor = pressure_scale * pressure_scale * inverse_lambda_factor * std::pow((*xi)[q], s) /
                              E.value(x[dim - 1]) * Strain::weight(x) * inverse.JxW(q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          psi[i] = (fe.system_to_component_index(i).first == pressure) ? inverse.shape_value(i, q) : 0.0;
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            cell_matrix(i, j) -= factor * psi[i] * psi[j];
      }
  }

  template class GradedElasticityCell<AxisymmetricStrain>;
  template class GradedElasticityCell<Mode1Strain>;
  template class GradedElasticityCell<CartesianStrain>;



  double mixed_pressure_scale(const Material &material, const double contact_radius)
  {
    const double S = material.modulus->value(contact_radius);
    return (S > 0 && std::isfinite(S)) ? S : 1.0;
  }



  bool depth_weighted_pressure(const Material &material)
  {
    return material.modulus && material.modulus->surface_exponent() < 0;
  }



  std::string mixed_pressure_name(const Material &material)
  {
    return depth_weighted_pressure(material) ? "q_over_E" : "q";
  }



  Vector<double> with_physical_pressure(const Vector<double> &u, const DoFHandler<2> &dof_handler,
                                       const FESystem<2> &fe, const Material &material, const double contact_radius)
  {
    Vector<double> fields = u;
    if (fe.n_components() == AxisymmetricStrain::n_displacement_components + 1 && !depth_weighted_pressure(material))
      {
        const double S = mixed_pressure_scale(material, contact_radius);
        for (const auto i : DoFTools::extract_dofs(dof_handler, fe.component_mask(FEValuesExtractors::Scalar(2))))
          fields[i] *= S;
      }
    return fields;
  }



  void make_homogeneous_constraints(const DoFHandler<2> &dof_handler, const Mapping<2> &mapping,
                                    const FESystem<2> &fe, AffineConstraints<double> &constraints,
                                    const bool clamp_far_field)
  {
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    const unsigned int                       n_components = fe.n_components();
    const FEValuesExtractors::Scalar radial(0);
    VectorTools::interpolate_boundary_values(mapping, dof_handler, boundary_id::axis,
                                                     Functions::ZeroFunction<2>(n_components),
                                                     constraints, fe.component_mask(radial));
    // u = 0 on the truncation boundary; the pressure q of the mixed formulation stays free there.
    const FEValuesExtractors::Vector displacement(0);
    if (clamp_far_field)
      VectorTools::interpolate_boundary_values(mapping, dof_handler, boundary_id::far_field,
                                               Functions::ZeroFunction<2>(n_components), constraints,
                                               fe.component_mask(displacement));
    constraints.close();
  }

  CellPressureLoad::CellPressureLoad(const FESystem<2> &fe_, const Mapping<2> &mapping,
                                     const DiscretizationParameters &discretization)
    : fe(fe_)
    , face_values(mapping, fe_, QGauss<1>(n_points(discretization)),
                  update_values | update_quadrature_points | update_JxW_values)
    , cell_rhs(fe_.n_dofs_per_cell())
  {}



  const Vector<double> &CellPressureLoad::vector(const DoFHandler<2>::active_cell_iterator &cell,
                                                 const double p0, bool &loaded)
  {
    cell_rhs = 0;
    loaded   = false;
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id::contact)
        {
          loaded = true;
          face_values.reinit(cell, f);
          for (const unsigned int q : face_values.quadrature_point_indices())
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              if (fe.system_to_component_index(i).first == 1)
                cell_rhs(i) +=
                  p0 * face_values.shape_value(i, q) * face_values.quadrature_point(q)[0] * face_values.JxW(q);
        }
    return cell_rhs;
  }

  Formulation checked_formulation(const Material &material, const DiscretizationParameters &discretization)
  {
    discretization.validate();
    const Formulation f = resolve_formulation(discretization, material.nu);
    material.validate(f == Formulation::mixed);
    return f;
  }

  template <int dim>
  FESystem<dim> displacement_pressure_element(const unsigned int degree, const Formulation formulation)
  {
    if (formulation == Formulation::mixed)
      return FESystem<dim>(FE_Q<dim>(degree), dim, FE_Q<dim>(degree - 1), 1);
    return FESystem<dim>(FE_Q<dim>(degree), dim);
  }

  template FESystem<2> displacement_pressure_element<2>(unsigned int, Formulation);
  template FESystem<3> displacement_pressure_element<3>(unsigned int, Formulation);
} // namespace gradcontact::fem
