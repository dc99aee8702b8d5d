// The far field beyond the truncation boundary, condensed onto it: the infinitely many rings of the
// meridian mesh (fem/grid/mesh.h) as one dense stiffness on the DoFs of max(r, z) = L.
//
// The rings of fem/grid/mesh.h are copies of one polyline P scaled by g: ring j lies between g^{j-1} P and g^j P.
// For E(z) = E0 (z/c0)^s, a ring scaled by lambda has lambda^{1+s} times the stiffness of the original in
// matching DoFs (r dr dz ~ lambda^3, grad^2 ~ lambda^-2, E ~ lambda^s). After static condensation of its
// interior DoFs a ring is a two-port T = [A B; B^T C] between its inner DoFs and its outer ones, and the
// exterior beyond the mesh's last ring (scale sigma = g^{1+s} per ring) condensed onto its outer DoFs is the
// S of
//   S = sigma (A - B (C + S)^{-1} B^T).
// It is found by doubling: a chain of N rings and its copy scaled by sigma^N make a chain of 2N rings (the
// middle port eliminated), and a chain clamped at its far end is the problem truncated at L g^N, whose
// truncation error falls like g^{-N (1 + s)}; the doubling stops once that factor is below 1e-18, so the
// mesh's L only has to hold the near field and two rings (the "cloning" of self-similar rings: Dasgupta,
// J. Appl. Mech. 49 (1982) 136-140).
//
// Nothing is assumed of the modulus or the mesh: the mesh's last two rings are both condensed, the scale is
// the least-squares fit of the outer one onto the inner one, and their relative deviation is measured and
// bounded: a modulus that is no power law of depth at the rings' size (a finite surface modulus, a coating)
// and a surface map that is not yet homogeneous at L are refused with the deviation found.
//
// The mixed formulation's pressure DoFs scale otherwise: K_uq = \int div(v) q r dr dz ~ lambda^2 and
// K_qq = \int q q' / lambda_Lame r dr dz ~ lambda^{3-s}, so a ring scaled by lambda is
// lambda^{1+s} D T D with D = diag(1 on displacement DoFs, mu on pressure DoFs), mu = lambda^{1-s} (the
// pressure of the scaled ring is measured in units lambda^{s-1} times those of the original: q ~ E eps ~
// lambda^{s-1} at equal displacements); mu = lambda where the unknown is q / E (a stiff surface,
// fem/elasticity/graded_elasticity.h). sigma is fitted on the displacement block and mu on the displacement-pressure one;
// the deviation is measured over all of T.
//
// The infinite discrete problem has no truncation error left: the flat punch at k = -0.5 gives the force
// of the mesh clamped at L / a = 1e16 (fem/doc/meshes.md "Far field").
#ifndef GRADCONTACT_FEM_FAR_FIELD_H
#define GRADCONTACT_FEM_FAR_FIELD_H

#include <fem/grid/discretization.h>
#include <fem/grid/mesh.h>

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>

#include <functional>
#include <vector>

namespace gradcontact::fem
{
  /// Relative deviation of the last ring's two-port from the scaled one of the ring before it above which
  /// FarFieldRings::condense refuses: the exterior then is no copy of one ring.
  inline constexpr double self_similarity_tolerance = 1e-7;

  /// The exterior stiffness on the truncation boundary and how it was found.
  struct Exterior
  {
    std::vector<dealii::types::global_dof_index> dofs; ///< the truncation-boundary DoFs S acts on
    dealii::FullMatrix<double>                   stiffness; ///< S (symmetric), in the order of `dofs`
    double       ring_scale      = 0; ///< sigma, the measured ratio of consecutive rings' stiffness
    double       pressure_scale  = 1; ///< mu, the factor of the pressure DoFs per ring (mixed formulation; else 1)
    double       self_similarity = 0; ///< |T_n - sigma T_{n-1}| / |T_n| (Frobenius)
    unsigned int doublings       = 0; ///< chains of 2^doublings rings
    double       chain_error     = 0; ///< the truncation factor sigma^{-N} of the last chain
  };

