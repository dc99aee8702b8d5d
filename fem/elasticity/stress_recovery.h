// The stresses of an axisymmetric FE solution, recovered as continuous fields.
//
// Stress. At a point of a cell, from the displacement gradient in the mesh coordinates (r, zeta) and the surface map
// (fem/modulus/surface_map.h; the identity without one), du/dz = g_zeta / Phi_zeta and du/dr = g_r - shift g_zeta:
//   eps_rr = d u_r / dr,  eps_zz = d u_z / dz,  eps_tt = u_r / r (d u_r / dr on the axis),  gamma_rz = d u_r / dz + d u_z / dr,
//   sigma = lambda(z) tr eps I + 2 mu(z) eps,  sigma_rz = mu(z) gamma_rz,
// with the Lame parameters of the pointwise modulus (fem/bodies/axisymmetric_solver.h). In the mixed formulation
// lambda tr eps is the pressure unknown q (q = S q_hat, or E(z) q_hat on a stiff surface;
// fem/elasticity/graded_elasticity.h), which stays bounded as nu -> 1/2 where lambda tr eps is 0 times infinity.
// Tension positive; z into the material, so sigma_rz is the shear on a plane z = const in the +r direction
// exerted by the material below on the material above. Under the map the soft surface layer of E ~ z^s, s > 0,
// has eps_zz ~ zeta^-gamma and E ~ zeta^gamma (gamma = s / (1 - s)): their product, the stress, is a regular
// function of the mesh coordinates, which is what makes the recovery below converge there.
//
// Recovery. Cell by cell the stress is a discontinuous function: its jumps across faces are of the order of the
// discretisation error, and its values at a point on a face depend on the cell asked. The recovered field is the
// weighted least-squares fit of the cell stresses by the continuous elements FE_Q(p) of the displacement's degree,
// the global smoothing of Hinton & Campbell (Int. J. Numer. Methods Eng. 8 (1974) 461):
//   find s_c in Q_p:  \int s_c v r dr dzeta = \int sigma_c v r dr dzeta  for all v in Q_p,   c = rr, zz, tt, rz,
// in the mesh coordinates (the weight of the meridian plane without the map's Jacobian, which vanishes at a soft
// surface: every cell's stresses then weigh by the mesh's cell size, not by the physical one). The mass matrix is
// well conditioned after its diagonal scaling on any graded mesh, but its entries span the cells' range of sizes,
// so it is factorised (UMFPACK) rather than iterated to a residual that the large cells dominate. Where the exact
// stress is smooth the fit converges at the order of the displacement gradient; near a singular edge it spreads
// that cell's error over a few cells, no further.
// On a stiff surface (E ~ z^s, s < 0) the skin carries radial and hoop stresses that grow like z^s toward the
// surface, which no polynomial follows, and whose fit (not even square integrable from s = -1/2 on) would spread
// that layer's error into the body. There the fitted fields are sigma / E(z), linear combinations of the strains,
// which stay bounded and smooth at a stiff surface (as the mixed formulation's unknown q / E,
// fem/elasticity/graded_elasticity.h), and a stress at a point is E(z) times the fitted value: the z^s growth is
// then exact, and at z = 0 the stress is infinite, which at() refuses.
#ifndef GRADCONTACT_FEM_STRESS_RECOVERY_H
#define GRADCONTACT_FEM_STRESS_RECOVERY_H

#include <fem/modulus/modulus.h>
#include <fem/modulus/surface_map.h>

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>

namespace gradcontact::fem
{
  /// Cylindrical stress components [Pa], tension positive, z into the material.
  struct StressValue
  {
    double rr = 0, zz = 0, tt = 0, rz = 0;
  };

  /// The load-independent part of the recovery on one mesh: the scalar space Q_p, its r-weighted mass matrix
  /// factorised, and the cache that locates points. A solver keeps it, so that each further solution's recovery
  /// assembles and back-substitutes its right-hand sides only. Keeps references to the DoF handler and the mapping,
  /// which must outlive it.
  class StressFit
  {
  public:
    /// `map`: the surface map of the solve; `contact_radius`: the mesh's a (the mixed pressure's scale S = E(a)).
    StressFit(const dealii::DoFHandler<2> &dof_handler, const dealii::Mapping<2> &mapping, const Material &material,
              const SurfaceMap<2> &map, double contact_radius);
    ~StressFit();

    /// The memory of the mass matrix and its sparsity (UMFPACK's factors, of the scalar space's size, not counted).
    std::size_t bytes() const;

  private:
    friend class StressRecovery;
    const dealii::DoFHandler<2> &dof_handler;
    const dealii::Mapping<2>    &mapping;
    const Material               material;
    const SurfaceMap<2>          map;
    const bool                   mixed;
    const bool                   weighted_pressure; ///< q = E(z) q_hat (stiff surface), else q = S q_hat
    const bool                   over_modulus;      ///< the fields are sigma / E(z) (stiff surface)
    const double                 pressure_scale;    ///< S
    const double                 lambda_factor, mu_factor; ///< lambda / E, mu / E

    dealii::FE_Q<2>                   scalar_fe;
    dealii::DoFHandler<2>             scalar_dofs;
    dealii::AffineConstraints<double> scalar_constraints;
    struct Factorised;
    std::unique_ptr<Factorised>                  mass; ///< M of the header, factorised
    std::unique_ptr<dealii::GridTools::Cache<2>> cache;
  };

  /// The stress of an axisymmetric solution u (as solved: the mixed formulation's pressure in its solved units) and
  /// its recovered fields (the header), on the fit of its mesh, which must outlive it.
  class StressRecovery
  {
  public:
    StressRecovery(const StressFit &fit, const dealii::Vector<double> &u);

    /// The recovered stress at the physical point (r, z), r >= 0, z >= 0 (z > 0 on a stiff surface), inside the meshed
    /// body. Throws std::invalid_argument naming the point when it is not.
    StressValue at(double r, double z) const;

    /// The fitted fields, component c in (rr, zz, tt, rz), on dofs() (for output): the stresses, or on a stiff
    /// surface the stresses over E(z) (header).
    const dealii::Vector<double> &field(unsigned int c) const { return fields[c]; }
    const dealii::DoFHandler<2> &dofs() const { return fit.scalar_dofs; }
    /// The names of the fitted fields: "sigma_rr" and so on, "sigma_rr_over_E" on a stiff surface.
    std::string name(unsigned int c) const;

  private:
    /// The stress at mesh point x of `cell` from the solution's values and gradients there.
    StressValue from_gradients(const dealii::Point<2> &x, const std::array<double, 2> &u_value,
                               const std::array<dealii::Tensor<1, 2>, 2> &grad, double q_hat) const;
    void        project(const dealii::Vector<double> &u);
    /// The cell (of the displacement's DoF handler) around the physical point and the point's reference
    /// coordinates; `who` names the caller in the error.
    std::pair<dealii::DoFHandler<2>::active_cell_iterator, dealii::Point<2>> locate(double r, double z,
                                                                                   const std::string &who) const;

    const StressFit                      &fit;
    std::array<dealii::Vector<double>, 4> fields;
  };
} // namespace gradcontact::fem

#endif
