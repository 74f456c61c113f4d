// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/mpi_tools.h>
#include <porofrac/coupling/closure.h>
#include <porofrac/coupling/poromechanics.h>
#include <porofrac/flow/flow_output.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <cmath>

namespace porofrac
{
  namespace coupling
  {
    template <int dim>
    Poromechanics<dim>::Poromechanics(mechanics::ContactProblem<dim>            &mechanics,
                                      flow::FlowModel<dim>                      &flow,
                                      const CouplingParameters                  &parameters,
                                      ConditionalOStream                        &verbose,
                                      TimerOutput                               &timer,
                                      const MPI_Comm                             communicator,
                                      mechanics::DistributedContactProblem<dim> *distributed)
        : mechanics(mechanics)
        , flow(flow)
        , parameters(parameters)
        , verbose(verbose)
        , timer(timer)
        , communicator(communicator)
        , distributed(distributed)
        , contact_copies_per_machine(distributed ? 1 : processes_on_this_machine(communicator))
        , n_matrix(flow.grid->n_matrix_cells)
        , n_fracture(flow.grid->n_fracture_cells)
    {
      check_input(n_fracture == mechanics.get_mesh().fracture_faces.size(),
                  "Coupling",
                  "the flow and mechanics meshes do not share their fracture faces");
    }



    template <int dim>
    void
    Poromechanics<dim>::initialize()
    {
      auto &solver = *flow.solver;
      // p_E^0 from the initial pressures (11d); the storage term of (11d) is measured from it.
      p_E_initial = flow_equivalent_pressure();
      p_E         = p_E_initial;
      p_E_old     = p_E_initial;
      storage =
        std::make_shared<BiotStorage<dim>>(*flow.grid,
                                           flow.rocks[flow::matrix_rock].saturation,
                                           1. / parameters.biot_modulus,
                                           parameters.capillary_energy,
                                           std::vector<double>(p_E_initial.begin(),
                                                               p_E_initial.begin() + n_matrix),
                                           std::vector<double>(n_matrix, flow.initial_porosity));
      solver.set_storage_model(storage);
      // (u^0, lambda^0): the contact problem without time variable for p_E^0, from the deck's
      // initial guess (paper: open at the first step).
      solve_mechanics(p_E_initial);
      y_initial = displacement_measures();
      y_old     = y_initial;
      set_flow_inputs(y_initial);
      u_old      = mechanics.displacement();
      lambda_old = mechanics.multipliers();
      jump_old.resize(n_fracture);
      for (unsigned int f = 0; f < n_fracture; ++f)
        jump_old[f] = mechanics.jump(f);
      flow_guess = solver.state;
    }



    template <int dim>
    void
    Poromechanics<dim>::solve_mechanics(const Vector<double> &x)
    {
      TimerOutput::Scope        t(timer, "Coupling: contact mechanics");
      const std::vector<double> p_matrix(x.begin(), x.begin() + n_matrix);
      const std::vector<double> p_fracture(x.begin() + n_matrix, x.end());
      const auto                count = [&](const mechanics::ContactStatistics &s) {
        report.mechanics_iterations += s.iterations;
        linear_totals[0] += s.factorizations;
        linear_totals[1] += s.linear_iterations;
        linear_totals[2] += s.direct_fallbacks;
        linear_totals[3] += s.direct_workspace_retries;
        linear_totals[4] += s.fallback_factorizations;
      };
      if (distributed)
        {
          // Collective; a contact failure is thrown on every process.
          distributed->set_equivalent_pressures(p_matrix, p_fracture, parameters.biot_coefficient);
          // The serial copy's loads too (a vector update), for what solves it again
          // (the Iteration table).
          mechanics.set_equivalent_pressures(p_matrix, p_fracture, parameters.biot_coefficient);
          count(distributed->solve(/*warm_start=*/true));
          Vector<double> u, lambda;
          distributed->replicate_state(mechanics.get_dof_handler(), u, lambda);
          mechanics.set_state(u, lambda);
          return;
        }
      // A contact failure on one process is thrown on all of them.
      const ReplicatedSerialSolves replicated(contact_copies_per_machine);
      collectively(communicator, [&]() {
        mechanics.set_equivalent_pressures(p_matrix, p_fracture, parameters.biot_coefficient);
        // Warm start from the previous solve (paper 5.3: the previous time step's solution).
        count(mechanics.solve(/*warm_start=*/true));
      });
    }



