// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/flow/model.h>
#include <porofrac/io/expression.h>

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
      /// Boundary ids of @p dirichlet; for the matrix (@p on_mesh), each must be on the mesh.
      template <int dim>
      std::set<types::boundary_id>
      dirichlet_ids(const DirichletData          &dirichlet,
                    const geometry::CutMesh<dim> &mesh,
                    const bool                    on_mesh,
                    const std::string            &parameter)
      {
        std::set<types::boundary_id> ids;
        for (const auto &b : dirichlet)
          {
            check_input(!on_mesh || std::count(mesh.outer_boundary_ids.begin(),
                                               mesh.outer_boundary_ids.end(),
                                               b.first),
                        parameter,
                        "boundary id " + std::to_string(b.first) + " is not on the mesh");
            ids.insert(b.first);
          }
        return ids;
      }

      /// Matrix sources h^alpha(x) (1/s, volume of phase per bulk volume): |K| h^alpha per cell.
      template <int dim>
      void
      set_sources(const std::array<std::string, 2> &expression,
                  const TpfaGrid<dim>              &grid,
                  TwoPhaseSolver<dim>              &solver)
      {
        if (expression[0] == "0" && expression[1] == "0")
          return;
        solver.source.assign(grid.n_nodes(), {{0., 0.}});
        for (unsigned int phase = 0; phase < 2; ++phase)
          {
            const std::string name = std::string("Flow/Matrix/Source ") + (phase == 0 ? "w" : "nw");
            const auto        h    = io::parse_expressions<dim>({expression[phase]}, name);
            for (unsigned int K = 0; K < grid.n_matrix_cells; ++K)
              {
                const double value      = h->value(grid.nodes[K].centre);
                solver.source[K][phase] = grid.nodes[K].measure * value;
              }
          }
      }
    } // namespace

    template <int dim>
    FlowModel<dim>
    make_flow_model(const FlowParameters                          &parameters,
                    const geometry::CutMesh<dim>                  &mesh,
                    const std::function<void(NewtonParameters &)> &adjust_newton)
    {
      parameters.validate();
      FlowModel<dim> model;
      model.rocks = parameters.rocks;
      const auto matrix_ids =
        dirichlet_ids(parameters.matrix_dirichlet, mesh, true, "Flow/Boundary conditions/Matrix");
      const auto fracture_ids = dirichlet_ids(parameters.fracture_dirichlet,
                                              mesh,
                                              false,
                                              "Flow/Boundary conditions/Fracture");
      model.stepping          = parameters.stepping;
      model.newton            = parameters.newton;
      if (adjust_newton)
        adjust_newton(model.newton);

      model.grid =
        std::make_unique<TpfaGrid<dim>>(mesh, parameters.axisymmetric, matrix_ids, fracture_ids);
      TpfaGrid<dim> &grid        = *model.grid;
      model.initial_porosity     = parameters.porosity;
      model.initial_permeability = parameters.permeability;
      model.initial_aperture     = parameters.aperture;
      grid.porosity.assign(grid.n_matrix_cells, model.initial_porosity);
      grid.permeability.assign(grid.n_matrix_cells, model.initial_permeability);
      grid.aperture.assign(grid.n_fracture_cells, model.initial_aperture);
      grid.normal_transmissibility = parameters.normal_transmissibility;
      grid.damaged_layer_thickness = parameters.damaged_layer_thickness;
      grid.damaged_layer_porosity  = parameters.damaged_layer_porosity;
      grid.update_transmissibilities();

      model.solver = std::make_unique<TwoPhaseSolver<dim>>(grid, model.rocks, model.newton);
      TwoPhaseSolver<dim> &solver = *model.solver;
      solver.matrix_dirichlet     = parameters.matrix_dirichlet;
      solver.fracture_dirichlet   = parameters.fracture_dirichlet;
      solver.reference_pressure   = parameters.reference_pressure;
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        {
          const bool matrix = grid.nodes[i].kind == TpfaGrid<dim>::NodeKind::matrix ||
                              grid.nodes[i].kind == TpfaGrid<dim>::NodeKind::interface;
          const auto &p   = parameters.initial_pressure[matrix ? matrix_rock : fracture_rock];
          solver.state[i] = {{p[0] - solver.reference_pressure, p[1] - solver.reference_pressure}};
        }
      solver.apply_dirichlet(solver.state);
      solver.begin_time_step();
      set_sources(parameters.source, grid, solver);
      return model;
    }

    template FlowModel<2>
    make_flow_model(const FlowParameters &,
                    const geometry::CutMesh<2> &,
                    const std::function<void(NewtonParameters &)> &);
    template FlowModel<3>
    make_flow_model(const FlowParameters &,
                    const geometry::CutMesh<3> &,
                    const std::function<void(NewtonParameters &)> &);
  } // namespace flow
} // namespace porofrac
