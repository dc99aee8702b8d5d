#include "model/analytic_reference.h"

#include <analytic/batch.h>

namespace gradcontact::cases
{
  namespace
  {
    using Type = LoadParameters::Type;

    // The case of the scene's load in each problem; the cone of an adhesive scene is the power law n = 1.
    void set_case(batch::Request &q, const Scene &s, const AnalyticReference::Problem problem)
    {
      const LoadParameters &l = s.load;
      const bool adhesive = problem == AnalyticReference::Problem::adhesive;
      switch (l.type)
        {
          case Type::flat_punch:
            q.case_name = adhesive ? "jkr_flat_punch" : "flat_punch";
            q.a = l.a;
            if (!adhesive)
              q.d = l.depth;
            break;
          case Type::paraboloid:
            q.case_name = adhesive ? "jkr_paraboloid" : "paraboloid";
            q.geometry.R = l.R;
            break;
          case Type::cone:
            q.case_name = adhesive ? "jkr_power_law" : "cone";
            if (adhesive)
              {
                q.geometry.n = 1.;
                q.geometry.A = l.tan_theta;
              }
            else
              q.geometry.tan_theta = l.tan_theta;
            break;
          case Type::power_law:
            q.case_name = adhesive ? "jkr_power_law" : "power_law";
            q.geometry.n = l.n;
            q.geometry.A = l.A;
            break;
          case Type::concave_punch:
            q.case_name = adhesive ? "jkr_concave" : "concave_paraboloid";
            q.geometry.h0 = l.h0;
            q.a = l.a;
            if (!adhesive)
              q.d0 = l.depth;
            else if (s.adhesion.tensile_strength > 0.)
              q.sigma_th = s.adhesion.tensile_strength;
            break;
          case Type::constant_pressure:
            q.case_name = adhesive ? "optimal_profile" : "constant_pressure";
            q.a = l.a;
            if (adhesive)
              q.sigma_th = s.adhesion.tensile_strength;
            else
              q.geometry.p0 = l.p0;
            break;
        }
      if (adhesive && l.type != Type::constant_pressure)
        q.dgamma = s.adhesion.work_of_adhesion;
    }

    bool curved(const LoadParameters &l)
    {
      return l.type == Type::paraboloid || l.type == Type::cone || l.type == Type::power_law;
    }
  } // namespace

  namespace input
  {
    Inputs r(const double r) { return [r](batch::Request &q) { q.r = r; }; }
    Inputs a(const double a) { return [a](batch::Request &q) { q.a = a; }; }
    Inputs a_r(const double a, const double r) { return both(input::a(a), input::r(r)); }
    Inputs control(const Control control) { return [control](batch::Request &q) { q.control = control; }; }
    Inputs mechanism(const Mechanism mechanism) { return [mechanism](batch::Request &q) { q.mechanism = mechanism; }; }
    Inputs both(Inputs first, Inputs second)
    {
      return [first, second](batch::Request &q) {
        if (first)
          first(q);
        if (second)
          second(q);
      };
    }
  } // namespace input

  AnalyticReference::AnalyticReference(const Scene &s, const batch::Method method, const Problem problem)
  {
    const MaterialParameters &m = s.material;
    base.material = GradedHalfSpace{m.E0, m.c0, m.k, m.nu};
    idealised_material = m.modulus != MaterialParameters::Modulus::power_law;
    // An elastic indenter: the second body of 9.4 where the chapter covers the pairing, else the rigid indenter.
    const IndenterParameters &indenter = s.indenter;
    if (indenter.elasticity != IndenterParameters::Elasticity::rigid && indenter.covered_by_9_4(m.k))
      base.material2 = GradedHalfSpace{
        indenter.E, m.c0, indenter.elasticity == IndenterParameters::Elasticity::graded ? m.k : 0., indenter.nu};
    idealised_indenter = !indenter.covered_by_9_4(m.k);
    idealised_surface  = frictional_loading(s);
    idealised_adhesion = s.adhesion.law != AdhesionParameters::Law::jkr;
    base.method = method;
    if (problem == Problem::tangential)
      {
        base.a = s.load.a;
        base.geometry.R = s.load.R;
        base.mu = s.friction.coefficient;
        return;
      }
    set_case(base, s, problem);
    const LoadParameters &l = s.load;
    if (problem != Problem::normal || !curved(l))
      return;
    // The reference state is the one the load prescribes: a given, or a(d), or a(F).
    if (l.control == LoadParameters::Control::contact_radius)
      {
        base.a = l.a;
        return;
      }
    batch::Request q = base;
    q.quantity = "contact_radius";
    (l.control == LoadParameters::Control::depth ? q.d : q.F) =
      l.control == LoadParameters::Control::depth ? l.depth : l.force;
    base.a = batch::evaluate(q);
  }

  double AnalyticReference::get(const std::string &quantity, const Inputs &inputs) const
  {
    return get(base.case_name, quantity, inputs);
  }

  double AnalyticReference::at(const std::string &quantity, const double r) const
  {
    return get(quantity, [r](batch::Request &q) { q.r = r; });
  }

  double AnalyticReference::get(const std::string &case_name, const std::string &quantity, const Inputs &inputs) const
  {
    batch::Request q = base;
    q.case_name = case_name;
    q.quantity = quantity;
    if (inputs)
      inputs(q);
    return batch::evaluate(q);
  }

  double AnalyticReference::radius() const { return base.a.value_or(0.); }

  std::string AnalyticReference::label() const
  {
    const std::string method = base.method == batch::Method::closed_form ? "closed form" : "numerical MDR";
    return method + (idealised_material ? " (power-law idealisation E0, c0, k)" : "") +
           (idealised_indenter ? " (rigid-indenter idealisation)" : "") +
           (idealised_surface ? " (frictionless idealisation)" : "") +
           (idealised_adhesion ? " (JKR idealisation)" : "");
  }
} // namespace gradcontact::cases