    template <int dim>
    void
    Poromechanics<dim>::set_mechanics_state(const Vector<double> &u, const Vector<double> &lambda)
    {
      mechanics.set_state(u, lambda);
      if (distributed)
        distributed->set_state(mechanics.get_dof_handler(), u, lambda);
    }



    template <int dim>
    Vector<double>
    Poromechanics<dim>::displacement_measures() const
    {
      Vector<double>            y(n_matrix + n_fracture);
      const std::vector<double> div = mechanics.cell_divergence();
      for (unsigned int K = 0; K < n_matrix; ++K)
        y[K] = div[K];
      for (unsigned int f = 0; f < n_fracture; ++f)
        y[n_matrix + f] = mechanics.frame(f)[0] * mechanics.jump(f);
      if (communicator != MPI_COMM_SELF && Utilities::MPI::n_mpi_processes(communicator) > 1)
        {
          const int ierr = MPI_Bcast(y.begin(), y.size(), MPI_DOUBLE, 0, communicator);
          AssertThrowMPI(ierr);
        }
      return y;
    }



    template <int dim>
    void
    Poromechanics<dim>::set_flow_inputs(const Vector<double> &y)
    {
      auto &grid = *flow.grid;
      // (11d): phi = phi_0 + b div(u - u^0) + (p_E - p_E^0)/M; the last term is implicit in the
      // flow solve, the first two are frozen during it.
      std::vector<double> phi_u(n_matrix);
      for (unsigned int K = 0; K < n_matrix; ++K)
        phi_u[K] = displacement_porosity(flow.initial_porosity,
                                         parameters.biot_coefficient,
                                         y[K] - y_initial[K]);
      storage->set_displacement_porosity(phi_u);
      // (11d): d_f = d_0 - [u]_n.
      for (unsigned int f = 0; f < n_fracture; ++f)
        {
          const double d = aperture(flow.initial_aperture, y[n_matrix + f]);
          if (!(d > 0))
            throw SolverFailure("the aperture of fracture face " + std::to_string(f) +
                                " became non-positive (" + io::to_text(d) + " m)");
          grid.aperture[f] = d;
        }
      grid.update_transmissibilities();
    }



    template <int dim>
    void
    Poromechanics<dim>::solve_flow()
    {
      TimerOutput::Scope t(timer, "Coupling: two-phase flow");
      auto              &solver = *flow.solver;
      solver.state              = flow_guess;
      const flow::StepResult r  = solver.solve_time_step(dt, verbose);
      report.flow_newton_iterations += r.iterations;
      report.mass_defect = r.mass_defect;
      if (!r.converged)
        throw SolverFailure("two-phase flow Newton failed: " + r.failure);
      flow_guess = solver.state;
    }



    template <int dim>
    Vector<double>
    Poromechanics<dim>::flow_equivalent_pressure() const
    {
      const auto    &solver = *flow.solver;
      const auto    &state  = solver.state;
      Vector<double> x(n_matrix + n_fracture);
      for (unsigned int i = 0; i < n_matrix + n_fracture; ++i)
        x[i] = coupling::equivalent_pressure(*flow.rocks[flow.grid->nodes[i].rock].saturation,
                                             solver.pressure(state, i, 0),
                                             state[i][1] - state[i][0],
                                             parameters.capillary_energy);
      return x;
    }



