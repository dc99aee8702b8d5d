// gradcontact/analytic: a request for any closed form of chapter 9 or its numerical-MDR twin, as a
// value (what code builds) and as JSON (what `gradcontact eval` reads); the vocabulary, units and sign
// conventions are in analytic/README.md. batch.h evaluates it.
#ifndef GRADCONTACT_ANALYTIC_REQUEST_H
#define GRADCONTACT_ANALYTIC_REQUEST_H

#include <analytic/material.h>
#include <analytic/states.h>

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>

namespace gradcontact::batch
{
  enum class Method
  {
    closed_form,  ///< the chapter's closed form
    numerical_mdr ///< the MDR integrals of the case's profile (mdr.h, mdr_contact.h)
  };

  /// The geometry of a case; a case reads the entries it needs (analytic/README.md).
  struct Geometry
  {
    std::optional<double> R, tan_theta, n, A, h0, p0;
  };

  /// One request: a case, a quantity and the inputs the pair needs; an input it needs and does not
  /// find is a DomainError naming it.
  struct Request
  {
    std::string case_name; ///< flat_punch, cone, paraboloid, power_law, ... (analytic/README.md)
    std::string quantity;  ///< force, depth, pressure, ...
    Method method = Method::closed_form;
    std::optional<GradedHalfSpace> material;
    std::optional<GradedHalfSpace> material2; ///< a second graded body (9.4); none: a rigid indenter
    Geometry geometry;
    std::optional<double> a, r, d, F, d0, dgamma, sigma_th, mu, c, Fx, FA, u0, a_lo, a_hi;
    /// The depth of a stress below the surface (quantity stress).
    std::optional<double> z;
    /// The stress component of quantity stress: rr, zz, tt (hoop), rz, principal_max, principal_min, von_mises,
    /// max_shear.
    std::optional<std::string> component;
    /// The adhesive's range instead of its stress (maugis_dugdale only; parse converts either into sigma_th):
    /// the Dugdale range h0, sigma_0 = dgamma / h0, or the Lennard-Jones equilibrium spacing z0, sigma_0 =
    /// 16 dgamma / (9 sqrt(3) z0), the largest stress of that law (Maugis, J. Colloid Interface Sci. 150 (1992)
    /// 243-269), which makes lambda = 1.157 mu with Tabor's mu = (R dgamma^2 / (E*^2 z0^3))^(1/3).
    std::optional<double> h0, z0;
    std::optional<Control> control;
    std::optional<Branch> branch;
    std::optional<Mechanism> mechanism; ///< none: Mechanism::governing
  };

  /// The Request of a JSON object; DomainError for an unknown key, a mistyped or missing entry.
  Request parse(const nlohmann::json &object);
  /// The same from one line of text (DomainError also for invalid JSON).
  Request parse(const std::string &line);
  /// The request as a JSON object, with the keys of analytic/README.md (for messages and files).
  nlohmann::json to_json(const Request &request);

  /// "closed_form" or "numerical_mdr".
  const char *method_name(Method method);
} // namespace gradcontact::batch

#endif
