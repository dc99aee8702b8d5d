#include <fem/grid/discretization.h>
#include <fem/base/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  namespace
  {
    constexpr unsigned int max_degree = 8;
  }



  void DiscretizationParameters::validate() const
  {
    if (degree < 1 || degree > max_degree)
      fail("DiscretizationParameters", "degree", degree, "[1, 8]");
    if (extra_quadrature_points > 6)
      fail("DiscretizationParameters", "extra_quadrature_points", extra_quadrature_points, "[0, 6]");
    if (discontinuity_subdivisions < 1 || discontinuity_subdivisions > 64)
      fail("DiscretizationParameters", "discontinuity_subdivisions", discontinuity_subdivisions,
           "[1, 64]");
    if (formulation != Formulation::displacement && formulation != Formulation::mixed &&
        formulation != Formulation::automatic)
      fail("DiscretizationParameters", "formulation", static_cast<int>(formulation),
           "{displacement, mixed, automatic}");
    if (formulation == Formulation::mixed && degree < 2)
      fail("DiscretizationParameters (mixed formulation)", "degree", degree,
           "[2, 8] (the pressure space is FE_Q(degree - 1))");
    if (far_field != FarField::clamped && far_field != FarField::condensed)
      fail("DiscretizationParameters", "far_field", static_cast<int>(far_field), "{clamped, condensed}");
    surface_map.validate();
  }



  Formulation resolve_formulation(const DiscretizationParameters &discretization, const double nu)
  {
    Formulation f = discretization.formulation;
    if (f == Formulation::automatic)
      f = (nu >= automatic_mixed_threshold) ? Formulation::mixed : Formulation::displacement;
    if (f == Formulation::mixed && discretization.degree < 2)
      fail("DiscretizationParameters (mixed formulation, nu = " + std::to_string(nu) + ")", "degree",
           discretization.degree, "[2, 8] (the pressure space is FE_Q(degree - 1))");
    return f;
  }



  void require_displacement_formulation(const DiscretizationParameters &discretization, const double nu,
                                        const std::string &where)
  {
    if (resolve_formulation(discretization, nu) == Formulation::mixed)
      {
        std::ostringstream msg;
        msg << where << ": not supported with the mixed formulation (DiscretizationParameters::formulation = "
            << (discretization.formulation == Formulation::mixed ? "mixed" : "automatic") << ", nu = " << nu
            << "); use Formulation::displacement with nu < 0.5";
        throw std::invalid_argument(msg.str());
      }
  }



  Settings recommended_settings(const double contact_radius, const double s, const double force_tolerance)
  {
    if (!(force_tolerance > 0 && force_tolerance < 1))
      fail("recommended_settings", "force_tolerance", force_tolerance, "(0, 1)");
    // The threshold between the degree-3 and degree-4 settings: the force error that degree 3 on its mesh
    // reaches over -0.5 <= s <= 0.5 (reports/benchmarks/fe_work_precision.md of `./vv bench`).
    constexpr double degree_3_limit = 1e-6;
    // Degree 2 on the same mesh (`build/cases/tools/studies/fem_study p=2`, flat punch / paraboloid / cone / power law
    // n = 4) keeps the force well inside 2e-4 for -0.9 <= s <= 0.5 at a fraction of degree 3's time; beyond
    // s = 0.5 the u_z ~ z^{1-s} surface layer takes it out of that bound, so larger s, and the unchecked
    // s < -0.9, keep degree 3. Asked for 2e-4 or more, a case need not pay for 1e-6.
    constexpr double degree_2_limit = 2e-4, degree_2_min_exponent = -0.9, degree_2_max_exponent = 0.5;
    Settings settings;
    settings.mesh = recommended_mesh_parameters(contact_radius, s, std::min(force_tolerance / 10, 1e-8));
    if (force_tolerance >= degree_2_limit && s >= degree_2_min_exponent && s <= degree_2_max_exponent)
      settings.discretization.degree = 2;
    else if (force_tolerance < degree_3_limit)
      {
        settings.discretization.degree = 4;
        settings.mesh.h_edge           = 1e-6;
        settings.mesh.h_far            = 4.0;
        settings.mesh.ring_growth      = 1.3;
        // No halvings of the cells just outside the contact: the u_z ~ z^{1-k} layer they resolve lies under
        // the loaded surface, so outside it they double the DoFs for k > 0 without changing the force error.
        settings.mesh.halving_radius = 1.0;
      }
    return settings;
  }



  bool surface_map_applies(const ModulusField &modulus)
  {
    const double s = modulus.surface_exponent();
    return s > 0 && s <= 0.95 && modulus.discontinuities().empty();
  }



  bool use_surface_map(Settings &settings, const ModulusField &modulus)
  {
    if (!surface_map_applies(modulus))
      return false;
    const double s = modulus.surface_exponent();
    settings.discretization.surface_map.enabled = true;
    settings.mesh.surface_layer_thickness       = 1.0;
    // The map pulls the truncation boundary in (fem/modulus/surface_map.h): widen L so that its image is as far.
    const double alpha = settings.discretization.surface_map.scale != 0 ? settings.discretization.surface_map.scale :
                                                                          SurfaceMap<2>::automatic_scale(s);
    settings.mesh.far_field_size =
      std::min(1e16, settings.mesh.far_field_size * SurfaceMap<2>::far_field_contraction(s, alpha));
    return true;
  }

  bool power_law_of_depth(const ModulusField &modulus)
  {
    if (!modulus.discontinuities().empty() || modulus.deep_exponent() != modulus.surface_exponent())
      return false;
    const double factor = std::pow(10.0, modulus.surface_exponent());
    for (double z = 1e-12; z <= 1e6; z *= 10)
      {
        const double E = modulus.value(z), E10 = modulus.value(10 * z);
        if (!(E > 0 && std::isfinite(E10) && std::abs(E10 / (factor * E) - 1) <= 1e-12))
          return false;
      }
    return true;
  }



  bool use_condensed_far_field(Settings &settings, const Material &material, const double far_field_size)
  {
    if (!material.modulus || !power_law_of_depth(*material.modulus) || settings.discretization.surface_map.enabled)
      return false;
    const double two_rings = settings.mesh.near_field_size * settings.mesh.ring_growth * (1 + 1e-9);
    if (!(far_field_size > two_rings && far_field_size <= 1e16))
      fail("use_condensed_far_field", "far_field_size", far_field_size,
           "(" + std::to_string(two_rings) + ", 1e16] (L / a > near_field_size ring_growth: two rings at least)");
    settings.discretization.far_field = FarField::condensed;
    settings.mesh.far_field_size      = far_field_size;
    return true;
  }



  void require_clamped_far_field(const DiscretizationParameters &discretization, const std::string &where)
  {
    if (discretization.far_field == FarField::condensed)
      throw std::invalid_argument(where +
                                  ": DiscretizationParameters::far_field = condensed is not supported (the axisymmetric "
                                  "and mode-1 solvers' only, on the meshes of fem/grid/mesh.h); use FarField::clamped with its "
                                  "L / a");
  }



  Settings recommended_settings(const double contact_radius, const ModulusField &modulus, const double force_tolerance)
  {
    // A finite surface modulus E0 ((z + z0)/c0)^k: the power law's mesh with surface cells of z0/4, so that E
    // varies by a bounded factor in each (plain Gauss: E is regular at z = 0), but not thinner than 1e-10 a
    // (k > 0) or 2e-6 a (k < 0, where thinner cells under the stiff surface make the system ill-conditioned
    // and the energy check, energy_mismatch_tolerance, flags the solve).
    if (const auto *shifted = dynamic_cast<const ShiftedPowerLawModulus *>(&modulus))
      {
        Settings settings = recommended_settings(contact_radius, shifted->k, force_tolerance);
        settings.mesh.surface_layer_thickness =
          std::clamp(shifted->z0 / (4 * contact_radius), shifted->k < 0 ? 2e-6 : 1e-10, 1.);
        return settings;
      }
    // The error-function grading: homogeneous at both ends (s = 0), surface cells of w/4 (not thinner than
    // 1e-8 a) over the whole near field: outside the contact the skin carries in-plane stress, and halvings only
    // under r <= 1.05 a leave the thin-layer coefficient of a flat punch several percent off (w = 1e-3..1e-4 a;
    // test "An error-function grading with w << a*").
    if (const auto *erf = dynamic_cast<const ErrorFunctionModulus *>(&modulus))
      {
        Settings settings = recommended_settings(contact_radius, 0.0, force_tolerance);
        settings.mesh.surface_layer_thickness = std::clamp(erf->width / (4 * contact_radius), 1e-8, 1.);
        settings.mesh.halving_radius          = settings.mesh.near_field_size;
        return settings;
      }
    Settings settings = recommended_settings(contact_radius, modulus.surface_exponent(), force_tolerance);
    // The truncation error C (a/L)^(1 + s) is set by the exponent far below the surface, not at it: layers
    // that end in a power law of k < 0 need the L/a of k, since that of s = 0 leaves a truncation error far
    // above the force tolerance.
    if (modulus.deep_exponent() != modulus.surface_exponent())
      settings.mesh.far_field_size =
        recommended_settings(contact_radius, modulus.deep_exponent(), force_tolerance).mesh.far_field_size;
    return settings;
  }



  EnergyCheck check_energy(const double energy, const double work, const double min_surface_cell,
                           const std::string &details, const double magnitude)
  {
    EnergyCheck check;
    if (energy == 0 && work == 0)
      return check; // no load (a profile that is flat where it touches): the zero solution, exactly
    check.mismatch = std::abs(energy - work) / std::abs(energy);
    // The rounding of two sums of products, with a margin for their length (the rows of a degree-4 cell couple
    // about a hundred DoFs): a mismatch below it says nothing about the solve.
    constexpr double rounding_margin = 16 * std::numeric_limits<double>::epsilon();
    const double     tolerance = std::max(energy_mismatch_tolerance, rounding_margin * magnitude / std::abs(energy));
    if (!(check.mismatch <= tolerance))
      {
        std::ostringstream msg;
        msg << "unreliable solve: energy mismatch " << check.mismatch << " > " << tolerance
            << " (ill-conditioned: surface cells " << min_surface_cell << " a thin"
            << (details.empty() ? "" : ", " + details)
            << "; increase MeshParameters::surface_layer_thickness); ";
        check.reliable = false;
        check.message  = msg.str();
      }
    return check;
  }

  void RunReport::start(const Timings &setup, const dealii::types::global_dof_index dofs, const unsigned int cells,
                        const MeshInfo &info)
  {
    time    = setup;
    n_dofs  = dofs;
    n_cells = cells;
    mesh    = info;
  }

  void RunReport::record(const EnergyCheck &check)
  {
    energy_mismatch = check.mismatch;
    reliable        = check.reliable;
    message += check.message;
  }
} // namespace gradcontact::fem