    template <int dim>
    double
    Poromechanics<dim>::matrix_porosity(const unsigned int K) const
    {
      const auto &solver = *flow.solver;
      return storage->porosity(K,
                               solver.pressure(solver.state, K, 0),
                               solver.state[K][1] - solver.state[K][0]);
    }



    template <int dim>
    void
    Poromechanics<dim>::map_pressure(const Vector<double> &x, Vector<double> &gx)
    {
      solve_mechanics(x);
      set_flow_inputs(displacement_measures());
      solve_flow();
      gx = flow_equivalent_pressure();
    }



    template <int dim>
    void
    Poromechanics<dim>::map_displacement(const Vector<double> &y, Vector<double> &gy)
    {
      set_flow_inputs(y);
      solve_flow();
      solve_mechanics(flow_equivalent_pressure());
      gy = displacement_measures();
    }



    template <int dim>
    Vector<double>
    Poromechanics<dim>::initial_guess(const Vector<double> &x_old,
                                      const Vector<double> &x_older) const
    {
      Vector<double> x = x_old;
      if (parameters.extrapolate_initial_guess && dt_old > 0 && x_older.size() == x.size())
        {
          const double ratio = dt / dt_old;
          x.sadd(1. + ratio, -ratio, x_older);
        }
      return x;
    }



    template <int dim>
    CoupledStepReport
    Poromechanics<dim>::solve_time_step(const double time_step)
    {
      dt           = time_step;
      report       = CoupledStepReport();
      auto &solver = *flow.solver;
      auto &grid   = *flow.grid;
      // Kozeny-Carman, explicit in time: the permeability of the previous step's porosity.
      if (parameters.kozeny_carman)
        for (unsigned int K = 0; K < n_matrix; ++K)
          grid.permeability[K] =
            kozeny_carman(flow.initial_permeability, flow.initial_porosity, grid.porosity[K]);
      solver.begin_time_step();
      flow_guess = solver.old_state;
      {
        // The flow residual at the start of the step is the scale of the inner tolerances.
        Vector<double> residual;
        solver.assemble(solver.old_state, solver.old_state, dt, residual, nullptr);
        solver.residual_scale = residual.l2_norm();
      }

      FixedPointSolver fixed_point(parameters.fixed_point);
      FixedPointResult result;
      try
        {
          if (parameters.variable == CouplingVariable::equivalent_pressure)
            {
              Vector<double> x = initial_guess(p_E_old, p_E_older);
              result           = fixed_point.solve([this](const Vector<double> &x,
                                                Vector<double>       &gx) { map_pressure(x, gx); },
                                         x);
              // Leave every field consistent with one evaluation at the solution.
              if (!result.evaluated_at_solution)
                {
                  Vector<double> gx(x.size());
                  map_pressure(x, gx);
                  ++result.map_evaluations;
                }
            }
          else
            {
              Vector<double> y = initial_guess(y_old, y_older);
              result           = fixed_point.solve([this](const Vector<double> &y,
                                                Vector<double> &gy) { map_displacement(y, gy); },
                                         y);
              if (!result.evaluated_at_solution)
                {
                  Vector<double> gy(y.size());
                  map_displacement(y, gy);
                  ++result.map_evaluations;
                }
            }
          if (!result.converged)
            report.failure = "the coupling fixed point did not converge in " +
                             std::to_string(result.iterations) + " iterations (relative residual " +
                             io::to_text(result.relative_residual) + ")";
        }
      catch (const InsufficientMemory &)
        {
          // A shorter time step needs the same memory: the run stops.
          throw;
        }
      catch (const SolverFailure &e)
        {
          report.failure = e.what();
        }
      report.converged           = report.failure.empty();
      report.coupling_iterations = result.iterations;
      report.map_evaluations     = result.map_evaluations;
      report.gmres_iterations    = result.gmres_iterations;
      report.relative_residual   = result.relative_residual;
      if (report.converged)
        {
          p_E = flow_equivalent_pressure();
        }
      else
        {
          // Back to the accepted state, so that a shorter retry starts from the right pore
          // volumes and apertures.
          solver.state = solver.old_state;
          flow_guess   = solver.old_state;
          try
            {
              set_flow_inputs(y_old);
            }
          catch (const SolverFailure &)
            {
            }
        }
      return report;
    }



