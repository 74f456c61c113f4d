// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/coupling/energy_estimate.h>

#include <cmath>

namespace porofrac
{
  namespace coupling
  {
    template <int dim>
    EnergyEstimate<dim>::EnergyEstimate(const Poromechanics<dim> &problem)
        : problem(problem)
        , previous(stored_energy())
    {
    }



    template <int dim>
    EnergyTerms
    EnergyEstimate<dim>::stored_energy() const
    {
      const auto        &flow     = problem.flow;
      const auto        &solver   = *flow.solver;
      const auto        &grid     = *flow.grid;
      const auto        &p_E      = problem.equivalent_pressure();
      const double       M        = problem.get_parameters().biot_modulus;
      const unsigned int n_matrix = grid.n_matrix_cells;
      EnergyTerms        e;
      for (unsigned int K = 0; K < n_matrix; ++K)
        {
          const double pc = solver.state[K][1] - solver.state[K][0];
          e.capillary_matrix += problem.matrix_porosity(K) *
                                flow.rocks[flow::matrix_rock].saturation->energy(pc) *
                                grid.nodes[K].measure;
          e.storage += p_E[K] * p_E[K] * grid.nodes[K].measure / (2 * M);
        }
      for (unsigned int f = 0; f < grid.n_fracture_cells; ++f)
        {
          const unsigned int i  = n_matrix + f;
          const double       pc = solver.state[i][1] - solver.state[i][0];
          e.capillary_fracture +=
            grid.pore_volume(i) * flow.rocks[flow::fracture_rock].saturation->energy(pc);
        }
      e.elastic = problem.elastic_energy();
      return e;
    }



    template <int dim>
    StepEnergy
    EnergyEstimate<dim>::record_step()
    {
      const auto &solver    = *problem.flow.solver;
      const auto &mechanics = problem.mechanics;
      const auto  exchange  = solver.energy_exchange(solver.state, problem.time_step());
      StepEnergy  s;
      s.energy      = stored_energy();
      s.change      = s.energy.total() - previous.total();
      s.dissipation = exchange.dissipation;
      s.supplied_work =
        exchange.boundary_work + mechanics.external_work(problem.accepted_displacement());
      for (unsigned int f = 0; f < mechanics.get_mesh().fracture_faces.size(); ++f)
        s.friction_work += mechanics.multiplier(f) *
                           (mechanics.jump(f) - problem.accepted_jump(f)) *
                           mechanics.face_measure(f);
      const double lhs = s.change + s.dissipation + s.friction_work;
      // The step's terms are resolved to the coupling tolerance of the stored energy: near an
      // equilibrium they are all at that level, and their balance says nothing about (19).
      const double resolution =
        problem.get_parameters().fixed_point.tolerance * std::abs(s.energy.total());
      const double scale = std::abs(s.change) + s.dissipation + std::abs(s.friction_work) +
                           std::abs(s.supplied_work) + resolution;
      s.violation       = scale > 0 ? std::max(0., lhs - s.supplied_work) / scale : 0.;
      largest_violation = std::max(largest_violation, s.violation);
      previous          = s.energy;
      return s;
    }

    template <int dim>
    void
    EnergyEstimate<dim>::save(io::CheckpointWriter &c) const
    {
      c.put("stored energy",
            std::vector<double>{previous.capillary_matrix,
                                previous.capillary_fracture,
                                previous.elastic,
                                previous.storage});
      c.put("largest energy violation", largest_violation);
    }



    template <int dim>
    void
    EnergyEstimate<dim>::load(io::CheckpointReader &c)
    {
      std::vector<double> e;
      c.get("stored energy", e);
      check_input(e.size() == 4, "--restart", "malformed checkpoint");
      previous = {e[0], e[1], e[2], e[3]};
      c.get("largest energy violation", largest_violation);
    }

    template class EnergyEstimate<2>;
    template class EnergyEstimate<3>;
  } // namespace coupling
} // namespace porofrac
