// The command line of the FE studies (fem_study, mode1_study, cohesive_study, ladder_study, fem_mpi, fem3d):
// key=value arguments, and the mesh and discretisation keys they share, so that a setting means the same in every
// study.
//
//   mesh:            h_edge h_surface h_far g (ring growth) L (far field / a) layer (surface layer / a)
//                    R1 (near field / a) halving_radius axis_refinements edge_refinements global
//   discretisation:  p (degree) extra_q subdiv formulation=displacement|mixed|automatic
//                    map=0|auto|alpha (surface map; L is not widened, fem::use_surface_map does) map_floor (tau / a, 0: h_edge)
//   distributed:     solver=direct|amg tol threshold sweeps
#ifndef GRADCONTACT_CASES_TOOLS_STUDIES_STUDY_ARGUMENTS_H
#define GRADCONTACT_CASES_TOOLS_STUDIES_STUDY_ARGUMENTS_H

#include <fem/grid/discretization.h>
#include <fem/linear_algebra/distributed_linear_solver.h>
#include <fem/grid/mesh.h>
#include <fem/grid/mesh_3d.h>

#include <exception>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace gradcontact::studies
{
  class StudyArguments
  {
  public:
    /// Throws std::invalid_argument "<tool>: argument '...' is not key=value".
    StudyArguments(const int argc, char **argv, const std::string &tool)
      : tool(tool)
    {
      for (int i = 1; i < argc; ++i)
        {
          const std::string s  = argv[i];
          const auto        eq = s.find('=');
          if (eq == std::string::npos)
            throw std::invalid_argument(tool + ": argument '" + s + "' is not key=value");
          values[s.substr(0, eq)] = s.substr(eq + 1);
        }
    }

    /// Names the arguments that no query read (a misspelt key such as h_egde=..., or one of another mode) on
    /// stderr: the run used the defaults for them. Not while an error unwinds (its keys were not all read yet).
    ~StudyArguments()
    {
      if (std::uncaught_exceptions() > 0)
        return;
      std::string unused;
      for (const auto &entry : values)
        if (queried.count(entry.first) == 0)
          unused += " " + entry.first;
      if (!unused.empty())
        std::cerr << tool << ": warning: argument(s) not used in this run:" << unused << '\n';
    }
    StudyArguments(const StudyArguments &)            = delete;
    StudyArguments &operator=(const StudyArguments &) = delete;

    bool has(const std::string &key) const
    {
      queried.insert(key);
      return values.count(key) != 0;
    }

    std::string text(const std::string &key, const std::string &fallback = "") const
    {
      return has(key) ? values.at(key) : fallback;
    }

    /// The number given for `key`, else `fallback`; a value that is no number is an error naming it.
    double num(const std::string &key, const double fallback) const
    {
      if (!has(key))
        return fallback;
      try
        {
          return std::stod(values.at(key));
        }
      catch (const std::exception &)
        {
          throw std::invalid_argument(tool + ": " + key + " = '" + values.at(key) + "' is not a number");
        }
    }

    unsigned int count(const std::string &key, const unsigned int fallback) const
    {
      return static_cast<unsigned int>(num(key, fallback));
    }

    /// Overrides the entries of the 3D mesh (fem/grid/mesh_3d.h) whose keys are given: R0, sectors, L, g3, h_edge, q,
    /// inner, layer, edge, grading, contact_ref, global3.
    void apply(fem::HalfSpaceMesh3DParameters &mesh) const
    {
      mesh.core_radius             = num("R0", mesh.core_radius);
      mesh.sectors                 = count("sectors", mesh.sectors);
      mesh.far_field_size          = num("L", mesh.far_field_size);
      mesh.ring_growth             = num("g3", mesh.ring_growth);
      mesh.h_edge                  = num("h_edge", mesh.h_edge);
      mesh.edge_ratio              = num("q", mesh.edge_ratio);
      mesh.inner_ring_width        = num("inner", mesh.inner_ring_width);
      mesh.surface_layer_thickness = num("layer", mesh.surface_layer_thickness);
      mesh.edge_refinements        = count("edge", mesh.edge_refinements);
      mesh.edge_grading            = num("grading", mesh.edge_grading);
      mesh.contact_refinements     = count("contact_ref", mesh.contact_refinements);
      mesh.global_refinements      = count("global3", mesh.global_refinements);
    }

    /// Overrides the entries of `mesh` whose keys are given (header).
    void apply(fem::MeshParameters &mesh) const
    {
      mesh.h_edge                  = num("h_edge", mesh.h_edge);
      mesh.h_surface               = num("h_surface", mesh.h_surface);
      mesh.h_surface_outer         = num("h_surface_outer", mesh.h_surface_outer);
      mesh.h_far                   = num("h_far", mesh.h_far);
      mesh.ring_growth             = num("g", mesh.ring_growth);
      mesh.far_field_size          = num("L", mesh.far_field_size);
      mesh.surface_layer_thickness = num("layer", mesh.surface_layer_thickness);
      mesh.near_field_size         = num("R1", mesh.near_field_size);
      mesh.halving_radius          = num("halving_radius", mesh.halving_radius);
      mesh.axis_refinements        = count("axis_refinements", mesh.axis_refinements);
      mesh.edge_refinements        = count("edge_refinements", mesh.edge_refinements);
      mesh.global_refinements      = count("global", mesh.global_refinements);
    }

    /// Overrides the entries of `discretization` whose keys are given (header).
    void apply(fem::DiscretizationParameters &discretization) const
    {
      discretization.degree                     = count("p", discretization.degree);
      discretization.extra_quadrature_points    = count("extra_q", discretization.extra_quadrature_points);
      discretization.discontinuity_subdivisions = count("subdiv", discretization.discontinuity_subdivisions);
      if (has("map"))
        {
          // map=0 off, map=auto the automatic scale, map=alpha that scale
          discretization.surface_map.enabled = text("map") != "0";
          discretization.surface_map.scale   = (text("map") == "auto") ? 0.0 : num("map", 0.0);
        }
      discretization.surface_map.floor          = num("map_floor", discretization.surface_map.floor);
      const std::string far_field               = text("far", "clamped");
      if (far_field == "condensed")
        discretization.far_field = fem::FarField::condensed;
      else if (far_field != "clamped")
        throw std::invalid_argument(tool + ": far = '" + far_field + "' outside {clamped, condensed}");
      const std::string formulation             = text("formulation", "displacement");
      if (formulation == "mixed")
        discretization.formulation = fem::Formulation::mixed;
      else if (formulation == "automatic")
        discretization.formulation = fem::Formulation::automatic;
      else if (formulation != "displacement")
        throw std::invalid_argument(tool + ": formulation = '" + formulation +
                                    "' outside {displacement, mixed, automatic}");
    }

    /// solver=direct|amg tol threshold sweeps into `parameters` (fem_mpi, fem3d).
    void apply(fem::DistributedSolverParameters &parameters) const
    {
      const std::string solver = text("solver", "direct");
      if (solver == "amg")
        parameters.method = fem::DistributedSolverParameters::Method::amg_cg;
      else if (solver != "direct")
        throw std::invalid_argument(tool + ": solver = " + solver + " outside {direct, amg}");
      parameters.relative_tolerance    = num("tol", parameters.relative_tolerance);
      parameters.aggregation_threshold = num("threshold", parameters.aggregation_threshold);
      parameters.smoother_sweeps       = count("sweeps", parameters.smoother_sweeps);
    }

  private:
    std::string                        tool;
    std::map<std::string, std::string> values;
    mutable std::set<std::string>      queried; ///< every key asked for (has, text, num, count, apply)
  };
} // namespace gradcontact::studies

#endif
