// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/flow/model.h>
#include <porofrac/flow/scene.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace porofrac
{
  namespace flow
  {
    using namespace dealii;

    namespace
    {
      double
      get_double(const ParameterHandler         &prm,
                 const std::vector<std::string> &path,
                 const std::string              &name)
      {
        return Utilities::string_to_double(prm.get(path, name));
      }
    } // namespace

    template <int dim>
    FlowModel<dim>
    make_flow_model(const ParameterHandler                        &prm,
                    const geometry::CutMesh<dim>                  &mesh,
                    const std::function<void(NewtonParameters &)> &adjust_newton)
    {
      const std::vector<std::string> flow = {"Flow"};
      FlowModel<dim>                 model;
      const double                   mu_w  = get_double(prm, flow, "Viscosity w");
      const double                   mu_nw = get_double(prm, flow, "Viscosity nw");
      model.rocks                          = {
                                 {parse_rock(prm, "Matrix", mu_w, mu_nw), parse_rock(prm, "Fracture", mu_w, mu_nw)}};
      const auto matrix_bc   = parse_dirichlet(prm.get({"Flow", "Boundary conditions"}, "Matrix"),
                                             model.rocks[0],
                                             "Flow/Boundary conditions/Matrix");
      const auto fracture_bc = parse_dirichlet(prm.get({"Flow", "Boundary conditions"}, "Fracture"),
                                               model.rocks[1],
                                               "Flow/Boundary conditions/Fracture");
      std::set<types::boundary_id> matrix_ids, fracture_ids;
      for (const auto &b : matrix_bc)
        {
          check_input(std::count(mesh.outer_boundary_ids.begin(),
                                 mesh.outer_boundary_ids.end(),
                                 b.first),
                      "Flow/Boundary conditions/Matrix",
                      "boundary id " + std::to_string(b.first) + " is not on the mesh");
          matrix_ids.insert(b.first);
        }
      for (const auto &b : fracture_bc)
        fracture_ids.insert(b.first);

      TimeStepping &ts = model.stepping;
      ts.final_time    = get_double(prm, flow, "Final time");
      ts.initial_step  = get_double(prm, flow, "Initial time step");
      ts.maximum_step  = get_double(prm, flow, "Maximum time step");
      ts.growth        = get_double(prm, flow, "Time step growth");
      ts.maximum_cuts  = Utilities::string_to_int(prm.get(flow, "Maximum time step cuts"));
      ts.output_every  = Utilities::string_to_int(prm.get(flow, "Output every"));
      check_input(ts.final_time > 0, "Flow/Final time", "must be positive");
      check_input(ts.initial_step > 0, "Flow/Initial time step", "must be positive");
      check_input(ts.maximum_step > 0, "Flow/Maximum time step", "must be positive");
      check_input(ts.growth >= 1, "Flow/Time step growth", "must be >= 1");

      NewtonParameters &newton = model.newton;
      newton.max_iterations = Utilities::string_to_int(prm.get(flow, "Maximum Newton iterations"));
      newton.residual_tolerance = get_double(prm, flow, "Residual tolerance");
      newton.update_tolerance   = get_double(prm, flow, "Update tolerance");
      newton.mass_tolerance     = get_double(prm, flow, "Mass balance tolerance");
      newton.capillary_chop     = get_double(prm, flow, "Capillary chop");
      newton.saturation_chop    = get_double(prm, flow, "Saturation chop");
      newton.stagnation_iterations =
        Utilities::string_to_int(prm.get(flow, "Stagnation iterations"));
      newton.entry_slope_iterations =
        Utilities::string_to_int(prm.get(flow, "Entry slope iterations"));
      check_input(newton.saturation_chop < 1, "Flow/Saturation chop", "must be below 1");
      newton.entry_slope     = prm.get(flow, "Entry slope in Jacobian") == "true";
      newton.capillary_bound = prm.get(flow, "Capillary pressure bound") == "true";
      newton.line_search     = prm.get(flow, "Line search") == "true";
      if (adjust_newton)
        adjust_newton(newton);

      const bool axisymmetric = prm.get(flow, "Axisymmetric") == "true";
      model.grid = std::make_unique<TpfaGrid<dim>>(mesh, axisymmetric, matrix_ids, fracture_ids);
      TpfaGrid<dim> &grid        = *model.grid;
      model.initial_porosity     = get_double(prm, {"Flow", "Matrix"}, "Porosity");
      model.initial_permeability = get_double(prm, {"Flow", "Matrix"}, "Permeability");
      model.initial_aperture     = get_double(prm, {"Flow", "Fracture"}, "Aperture");
      check_input(model.initial_porosity > 0 && model.initial_porosity < 1,
                  "Flow/Matrix/Porosity",
                  "must lie in (0, 1)");
      check_input(model.initial_permeability > 0, "Flow/Matrix/Permeability", "must be positive");
      check_input(model.initial_aperture > 0, "Flow/Fracture/Aperture", "must be positive");
      grid.porosity.assign(grid.n_matrix_cells, model.initial_porosity);
      grid.permeability.assign(grid.n_matrix_cells, model.initial_permeability);
      grid.aperture.assign(grid.n_fracture_cells, model.initial_aperture);
      grid.normal_transmissibility =
        get_double(prm, {"Flow", "Fracture"}, "Normal transmissibility");
      grid.damaged_layer_thickness =
        get_double(prm, {"Flow", "Fracture"}, "Damaged layer thickness");
      grid.damaged_layer_porosity = get_double(prm, {"Flow", "Fracture"}, "Damaged layer porosity");
      check_input(grid.damaged_layer_thickness >= 0,
                  "Flow/Fracture/Damaged layer thickness",
                  "must be non-negative");
      check_input(grid.damaged_layer_porosity >= 0 && grid.damaged_layer_porosity < 1,
                  "Flow/Fracture/Damaged layer porosity",
                  "must lie in [0, 1)");
      check_input(grid.damaged_layer_thickness == 0 || grid.damaged_layer_porosity > 0,
                  "Flow/Fracture/Damaged layer porosity",
                  "must be positive when the damaged layer thickness is");
      grid.update_transmissibilities();

      model.solver = std::make_unique<TwoPhaseSolver<dim>>(grid, model.rocks, newton);
      TwoPhaseSolver<dim> &solver     = *model.solver;
      solver.matrix_dirichlet         = matrix_bc;
      solver.fracture_dirichlet       = fracture_bc;
      solver.reference_pressure       = get_double(prm, flow, "Reference pressure");
      const std::array<double, 2> p_m = {
        {get_double(prm, {"Flow", "Matrix"}, "Initial pressure w"),
         get_double(prm, {"Flow", "Matrix"}, "Initial pressure nw")}};
      const std::array<double, 2> p_f = {
        {get_double(prm, {"Flow", "Fracture"}, "Initial pressure w"),
         get_double(prm, {"Flow", "Fracture"}, "Initial pressure nw")}};
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        {
          const auto &p   = (grid.nodes[i].kind == TpfaGrid<dim>::NodeKind::matrix ||
                           grid.nodes[i].kind == TpfaGrid<dim>::NodeKind::interface) ?
                              p_m :
                              p_f;
          solver.state[i] = {{p[0] - solver.reference_pressure, p[1] - solver.reference_pressure}};
        }
      solver.apply_dirichlet(solver.state);
      solver.begin_time_step();

      // Matrix sources h^alpha(x) (1/s, volume of phase per bulk volume), |K| h^alpha per cell.
      std::array<std::string, 2> source_expression = {
        {prm.get({"Flow", "Matrix"}, "Source w"), prm.get({"Flow", "Matrix"}, "Source nw")}};
      if (source_expression[0] != "0" || source_expression[1] != "0")
        {
          solver.source.assign(grid.n_nodes(), {{0., 0.}});
          for (unsigned int phase = 0; phase < 2; ++phase)
            {
              const std::string name =
                std::string("Flow/Matrix/Source ") + (phase == 0 ? "w" : "nw");
              FunctionParser<dim> h(1);
              try
                {
                  h.initialize(dim == 2 ? "x,y" : "x,y,z", source_expression[phase], {});
                  h.value(Point<dim>()); // deal.II parses lazily: force it here
                }
              catch (...)
                {
                  throw InputError(name,
                                   "cannot parse '" + source_expression[phase] +
                                     "' as a muparser expression of x, y (, z)");
                }
              for (unsigned int K = 0; K < grid.n_matrix_cells; ++K)
                {
                  const double value = h.value(grid.nodes[K].centre);
                  check_input(std::isfinite(value), name, "is not finite at a cell centre");
                  solver.source[K][phase] = grid.nodes[K].measure * value;
                }
            }
        }
      return model;
    }

    template FlowModel<2>
    make_flow_model(const ParameterHandler &,
                    const geometry::CutMesh<2> &,
                    const std::function<void(NewtonParameters &)> &);
    template FlowModel<3>
    make_flow_model(const ParameterHandler &,
                    const geometry::CutMesh<3> &,
                    const std::function<void(NewtonParameters &)> &);
  } // namespace flow
} // namespace porofrac
