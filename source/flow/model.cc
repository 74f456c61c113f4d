// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/flow/model.h>
#include <porofrac/io/expression.h>
#include <porofrac/io/text.h>

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
      /// Boundary ids (keys) of @p conditions; for the matrix (@p on_mesh), each must be on the
      /// mesh.
      template <int dim, typename Conditions>
      std::set<types::boundary_id>
      boundary_ids(const Conditions             &conditions,
                   const geometry::CutMesh<dim> &mesh,
                   const bool                    on_mesh,
                   const std::string            &parameter)
      {
        std::set<types::boundary_id> ids;
        for (const auto &b : conditions)
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

      template <int dim>
      typename TpfaGrid<dim>::Centres
      cell_centres(const std::string &choice)
      {
        using Centres = typename TpfaGrid<dim>::Centres;
        if (choice == "auto")
          return dim == 2 ? Centres::circumcentre : Centres::centroid;
        return choice == "centroid" ? Centres::centroid : Centres::circumcentre;
      }

      /// Measure of a matrix boundary face (segment or triangle), times 2 pi r if axisymmetric.
      template <int dim, typename Face>
      double
      boundary_face_area(const Face &face, const bool axisymmetric)
      {
        const Tensor<1, dim> a = face->vertex(1) - face->vertex(0);
        double               measure;
        Point<dim>           centre;
        for (unsigned int v = 0; v < dim; ++v)
          centre += face->vertex(v) / double(dim);
        if constexpr (dim == 2)
          measure = a.norm();
        else
          measure = 0.5 * cross_product_3d(a, face->vertex(2) - face->vertex(0)).norm();
        return measure * (axisymmetric ? 2. * numbers::PI * centre[1] : 1.);
      }

      template <int dim, typename Cell>
      Point<dim>
      centroid(const Cell &cell)
      {
        Point<dim> c;
        for (const unsigned int v : cell->vertex_indices())
          c += cell->vertex(v) / double(cell->n_vertices());
        return c;
      }

      /// Matrix permeability: K_0, or the expression at every cell centroid.
      template <int dim>
      void
      set_permeability(const FlowParameters         &parameters,
                       const geometry::CutMesh<dim> &mesh,
                       TpfaGrid<dim>                &grid)
      {
        grid.permeability.assign(grid.n_matrix_cells, parameters.permeability);
        if (parameters.permeability_expression.empty())
          return;
        const std::string name = "Flow/Matrix/Permeability expression";
        const auto k = io::parse_expressions<dim>({parameters.permeability_expression}, name);
        for (const auto &cell : mesh.triangulation.active_cell_iterators())
          {
            const Point<dim> x     = centroid<dim>(cell);
            const double     value = k->value(x);
            check_input(value > 0 && std::isfinite(value),
                        name,
                        "is " + io::to_text(value) + " at " + io::to_text(x) +
                          ", but a permeability must be positive");
            grid.permeability[cell->active_cell_index()] = value;
          }
      }

      /**
       * The inflow per face area of each Matrix flux id: the given one, or the total rate divided
       * by the area of the id's faces.
       */
      template <int dim>
      FaceFlux
      face_fluxes(const FlowParameters &parameters, const geometry::CutMesh<dim> &mesh)
      {
        std::map<types::boundary_id, double> area;
        for (const auto &cell : mesh.triangulation.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              area[cell->face(f)->boundary_id()] +=
                boundary_face_area<dim>(cell->face(f), parameters.axisymmetric);
        FaceFlux result;
        for (const auto &[id, flux] : parameters.matrix_flux)
          for (unsigned int phase = 0; phase < 2; ++phase)
            result[id][phase] = flux.total ? flux.rate[phase] / area[id] : flux.rate[phase];
        return result;
      }

      /**
       * Volumetric sources per node (m^3/s): matrix sources h^alpha(x) (1/s, volume of phase per
       * bulk volume) as |K| h^alpha per cell, plus the inflow |e| q^alpha through every matrix
       * boundary face e with a Matrix flux condition (@p face_flux), on the cell of the face.
       */
      template <int dim>
      void
      set_sources(const FlowParameters         &parameters,
                  const FaceFlux               &face_flux,
                  const geometry::CutMesh<dim> &mesh,
                  const TpfaGrid<dim>          &grid,
                  TwoPhaseSolver<dim>          &solver)
      {
        const auto &expression = parameters.source;
        if (expression[0] == "0" && expression[1] == "0" && face_flux.empty())
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
        for (const auto &cell : mesh.triangulation.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f) && face_flux.count(cell->face(f)->boundary_id()))
              {
                const auto  &q    = face_flux.at(cell->face(f)->boundary_id());
                const double area = boundary_face_area<dim>(cell->face(f), parameters.axisymmetric);
                for (unsigned int phase = 0; phase < 2; ++phase)
                  solver.source[cell->active_cell_index()][phase] += area * q[phase];
              }
      }
    } // namespace

    template <int dim>
    FlowModel<dim>
    make_flow_model(const FlowParameters                          &parameters,
                    const geometry::CutMesh<dim>                  &mesh,
                    const std::function<void(NewtonParameters &)> &adjust_newton,
                    const bool                                     distributed)
    {
      parameters.validate();
      FlowModel<dim> model;
      model.rocks = parameters.rocks;
      const auto matrix_ids =
        boundary_ids(parameters.matrix_dirichlet, mesh, true, "Flow/Boundary conditions/Matrix");
      boundary_ids(parameters.matrix_flux, mesh, true, "Flow/Boundary conditions/Matrix flux");
      const auto fracture_ids = boundary_ids(parameters.fracture_dirichlet,
                                             mesh,
                                             false,
                                             "Flow/Boundary conditions/Fracture");
      model.stepping          = parameters.stepping;
      model.newton            = parameters.newton;
      if (adjust_newton)
        adjust_newton(model.newton);

      model.grid                 = std::make_unique<TpfaGrid<dim>>(mesh,
                                                   parameters.axisymmetric,
                                                   matrix_ids,
                                                   fracture_ids,
                                                   cell_centres<dim>(parameters.cell_centres));
      TpfaGrid<dim> &grid        = *model.grid;
      model.initial_porosity     = parameters.porosity;
      model.initial_permeability = parameters.permeability;
      model.initial_aperture     = parameters.aperture;
      grid.porosity.assign(grid.n_matrix_cells, model.initial_porosity);
      set_permeability(parameters, mesh, grid);
      grid.aperture.assign(grid.n_fracture_cells, model.initial_aperture);
      grid.normal_transmissibility = parameters.normal_transmissibility;
      grid.damaged_layer_thickness = parameters.damaged_layer_thickness;
      grid.damaged_layer_porosity  = parameters.damaged_layer_porosity;
      grid.update_transmissibilities();

      model.solver =
        std::make_unique<TwoPhaseSolver<dim>>(grid, model.rocks, model.newton, !distributed);
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
      model.matrix_flux = face_fluxes(parameters, mesh);
      set_sources(parameters, model.matrix_flux, mesh, grid, solver);
      return model;
    }

    template FlowModel<2>
    make_flow_model(const FlowParameters &,
                    const geometry::CutMesh<2> &,
                    const std::function<void(NewtonParameters &)> &,
                    const bool);
    template FlowModel<3>
    make_flow_model(const FlowParameters &,
                    const geometry::CutMesh<3> &,
                    const std::function<void(NewtonParameters &)> &,
                    const bool);
  } // namespace flow
} // namespace porofrac