  /// The last two rings of a meridian mesh and the DoFs of their ports, found by geometry (the cells
  /// whose centre has max(r, z) between L / g^2 and L / g, and between L / g and L).
  class FarFieldRings
  {
  public:
    /// `constraints`: the model's homogeneous constraints *without* the far-field condition: a ring DoF
    /// constrained to zero or to DoFs of its own ring (the axis conditions) is applied in the ring's matrix, one
    /// tied to other rings (a hanging node) is refused. Needs at
    /// least two rings (MeshInfo::n_rings >= 2). `pressure_component`: the mixed formulation's pressure
    /// component of the element (none by default). Throws std::invalid_argument naming what is missing.
    FarFieldRings(const dealii::DoFHandler<2> &dof_handler, const dealii::Mapping<2> &mapping,
                  const dealii::AffineConstraints<double> &constraints, const MeshParameters &mesh,
                  const MeshInfo &info, unsigned int pressure_component = dealii::numbers::invalid_unsigned_int);

    /// The unconstrained DoFs on the truncation boundary (for the sparsity pattern: they couple densely).
    const std::vector<dealii::types::global_dof_index> &boundary_dofs() const { return outer_port[1]; }

    /// The exterior from the cell matrices of `cell_matrix` (e.g. CellStiffness::matrix). Throws
    /// std::runtime_error with the measured deviation when the rings are no scaled copies of each other.
    using CellMatrix = std::function<const dealii::FullMatrix<double> &(
      const typename dealii::DoFHandler<2>::active_cell_iterator &)>;
    Exterior condense(const CellMatrix &cell_matrix) const;

  private:
    /// Ring 0 is the mesh's last but one, ring 1 its last.
    struct Ring
    {
      std::vector<typename dealii::DoFHandler<2>::active_cell_iterator> cells;
      std::vector<dealii::types::global_dof_index>                      interior;
    };
    /// The condensed two-port of ring `i`: rows and columns in the order inner_port[i], outer_port[i].
    dealii::FullMatrix<double> two_port(unsigned int i, const CellMatrix &cell_matrix) const;

    /// Throws std::invalid_argument unless the last ring's outer port is the mesh's free far_field boundary.
    void check_truncation_boundary() const;
    /// The scale sigma of T1 against T0 and, with pressure DoFs, their factor mu per ring (1 without).
    std::pair<double, double> fit_ring_scale(const dealii::FullMatrix<double> &T0,
                                             const dealii::FullMatrix<double> &T1) const;

    const dealii::DoFHandler<2>                        &dof_handler;
    const dealii::AffineConstraints<double>            &constraints;
    /// Per port entry (the same for every port): whether it is a pressure DoF of the mixed formulation.
    std::vector<bool>                                   pressure_entry;
    std::array<Ring, 2>                                  rings;
    /// Port DoFs of each ring, sorted by (component, angle), so that entry j of every port is the same
    /// DoF of the polyline scaled.
    std::array<std::vector<dealii::types::global_dof_index>, 2> inner_port, outer_port;
  };

  /// `rings->condense` over the cell matrices of `cell_integrand` (any class with matrix(cell), e.g. CellStiffness);
  /// an empty Exterior when `rings` is null (the far field clamped).
  template <class CellIntegrand>
  Exterior condense_exterior(const FarFieldRings *rings, CellIntegrand &cell_integrand)
  {
    if (!rings)
      return Exterior();
    return rings->condense(
      [&](const typename dealii::DoFHandler<2>::active_cell_iterator &cell) -> const dealii::FullMatrix<double> & {
        return cell_integrand.matrix(cell);
      });
  }

  /// Copies the exterior's ring scale, self-similarity and doublings into a run's report.
  void record_far_field(const Exterior &exterior, RunReport &report);
} // namespace gradcontact::fem

#endif
