// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_TWO_PHASE_SOLVER_H
#define POROFRAC_FLOW_TWO_PHASE_SOLVER_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <porofrac/base/linear_solver.h>
#include <porofrac/flow/distributed_newton_system.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/flow/rock_type.h>
#include <porofrac/flow/storage_model.h>
#include <porofrac/flow/tpfa_grid.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace porofrac
{
  namespace flow
  {
    /// Energy exchanged by the flow over one time step (coupled energy estimate, paper
    /// Section 4.2).
    struct EnergyExchange
    {
      /// dt sum_alpha sum_c F^alpha_c (p^alpha_a - p^alpha_b) over connections between two
      /// non-Dirichlet nodes (each term >= 0 by phase-potential upwinding).
      double dissipation = 0;
      /// -dt sum_alpha sum_{c with a Dirichlet end b} F^alpha_{c, a->b} p^alpha_b: the power
      /// supplied through Dirichlet nodes, plus dt sum |K| h^alpha p^alpha of the sources. The
      /// dissipation dt F (p_a - p_b) >= 0 of the connections to Dirichlet nodes is in neither
      /// term, so E^{n+1} - E^n + dissipation <= boundary_work.
      double boundary_work = 0;
    };

    /// Outcome of one implicit Euler step.
    struct StepResult
    {
      bool                  converged  = false;
      unsigned int          iterations = 0;
      std::array<double, 2> mass_defect{{0., 0.}};
      /// Why a step failed (empty if converged).
      std::string failure;
    };

    /**
     * Implicit Euler, fully coupled two-phase TPFA (paper scheme (11a)), with the phase
     * pressures (p^w, p^nw) of every non-Dirichlet flow node as unknowns, S^nw = S_rock(p^nw -
     * p^w), phase-potential upwinding of the mobilities, and Newton's method with the analytic
     * Jacobian and a registered linear solver (NewtonParameters::linear_solver).
     *
     * Interface and intersection unknowns are solved monolithically with the cell unknowns (not
     * eliminated by a local solver); they are massless, so their rows are pure flux balances.
     *
     * Equations (multiplied by dt, i.e. in units of volume): for node i and phase alpha,
     *   PV_i(p_i) S^alpha_i - PV_i,old S^alpha_i,old + dt sum_c F^alpha_c = 0,
     *   F^alpha_c = T_c eta^alpha(S_up) (p^alpha_a - p^alpha_b), up = a if p^alpha_a >= p^alpha_b.
     * PV_i,old is the pore volume stored by begin_time_step(), so porosity and aperture may change
     * between steps. The pore volume of a matrix cell comes from the StorageModel
     * (set_storage_model(); GridPorosity by default), which may depend on the cell's unknowns
     * (the Biot storage of eq. (11d)): residual and Jacobian include that dependence.
     * Node numbering (TpfaGrid): matrix cell K is node K (active_cell_index); the fracture cell
     * of CutMesh fracture face f is node n_matrix_cells + f.
     */
    template <int dim>
    class TwoPhaseSolver
    {
    public:
      /// Per flow node: {p^w, p^nw} in Pa.
      using State = std::vector<std::array<double, 2>>;
      /// Also reachable as TwoPhaseSolver<dim>::EnergyExchange.
      using EnergyExchange = flow::EnergyExchange;

      /// Without @p serial_pattern the Newton matrix is not built: distribute() must follow
      /// before the first Newton step, and builds the rows of this process only.
      TwoPhaseSolver(const TpfaGrid<dim>           &grid,
                     const std::array<RockType, 2> &rocks,
                     const NewtonParameters        &parameters,
                     const bool                     serial_pattern = true);

      /**
       * Shares the Newton systems with the other processes of @p communicator
       * (DistributedNewtonSystem): this process assembles the rows of the nodes i with
       * @p node_owner[i] equal to its rank, and the distributed linear solver
       * (NewtonParameters::distributed_linear_solver) solves on all of them. The unknowns are
       * renumbered process by process. The state, the pore volumes and everything computed
       * from them (mass defect, energy terms, chops) stay whole on every process, so all
       * processes take the same steps; with one process the results are the serial ones up to
       * the round-off of MUMPS against the serial linear solver.
       */
      void
      distribute(const MPI_Comm communicator, const std::vector<unsigned int> &node_owner);

      /// What the linear solver of the Newton steps (the distributed one after distribute())
      /// did, plus the statistics of the run before a restart (restore_linear_statistics()).
      LinearSolverStatistics
      linear_statistics() const
      {
        LinearSolverStatistics s = linear_before_restart;
        s +=
          distribution ? distribution->linear_solver().statistics() : linear_solver->statistics();
        s.reused_setups += reused_setups;
        return s;
      }

      /// Continues the counts of linear_statistics() from a checkpoint's.
      void
      restore_linear_statistics(const LinearSolverStatistics &before_restart)
      {
        linear_before_restart = before_restart;
      }

      std::string
      linear_solver_name() const
      {
        return distribution ? distribution->linear_solver().name() : linear_solver->name();
      }

      /// Whether distribute() was called.
      bool
      distributed() const
      {
        return distribution != nullptr;
      }

      /// Phase pressures of Dirichlet nodes, by boundary id, for matrix and fracture nodes.
      std::map<types::boundary_id, std::array<double, 2>> matrix_dirichlet;
      std::map<types::boundary_id, std::array<double, 2>> fracture_dirichlet;

      /// Sets every Dirichlet node of @p state to its boundary pressures.
      void
      apply_dirichlet(State &state) const;

      unsigned int
      n_unknowns() const
      {
        return 2 * n_free;
      }

      /// Nonzeros of the Newton matrix (after distribute(), of all processes' rows).
      types::global_dof_index
      n_nonzeros() const
      {
        return distribution ? distribution->n_nonzeros() : sparsity.n_nonzero_elements();
      }

      /// Global unknown index of node @p i and phase @p phase (invalid for Dirichlet nodes).
      unsigned int
      dof(const unsigned int i, const unsigned int phase) const
      {
        return node_dof[i] == numbers::invalid_unsigned_int ? numbers::invalid_unsigned_int :
                                                              2 * node_dof[i] + phase;
      }

      /// Residual and, if @p jacobian, its analytic derivative with respect to the unknowns.
      void
      assemble(const State          &state,
               const State          &old,
               const double          dt,
               Vector<double>       &residual,
               SparseMatrix<double> *jacobian) const;

      /// Non-wetting saturation of node i in @p state, with rock @p rock.
      double
      saturation(const State &state, const unsigned int i, const Rock rock) const
      {
        return rocks[rock].saturation->saturation(state[i][1] - state[i][0]);
      }

      /// Start of a time step: old_state = state, and stores the pore volume of every node
      /// (the storage model's at old_state, the current grid.aperture) as PV_old.
      void
      begin_time_step();

      /// The pore volume law of the matrix cells (kept alive by the solver). Takes effect for the
      /// pore volume of the current state; PV_old is the one stored by begin_time_step().
      void
      set_storage_model(const std::shared_ptr<const StorageModel> &storage);

      /// Pore volume of node @p i in @p state: the storage model's for a matrix cell, |sigma| d_f
      /// (grid.aperture) for a fracture cell, the damaged layer's for an interface, or 0.
      double
      pore_volume(const State &state, const unsigned int i) const;

      /// Mass (pore volume) of each phase over non-Dirichlet nodes, with pore_volume(state, i).
      std::array<double, 2>
      phase_volumes(const State &state) const;

      /// Per phase: |mass change + dt * net outflow into Dirichlet nodes| / max(total pore
      /// volume, dt * sum of |boundary fluxes|), computed independently of the residual; the
      /// old mass uses the pore volumes stored by begin_time_step() and @p old's saturations.
      std::array<double, 2>
      mass_defect(const State &state, const State &old, const double dt) const;

      /// Dissipation and boundary work of the step ending in @p state (see EnergyExchange).
      EnergyExchange
      energy_exchange(const State &state, const double dt) const;

      /// Phase flux a -> b over connection c (m^3/s) with derivatives with respect to
      /// (p^w_a, p^nw_a, p^w_b, p^nw_b).
      double
      flux(const typename TpfaGrid<dim>::Connection &c,
           const State                              &state,
           const unsigned int                        phase,
           std::array<double, 4>                    &derivative) const;
      /// Newton for one step from old_state to state (state holds the initial guess). Never
      /// throws on failure: converged = false (non-convergence, non-finite values, singular
      /// matrix).
      StepResult
      solve_time_step(const double dt, ConditionalOStream &verbose);

      /// Phase pressures (w, nw) of every node, relative to reference_pressure.
      State state;
      State old_state;
      /// Gauge of the stored pressures: state holds p - reference_pressure. Fluxes see only
      /// differences, but a node's pressure can move by no less than one ulp of its stored
      /// value; where the fractures conduct so well that one ulp of ~1e5 Pa moves more than the
      /// mass tolerance, storing deviations from the fractures' pressure keeps Newton's
      /// roundoff floor below it. p_E, the energy terms and outputs add it back.
      double reference_pressure = 0.;

      /// Absolute pressure of @p phase at node @p i of @p s.
      double
      pressure(const State &s, const unsigned int i, const unsigned int phase) const
      {
        return s[i][phase] + reference_pressure;
      }
      /// Volumetric source of each phase per node (m^3/s, already integrated over the node's
      /// weighted measure: |K| h^alpha_K of scheme (11a)); empty = no sources.
      std::vector<std::array<double, 2>> source;
      /// If positive, the residual tolerance is relative to max(|R_0|, residual_scale) instead
      /// of |R_0|: warm-started solves inside coupled iterations start next to the solution, so
      /// |R_0| is no scale for them (the coupler passes the residual of the step's old state).
      double residual_scale = 0;
      /// Optional: times "Flow: assembly" and "Flow: linear solve (<linear solver name>)".
      TimerOutput *timer = nullptr;

      const TpfaGrid<dim>          &grid;
      const std::array<RockType, 2> rocks;
      const NewtonParameters        parameters;

      SparsityPattern      sparsity;
      SparseMatrix<double> jacobian;

    private:
      /// Numbers the unknowns of the non-Dirichlet nodes, those of process 0 first if
      /// @p node_owner is not empty.
      void
      number_unknowns(const std::vector<unsigned int> &node_owner);
      /// Makes the sparsity pattern and the Jacobian: of all rows, or with @p node_owner of the
      /// rows of process @p rank's nodes only.
      void
      make_pattern(const std::vector<unsigned int> &node_owner, unsigned int rank);
      /// Whether this process assembles the rows of node @p i.
      bool
      assembles(const unsigned int i) const
      {
        return !distribution || owned_node[i];
      }
      /// Whether the Jacobian equals, value for value and on every process, the one the linear
      /// solver was last set up with; stores its values for the next call. Then the solver's
      /// factors or preconditioner are used again: a linear (single-phase) step factorizes once.
      bool
      jacobian_unchanged();
      /// The Jacobian values of the last linear-solver set-up (empty: none, or it failed).
      std::vector<double> set_up_jacobian;
      /// Solves with the set-up of an unchanged Jacobian (jacobian_unchanged()).
      unsigned long          reused_setups = 0;
      LinearSolverStatistics linear_before_restart;
      /// Solver of the Newton systems (it may keep set-up of the fixed sparsity pattern).
      std::shared_ptr<SerialLinearSolver> linear_solver;
      /// The shared Newton systems (distribute()), and which nodes this process assembles.
      std::unique_ptr<DistributedNewtonSystem> distribution;
      std::vector<bool>                        owned_node;
      std::shared_ptr<const StorageModel>      storage;
      std::vector<unsigned int>                node_dof;
      /// Pore volume of every node at begin_time_step().
      std::vector<double> old_pore_volume;
      /// Pore volume of node i and its derivatives with respect to (p^w_i, p^nw_i).
      double
                   pore_volume(const State           &state,
                               const unsigned int     i,
                               std::array<double, 2> &derivative) const;
      unsigned int n_free;
      double
      total_pore_volume() const;
      /// The capillary chop of node @p i: the largest change of its p_c per iteration (0: none).
      double
      capillary_chop_limit(const unsigned int i) const;
      /// The change @p dpc of node @p i's capillary pressure that Newton proposes, limited by the
      /// capillary chop (@p chop_limit, capillary_chop_limit(i)), the kink stop, the entry slope,
      /// the capillary bound and the saturation chop (NewtonParameters).
      double
      limit_capillary_change(const unsigned int i,
                             const double       pc_old,
                             double             dpc,
                             const double       chop_limit) const;
      /// Verbose: the node and phase of the largest residual entry.
      void
      report_largest_residual(const Vector<double> &residual, ConditionalOStream &verbose) const;
      /// update = J^{-1} residual, iterative solvers to the relative residual @p tolerance;
      /// false (and why) when the linear solver fails.
      bool
      solve_linear_system(const Vector<double> &residual,
                          Vector<double>       &update,
                          const double          tolerance,
                          std::string          &failure);
      /// Applies the Newton update (capillary and saturation chops, the dominant phase's
      /// pressure kept); returns the relative update max |dp| / max |p|.
      /// @p n_capillary_chopped: the number of nodes whose p_c update the capillary chop limited.
      double
      apply_update(const Vector<double> &update,
                   ConditionalOStream   &verbose,
                   unsigned int         &n_capillary_chopped);
      /// Backtracking from @p previous along the applied update while |R| > @p r; whether a
      /// step lowered |R|.
      bool
      line_search(const State        &previous,
                  const double        r,
                  const double        dt,
                  ConditionalOStream &verbose);
      /// Jacobian-only virtual compressibility of p^w at node @p i where the wetting phase is
      /// absent and immobile (no equation holds its pressure there).
      void
      hold_absent_wetting_pressure(const State          &s,
                                   const unsigned int    i,
                                   SparseMatrix<double> &J) const;
      /// Jacobian-only virtual compressibility on every phase row of the massless nodes
      /// @p massless whose diagonal is exactly 0 after assembly (no connection has the node's
      /// phase upstream with a mobility, and no mass holds its pressure).
      void
      hold_unheld_massless_pressures(const std::vector<unsigned int> &massless,
                                     SparseMatrix<double>            &J) const;
      /// Whether this iteration's Jacobian uses the entry slope (Entry slope in Jacobian in its
      /// first iterations, or the capillary bound).
      bool
      entry_slope_applies() const;
      /// Whether the Jacobian uses @p law's entry slope at @p pc: the entry slope applies, the
      /// non-wetting phase is absent (p_c <= p_e or S < 1e-12) and S'(p_c) is below half the
      /// entry slope.
      bool
      entry_slope_replaces_tangent(const SaturationLaw &law, const double pc) const;
      /// dS/dp_c of @p rock's law in the Jacobian: the law's entry slope where the non-wetting
      /// phase is absent and entry_slope_applies(), else the exact S'(p_c).
      double
      slope(const RockType &rock, const double pc) const;
      /// The stagnation fallback of NewtonParameters: mass defect and normalized update small
      /// enough for a stalled solve to count as converged.
      bool
                   stagnation_fallback_holds(const double mass_defect, const double update) const;
      mutable bool entry_slope_active = false;
      /// The Jacobian-only pore volume that holds the pressures no equation holds (massless
      /// nodes, absent phases): 1e-3 times the mean pore volume of the cells.
      double virtual_pore_volume = 0;
    };
  } // namespace flow
} // namespace porofrac

#endif