    template <int dim>
    void
    Poromechanics<dim>::accept_time_step()
    {
      auto &grid = *flow.grid;
      // The porosity reached by the step, (11d), kept for output and Kozeny-Carman.
      for (unsigned int K = 0; K < n_matrix; ++K)
        grid.porosity[K] = matrix_porosity(K);
      p_E_older  = p_E_old;
      y_older    = y_old;
      dt_old     = dt;
      p_E_old    = p_E;
      y_old      = displacement_measures();
      u_old      = mechanics.displacement();
      lambda_old = mechanics.multipliers();
      for (unsigned int f = 0; f < n_fracture; ++f)
        jump_old[f] = mechanics.jump(f);
    }



    template <int dim>
    void
    Poromechanics<dim>::save(io::CheckpointWriter &c) const
    {
      const auto &grid = *flow.grid;
      c.put("matrix cells", n_matrix);
      c.put("fracture faces", n_fracture);
      c.put("p_E", p_E);
      c.put("accepted p_E", p_E_old);
      c.put("older p_E", p_E_older);
      c.put("accepted y", y_old);
      c.put("older y", y_older);
      c.put("older step", dt_old);
      c.put("accepted displacement", u_old);
      c.put("accepted multipliers", lambda_old);
      c.put("accepted jumps", jump_old);
      c.put("flow guess", flow_guess);
      c.put("flow state", flow.solver->state);
      c.put("displacement porosity", storage->displacement_porosity());
      c.put("porosity", grid.porosity);
      c.put("permeability", grid.permeability);
      c.put("aperture", grid.aperture);
      c.put("contact linear solves",
            std::vector<double>(linear_totals.begin(), linear_totals.end()));
    }



    template <int dim>
    void
    Poromechanics<dim>::load(io::CheckpointReader &c)
    {
      auto &grid = *flow.grid;
      c.expect("matrix cells", n_matrix);
      c.expect("fracture faces", n_fracture);
      c.get("p_E", p_E);
      c.get("accepted p_E", p_E_old);
      c.get("older p_E", p_E_older);
      c.get("accepted y", y_old);
      c.get("older y", y_older);
      c.get("older step", dt_old);
      c.get("accepted displacement", u_old);
      c.get("accepted multipliers", lambda_old);
      c.get("accepted jumps", jump_old);
      c.get("flow guess", flow_guess);
      c.get("flow state", flow.solver->state);
      std::vector<double> phi_u;
      c.get("displacement porosity", phi_u);
      storage->set_displacement_porosity(phi_u);
      c.get("porosity", grid.porosity);
      c.get("permeability", grid.permeability);
      c.get("aperture", grid.aperture);
      std::vector<double> totals;
      c.get("contact linear solves", totals);
      // Checkpoints written before the fallback factorizations were counted hold 4 totals.
      check_input(totals.size() == linear_totals.size() ||
                    totals.size() == linear_totals.size() - 1,
                  "--restart",
                  "malformed checkpoint");
      linear_totals.fill(0);
      std::copy(totals.begin(), totals.end(), linear_totals.begin());
      grid.update_transmissibilities();
      set_mechanics_state(u_old, lambda_old);
    }



    template <int dim>
    void
    Poromechanics<dim>::restore_accepted_state()
    {
      flow.solver->state = flow.solver->old_state;
      set_mechanics_state(u_old, lambda_old);
      p_E = p_E_old;
    }



    template <int dim>
    double
    Poromechanics<dim>::mean_fracture_width() const
    {
      return flow::mean_aperture(mechanics.get_mesh(), *flow.grid);
    }

    template class Poromechanics<2>;
    template class Poromechanics<3>;
  } // namespace coupling
} // namespace porofrac
