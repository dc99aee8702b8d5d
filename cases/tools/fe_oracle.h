// gradcontact/cases: the FE model as an oracle in the eval vocabulary (`gradcontact eval`, "method": "fe").
//
// A request of analytic/README.md with "method": "fe" and, optionally, "tolerance" (the wanted relative
// error of the force, default 1e-6, in [1e-8, 1e-2]) is answered by the axisymmetric FE model
// (fem/bodies/axisymmetric_solver.h) instead of a closed form: the cases flat_punch (at depth d), paraboloid, cone and
// power_law (at contact radius a, the contact-radius control of the FE model), the quantities force, depth
// (indenters), pressure and displacement (at r) and stress (at r, z > 0: a component of the recovered stress,
// fem/elasticity/stress_recovery.h). The FE keeps the accuracy contract of fem/accuracy/accuracy.h: the
// answer comes from the ladder of uniform refinements that first brings the Richardson estimate within the
// tolerance, and carries that estimate, absolute ("error_estimate") and relative ("relative_error_estimate": to
// |F|, |d|, |w(r)|, for a pressure to the largest |p| sampled with it, for a stress to the largest component
// sampled with it). A stress measure and the largest stress ("max_stress", "max_stress_radius", "max_stress_depth"
// with component von_mises or max_shear; k >= 0 and the indenters only, as on the closed-form side,
// analytic/subsurface.h) are those of model/fe_stress.h, with their estimates. A tolerance the ladder cannot reach is
// a refusal that names the limit (the DoF budget, the far field, an unreliable solve), never a value.
//
// Reuse. Besides c0 the power-law half-space has no length of its own, and c0 enters only through
// E_a = E0 (a/c0)^k: in units of a, the problem of contact radius a is the one of radius 1 on E_a (z/a)^k. Every
// load is linear in its amplitude s (d/a for the flat punch; a/R, tan theta, A a^(n-1) for the profile in units
// of a). So one FE state per (k, nu, tolerance, case, n), solved at radius 1 on E = z^k with unit amplitude,
// answers every request of that kind:
//   F = E_a a^2 s F~,  d = a s d~,  p(r) = E_a s p~(r/a),  w(r) = a s w~(r/a),  sigma(r, z) = E_a s sigma~(r/a, z/a).
// A pressure or displacement at a new r/a is one more run of the same factorised solver (back-substitutions).
#ifndef GRADCONTACT_CASES_FE_ORACLE_H
#define GRADCONTACT_CASES_FE_ORACLE_H

#include "report/result_cache.h"

#include <analytic/request.h>
#include <fem/bodies/axisymmetric_solver.h>

#include <nlohmann/json_fwd.hpp>

#include <istream>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <utility>
#include <string>

namespace gradcontact::cases
{
  class FeOracle
  {
  public:
    struct Answer
    {
      double       value          = 0;
      double       error_estimate = 0;          ///< absolute (header)
      double       relative_error_estimate = 0; ///< relative to the quantity's scale (header)
      unsigned int dofs           = 0;          ///< of the finest level of the ladder
      std::string  formulation;                 ///< "displacement", or "mixed" (nu >= 0.45, fem/doc/model.md)
    };

    FeOracle();
    ~FeOracle();

    /// The answer to one request with "method": "fe" (header). std::invalid_argument (or a DomainError of the
    /// request's parsing) naming the entry when the request is not one the FE answers.
    Answer evaluate(const nlohmann::json &request);

    /// Announces a request that will follow: its pressure or displacement radius, or its stress point, is then
    /// sampled in the same run as the first one of its unit state (a batch costs one run per state and quantity).
    /// Never throws.
    void plan(const nlohmann::json &request);

    /// FE states solved so far (each a ladder of meshes) and requests answered from them.
    unsigned int states_solved() const { return solved; }
    unsigned int requests() const { return answered; }

  private:
    struct UnitState; ///< the unit problem of one (k, nu, tolerance, case, n) on its ladder
    struct Parsed;
    Parsed     parse(const nlohmann::json &request) const;
    /// The point and component of a stress request, or the measure of a largest stress, into `p` (k: the grading,
    /// c: the case); refuses what has no FE answer.
    static void parse_stress(const batch::Request &q, double k, const std::string &c, Parsed &p);
    /// `min_degree`: the least degree of its ladder (0: the contract's own).
    UnitState &unit_state(const std::string &key, double k, double nu, double tolerance, const fem::LoadCase &load,
                          unsigned int min_degree);

    std::map<std::string, std::unique_ptr<UnitState>>          states;
    std::map<std::string, std::map<bool, std::set<double>>>    plans; ///< radii of states not built yet
    std::map<std::string, std::set<std::pair<double, double>>> stress_plans; ///< (r/a, z/a) of states not built yet
    unsigned int                                       solved = 0, answered = 0;
  };

  /// How `gradcontact eval` reads its input.
  enum class EvalReading
  {
    per_line,   ///< each request answered (and the output flushed) as soon as its line is complete: a script
                ///< can write one request and wait for its answer
    whole_input ///< every line read first, so that the FE samples all the pressures and displacements asked of
                ///< one unit state in one ladder run (their estimates then share the largest |p| as scale)
  };

  /// `gradcontact eval`: one answer line per request line, in order; a request with "method": "fe" goes to
  /// `oracle` (its answer adds "error_estimate", "relative_error_estimate", "dofs" and "formulation"), any other to
  /// the closed forms or the numerical MDR (analytic/batch.h). Never throws on a request: an error becomes
  /// {"id", "error"}. Returns the number of errors. With `cache` (read per line only: a batch's pressure estimates
  /// share their scale), an FE answer is kept under its request without "id" and the program's build, so that a
  /// later process answers the same request without solving (cases/report/result_cache.h).
  int evaluate_stream(std::istream &in, std::ostream &out, FeOracle &oracle,
                      EvalReading reading = EvalReading::whole_input, const ResultCache *cache = nullptr);
} // namespace gradcontact::cases

#endif
