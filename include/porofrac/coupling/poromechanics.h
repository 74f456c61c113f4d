// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_COUPLING_POROMECHANICS_H
#define POROFRAC_COUPLING_POROMECHANICS_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/vector.h>

#include <porofrac/coupling/biot_storage.h>
#include <porofrac/coupling/newton_krylov.h>
#include <porofrac/coupling/parameters.h>
#include <porofrac/flow/model.h>
#include <porofrac/io/checkpoint.h>
#include <porofrac/mechanics/contact_problem.h>
#include <porofrac/mechanics/distributed_contact_problem.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace porofrac
{
  namespace coupling
  {
    using namespace dealii;

    /// What one coupled time step did.
    struct CoupledStepReport
    {
      bool         converged              = false;
      unsigned int coupling_iterations    = 0; ///< Newton(-Krylov) or Picard iterations
      unsigned int map_evaluations        = 0; ///< evaluations of g_p or g_u
      unsigned int gmres_iterations       = 0;
      unsigned int flow_newton_iterations = 0; ///< summed over all flow solves of the step
      unsigned int mechanics_iterations   = 0; ///< summed over all contact solves of the step
      double       relative_residual      = 0;
      std::array<double, 2> mass_defect{{0., 0.}};
      std::string           failure; ///< why the step failed, empty when converged
    };

    /**
     * The coupled problem of the paper's Section 4.2: contact mechanics (11b)-(11c) and two-phase
     * flow (11a) linked by the closure (11d). Each time step solves the fixed point
     * p_E = g_p(p_E) or u = g_u(u) (paper, Section 5 opening) with FixedPointSolver.
     *
     * Numbering: matrix quantities per active cell index (= flow matrix cells), fracture
     * quantities per CutMesh fracture face index (= flow fracture cells n_matrix + f).
     *
     * On the processes of @p communicator (a flow distributed with TwoPhaseSolver::distribute()
     * over them): every process solves the same serial contact problem, a contact failure on one
     * process ends the map evaluation on all, and the displacement measures the flow sees
     * (div u per cell, [u]_n per face) are rank 0's, so that the replicated flow state and the
     * fixed-point vectors stay the same on every process even if their linear algebra differed
     * in round-off.
     *
     * With @p distributed_mechanics, the contact problem is solved by that distributed problem
     * instead (Coupling/Distributed contact mechanics), and its (u, lambda) is copied into
     * @p mechanics on every process after each solve: everything the coupling reads (divergences,
     * jumps, energies, output) comes from the serial problem as before.
     */
    template <int dim>
    class Poromechanics
    {
    public:
      Poromechanics(mechanics::ContactProblem<dim>            &mechanics,
                    flow::FlowModel<dim>                      &flow,
                    const CouplingParameters                  &parameters,
                    ConditionalOStream                        &verbose,
                    TimerOutput                               &timer,
                    const MPI_Comm                             communicator = MPI_COMM_SELF,
                    mechanics::DistributedContactProblem<dim> *distributed_mechanics = nullptr);

      /// t = 0: p_E^0 of the initial pressures, (u^0, lambda^0) the contact solution with p_E^0
      /// (paper, after (11d)), phi = phi_0, d_f = d_0 - [u^0]_n.
      void
      initialize();

      /// One implicit step of length dt from the accepted state. On failure, the flow state is
      /// reset to the accepted one and the report says why.
      CoupledStepReport
      solve_time_step(const double dt);

      /// Makes the current state the accepted one.
      void
      accept_time_step();

      /// Writes the state between two time steps (accepted and older states, the flow inputs
      /// and the flow state) to a checkpoint; load() restores it exactly, after initialize().
      void
      save(io::CheckpointWriter &checkpoint) const;
      void
      load(io::CheckpointReader &checkpoint);

      /// Sets the flow state, (u, lambda) and p_E back to the accepted ones (to write the last
      /// good state after a failed step).
      void
      restore_accepted_state();

      /// Porosity (11d) of matrix cell @p K in the current flow state.
      double
      matrix_porosity(const unsigned int K) const;
      /// Displacement and face jumps of the accepted state (the start of the current step).
      const Vector<double> &
      accepted_displacement() const
      {
        return u_old;
      }
      const Tensor<1, dim> &
      accepted_jump(const unsigned int f) const
      {
        return jump_old[f];
      }
      const CouplingParameters &
      get_parameters() const
      {
        return parameters;
      }
      /// Length of the last step solved.
      double
      time_step() const
      {
        return dt;
      }

      /// Length-weighted mean of d_f over all fracture faces (paper Fig. 15).
      double
      mean_fracture_width() const;

      /// Current p_E per matrix cell then per fracture face (flow numbering).
      const Vector<double> &
      equivalent_pressure() const
      {
        return p_E;
      }

      /// The statistics of the last contact solve (of the distributed problem if there is one).
      const mechanics::ContactStatistics &
      contact_statistics() const
      {
        return distributed ? distributed->statistics() : mechanics.statistics();
      }
      /// Over every contact solve so far (the initial one included): factorizations, Krylov
      /// iterations, Krylov solves replaced by a direct one, MUMPS factorizations repeated with
      /// a larger workspace, factorizations of those direct solves.
      const std::array<unsigned int, 5> &
      contact_linear_totals() const
      {
        return linear_totals;
      }
      /// Whether the contact problem is solved by the distributed code.
      bool
      distributed_contact() const
      {
        return distributed != nullptr;
      }
      /// 1/2 a(u, u) of the current displacement, from the distributed problem if there is one
      /// (collective over its processes; the serial copy holds the same u).
      double
      elastic_energy() const
      {
        return distributed ? distributed->elastic_energy() : mechanics.elastic_energy();
      }
      /// The linear solver of the contact iterations.
      std::string
      contact_linear_solver() const
      {
        return distributed ? distributed->linear_solver_name() : mechanics.linear_solver_name();
      }

      mechanics::ContactProblem<dim> &mechanics;
      flow::FlowModel<dim>           &flow;

    private:
      /// g_p: contact mechanics with x = p_E, then flow with the resulting u; gx = p_E(flow).
      void
      map_pressure(const Vector<double> &x, Vector<double> &gx);
      /// g_u on y = (cell means of div u, face jumps [u]_n): flow, then mechanics.
      void
      map_displacement(const Vector<double> &y, Vector<double> &gy);

      void
      solve_mechanics(const Vector<double> &p_E_all);
      /// Sets (u, lambda) of the contact problem(s).
      void
      set_mechanics_state(const Vector<double> &u, const Vector<double> &lambda);
      /// (div u per cell, [u]_n per face) of the current mechanics solution (rank 0's; collective).
      Vector<double>
      displacement_measures() const;
      /// Porosity base phi_0 + b (div u - div u^0) and apertures d_0 - [u]_n from y.
      void
      set_flow_inputs(const Vector<double> &y);
      void
      solve_flow();
      /// p_E per matrix cell and fracture cell of the current flow state (11d).
      Vector<double>
      flow_equivalent_pressure() const;

      const CouplingParameters parameters;
      /// The flow's matrix pore volumes: the Biot storage of (11d) (set by initialize()).
      std::shared_ptr<BiotStorage<dim>>                storage;
      ConditionalOStream                              &verbose;
      TimerOutput                                     &timer;
      const MPI_Comm                                   communicator;
      mechanics::DistributedContactProblem<dim> *const distributed;
      /// Processes on this machine that each solve the serial contact problem (1 if it is
      /// distributed): its memory checks count that many copies.
      const unsigned int          contact_copies_per_machine;
      std::array<unsigned int, 5> linear_totals{{0, 0, 0, 0, 0}};
      const unsigned int          n_matrix, n_fracture;

      double         dt = 0;
      Vector<double> p_E;     ///< current (matrix cells, then fracture faces)
      Vector<double> p_E_old; ///< accepted
      Vector<double> p_E_initial;
      Vector<double> y_initial; ///< div u^0, [u^0]_n
      Vector<double> y_old;     ///< accepted
      /// The accepted states before p_E_old and y_old, and the step between them (0: none yet).
      Vector<double> p_E_older, y_older;
      double         dt_old = 0;
      /// x_old + (dt/dt_old)(x_old - x_older) with Extrapolate initial guess, else x_old.
      Vector<double>
      initial_guess(const Vector<double> &x_old, const Vector<double> &x_older) const;
      Vector<double>                            u_old;      ///< accepted displacement
      Vector<double>                            lambda_old; ///< accepted multipliers
      std::vector<Tensor<1, dim>>               jump_old;
      typename flow::TwoPhaseSolver<dim>::State flow_guess;
      CoupledStepReport                         report;
    };
  } // namespace coupling
} // namespace porofrac

#endif
