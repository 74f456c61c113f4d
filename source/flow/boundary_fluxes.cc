// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/flow/boundary_fluxes.h>

#include <map>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      struct BoundarySums
      {
        std::array<double, 2> outflow{{0., 0.}};
        double                area = 0, pressure_area = 0;
      };

      /// Measure (times 2 pi r if axisymmetric), centre and unit normal of a simplex face.
      template <int dim, typename Face>
      double
      face_area(const Face &face, const bool axisymmetric, Point<dim> &centre, Tensor<1, dim> &n)
      {
        centre = Point<dim>();
        for (unsigned int v = 0; v < dim; ++v)
          centre += face->vertex(v) / double(dim);
        const Tensor<1, dim> a = face->vertex(1) - face->vertex(0);
        double               measure;
        if constexpr (dim == 2)
          {
            measure = a.norm();
            n[0]    = -a[1] / measure;
            n[1]    = a[0] / measure;
          }
        else
          {
            n       = cross_product_3d(a, face->vertex(2) - face->vertex(0));
            measure = 0.5 * n.norm();
            n /= n.norm();
          }
        return measure * (axisymmetric ? 2. * numbers::PI * centre[1] : 1.);
      }
    } // namespace



    template <int dim>
    io::Json
    boundary_fluxes(const geometry::CutMesh<dim> &mesh,
                    const TwoPhaseSolver<dim>    &solver,
                    const FaceFlux               &matrix_flux,
                    const bool                    axisymmetric)
    {
      const auto                              &grid  = solver.grid;
      const auto                              &state = solver.state;
      std::map<types::boundary_id, BoundarySums> sums;
      std::array<double, 4>                    d;
      // Dirichlet nodes: the flux of every connection into one.
      for (const auto &c : grid.connections)
        if (grid.is_dirichlet(c.b) && !grid.is_dirichlet(c.a))
          {
            const auto &node = grid.nodes[c.b];
            auto       &s    = sums[node.boundary_id];
            for (unsigned int phase = 0; phase < 2; ++phase)
              s.outflow[phase] += solver.flux(c, state, phase, d);
            if (node.kind == TpfaGrid<dim>::NodeKind::dirichlet_matrix)
              {
                s.area += c.area;
                s.pressure_area += c.area * solver.pressure(state, c.b, 0);
              }
          }
      // Flux faces: the prescribed inflow, and the face pressure of the two-point flux.
      for (const auto &cell : mesh.triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) && matrix_flux.count(cell->face(f)->boundary_id()))
            {
              const auto        &q = matrix_flux.at(cell->face(f)->boundary_id());
              const unsigned int K = cell->active_cell_index();
              Point<dim>         centre;
              Tensor<1, dim>     n;
              const double       area = face_area<dim>(cell->face(f), axisymmetric, centre, n);
              auto              &s    = sums[cell->face(f)->boundary_id()];
              for (unsigned int phase = 0; phase < 2; ++phase)
                s.outflow[phase] -= area * q[phase];
              const double distance =
                std::max(std::abs(grid.half_distance(grid.nodes[K].centre, centre, n)),
                         1e-3 * cell->diameter());
              const double eta = solver.rocks[matrix_rock].mobility(
                0, solver.saturation(state, K, matrix_rock));
              s.area += area;
              s.pressure_area +=
                area * (solver.pressure(state, K, 0) + q[0] * distance / (grid.permeability[K] * eta));
            }
      io::Json result = io::Json::object();
      for (const auto &[id, s] : sums)
        {
          io::Json &entry       = result[std::to_string(id)];
          entry["outflow_w"]    = s.outflow[0];
          entry["outflow_nw"]   = s.outflow[1];
          entry["area"]         = s.area;
          entry["mean_pressure_w"] = s.area > 0 ? s.pressure_area / s.area : 0.;
        }
      return result;
    }

    template io::Json
    boundary_fluxes(const geometry::CutMesh<2> &,
                    const TwoPhaseSolver<2> &,
                    const FaceFlux &,
                    const bool);
    template io::Json
    boundary_fluxes(const geometry::CutMesh<3> &,
                    const TwoPhaseSolver<3> &,
                    const FaceFlux &,
                    const bool);
  } // namespace flow
} // namespace porofrac
