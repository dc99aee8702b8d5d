// gradcontact/cases: the FE solves of a normal scene (fe_scene): the disc solver of fem/bodies/axisymmetric_solver.h
// with the contact zone r <= Load/a, the unilateral solver of fem/contact/unilateral_contact.h with the contact set
// found, and the accuracy contract's ladder (fem/accuracy/accuracy.h).
#ifndef GRADCONTACT_CASES_NORMAL_MODEL_H
#define GRADCONTACT_CASES_NORMAL_MODEL_H

#include "model/analytic_reference.h"
#include "model/fe_model.h"

#include <fem/accuracy/accuracy.h>

#include <memory>
#include <vector>

namespace gradcontact::cases
{
  /// fe_model at `refinement` with the meshes of a normal scene: graded toward the axis, where the pressure of a
  /// cone (and of f = A r^n, n < 2) is singular (fem/doc/accuracy-and-cost.md, "What limits the error", cone axis);
  /// for the rigid frictionless disc model with Discretization/surface map, the surface map (its contact edge at the
  /// mesh's; not with the mixed formulation, whose degree-3 force it leaves 10x less accurate than the halvings);
  /// the condensed far field for the disc model.
  FeModel normal_fe_model(const Scene &s, unsigned int refinement);

  /// The disc solve of `model` and the memory of its direct solver's factorisation and matrices (bytes).
  struct DiscSolve
  {
    fem::Result result;
    double      factor_bytes = 0;
  };
  DiscSolve solve_disc(const FeModel &model, const fem::OutputRequest &out);

  /// Load/contact = unilateral: the scene's indenter (Load/type) under force control (Load/force; not for the
  /// concave punch) or depth control, its contact set found on meshes graded toward the edge found.
  fem::UnilateralResult solve_normal_unilateral(const Scene &s, const FeModel &model, const fem::OutputRequest &out);

  /// A unilateral result as the disc solver's result: the contact radius is the outer edge, w(r) the approach of both
  /// surfaces with an elastic indenter (9.4); the message says the friction path's summary, the zones when there
  /// are several and an annulus's inner edge, and the contact is consistent when it is one zone.
  fem::Result as_disc_result(const Scene &s, const FeModel &model, const fem::UnilateralResult &u);

  /// Discretization/accuracy = contract: the ladder at Discretization/force tolerance from level 0 of `model`, its
  /// far field beyond the largest Outputs/displacement radius, graded toward the axis for a cone's tip.
  fem::ContractResult solve_normal_contract(const Scene &s, const FeModel &model);

  /// A panel of the two-solver maps (indenter modulus, friction): the scene at exponent k and Poisson ratio nu
  /// with a rigid indenter under contact-radius control at Load/a, its FE model, the closed forms there and the
  /// unilateral load at their depth.
  struct UnilateralPanel
  {
    Scene                              scene;
    FeModel                            model;
    std::unique_ptr<AnalyticReference> reference;
    fem::UnilateralLoad                load;
  };
  UnilateralPanel unilateral_panel(const Scene &s, double k, double nu);

  /// The friction map's one solver of a panel (the shear operator built once, the near field 1.6 Load/a), its load
  /// in Friction/load steps with p(r) sampled at `pressure_radii` (units of Load/a), the last result and the seconds
  /// of its setup.
  struct FrictionSolver
  {
    std::unique_ptr<fem::UnilateralContactSolver> solver;
    fem::UnilateralLoad                           load;
    fem::OutputRequest                            request;
    fem::UnilateralResult                         r;
    double                                        setup = 0.;
  };
  FrictionSolver friction_solver(const Scene &s, const UnilateralPanel &panel,
                                 const std::vector<double> &pressure_radii);

  /// The elastic-indenter map's one solver of a panel: a homogeneous indenter of the half-space's E0 and Indenter/nu,
  /// whose compliance each ratio E1/E0 rescales (set_indenter_modulus_factor; linear elasticity makes that exact), on
  /// the panel's mesh with the near field `near_field` (m).
  std::unique_ptr<fem::UnilateralContactSolver> elastic_indenter_solver(const Scene &s, const UnilateralPanel &panel,
                                                                        double near_field);
} // namespace gradcontact::cases

#endif
