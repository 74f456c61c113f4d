// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/flow/boundary_fluxes.h>

#include <cmath>
#include <iomanip>
#include <map>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
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
    std::map<types::boundary_id, BoundaryBalance>
    boundary_balances(const geometry::CutMesh<dim> &mesh,
                      const TwoPhaseSolver<dim>    &solver,
                      const FaceFlux               &matrix_flux,
                      const bool                    axisymmetric)
    {
      const auto                                   &grid  = solver.grid;
      const auto                                   &state = solver.state;
      std::map<types::boundary_id, BoundaryBalance> sums;
      std::array<double, 4>                         d;
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
                s.mean_pressure_w += c.area * solver.pressure(state, c.b, 0);
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
              const double eta =
                solver.rocks[matrix_rock].mobility(0, solver.saturation(state, K, matrix_rock));
              s.area += area;
              s.mean_pressure_w += area * (solver.pressure(state, K, 0) +
                                           q[0] * distance / (grid.permeability[K] * eta));
            }
      for (auto &entry : sums)
        if (entry.second.area > 0)
          entry.second.mean_pressure_w /= entry.second.area;
      return sums;
    }



    io::Json
    to_json(const std::map<types::boundary_id, BoundaryBalance> &balances)
    {
      io::Json result = io::Json::object();
      for (const auto &[id, b] : balances)
        {
          io::Json &entry          = result[std::to_string(id)];
          entry["outflow_w"]       = b.outflow[0];
          entry["outflow_nw"]      = b.outflow[1];
          entry["area"]            = b.area;
          entry["mean_pressure_w"] = b.mean_pressure_w;
        }
      return result;
    }



    void
    report_boundary_balances(const std::map<types::boundary_id, BoundaryBalance> &balances,
                             const bool                                           plane,
                             std::ostream                                        &report)
    {
      double largest = 0;
      for (const auto &entry : balances)
        for (const double q : entry.second.outflow)
          largest = std::max(largest, std::abs(q));
      const auto shown = [largest](const double q) {
        return std::abs(q) <= 1e-12 * largest ? 0. : q;
      };
      const auto flags = report.flags();
      for (const auto &[id, b] : balances)
        report << "Flow: boundary " << id << ": outflow of w " << std::scientific
               << std::setprecision(4) << shown(b.outflow[0]) << ", of nw " << shown(b.outflow[1])
               << (plane ? " m^2/s" : " m^3/s") << "; mean p_w " << b.mean_pressure_w << " Pa"
               << std::endl;
      report.flags(flags);
    }

    template std::map<types::boundary_id, BoundaryBalance>
    boundary_balances(const geometry::CutMesh<2> &,
                      const TwoPhaseSolver<2> &,
                      const FaceFlux &,
                      const bool);
    template std::map<types::boundary_id, BoundaryBalance>
    boundary_balances(const geometry::CutMesh<3> &,
                      const TwoPhaseSolver<3> &,
                      const FaceFlux &,
                      const bool);
  } // namespace flow
} // namespace porofrac
