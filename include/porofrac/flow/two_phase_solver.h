// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_TWO_PHASE_SOLVER_H
#define POROFRAC_FLOW_TWO_PHASE_SOLVER_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <porofrac/flow/laws.h>
#include <porofrac/flow/tpfa_grid.h>

#include <array>
#include <map>
#include <vector>

namespace porofrac
{
  namespace flow
  {
    /// Stopping rules of the flow Newton method (specs.md 1.1).
    struct NewtonParameters
    {
      unsigned int max_iterations     = 50;
      /// Stop when ||R||_2 / ||R_0||_2 < residual_tolerance ...
      double residual_tolerance = 1e-5;
      /// ... or max |delta p| / max |p| < update_tolerance ...
      double update_tolerance = 1e-4;
      /// ... and, in both cases, the relative mass defect of each phase < mass_tolerance.
      double mass_tolerance = 1e-11;
      /// Largest change of a node's capillary pressure per iteration, in units of the pressure
      /// scale (R or P_r) of its rock's saturation law; 0 = no limit.
      double capillary_chop = 1.;
      /// Jacobian only: use the entry slope S'(0+) instead of 0 where p_c <= 0 (inexact Newton
      /// across the kink of S at p_c = 0). false = exact analytic Jacobian.
      bool entry_slope = true;
      /// Number of Newton iterations per step that use the entry slope.
      unsigned int entry_slope_iterations = 1000;
      /// Newton: a node leaving the two-phase region (p_c > 0 to p_c < 0) stops at p_c = 0 first.
      bool kink_stop = true;
    };

    /// Outcome of one implicit Euler step.
    struct StepResult
    {
      bool                  converged  = false;
      unsigned int          iterations = 0;
      std::array<double, 2> mass_defect{{0., 0.}};
    };

    /**
     * Implicit Euler, fully coupled two-phase TPFA (paper scheme (11a), specs.md 3b), with the
     * phase pressures (p^w, p^nw) of every non-Dirichlet flow node as unknowns, S^nw = S_rock(p^nw
     * - p^w), phase-potential upwinding of the mobilities, and Newton's method with the analytic
     * Jacobian and UMFPACK.
     *
     * Interface and intersection unknowns are solved monolithically with the cell unknowns (not
     * eliminated by a local solver); they are massless, so their rows are pure flux balances.
     *
     * Equations (multiplied by dt, i.e. in units of volume): for node i and phase alpha,
     *   PV_i (S^alpha_i - S^alpha_i,old) + dt sum_c F^alpha_c = 0,
     *   F^alpha_c = T_c eta^alpha(S_up) (p^alpha_a - p^alpha_b), up = a if p^alpha_a >= p^alpha_b.
     */
    template <int dim>
    class TwoPhaseSolver
    {
    public:
      /// Per flow node: {p^w, p^nw} in Pa.
      using State = std::vector<std::array<double, 2>>;

      TwoPhaseSolver(const TpfaGrid<dim>              &grid,
                     const std::array<RockType, 2>    &rocks,
                     const NewtonParameters           &parameters);

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

      /// Global unknown index of node @p i and phase @p phase (invalid for Dirichlet nodes).
      unsigned int
      dof(const unsigned int i, const unsigned int phase) const
      {
        return node_dof[i] == numbers::invalid_unsigned_int ? numbers::invalid_unsigned_int :
                                                               2 * node_dof[i] + phase;
      }

      /// Residual and, if @p jacobian, its analytic derivative with respect to the unknowns.
      void
      assemble(const State &state, const State &old, const double dt, Vector<double> &residual,
               SparseMatrix<double> *jacobian) const;

      /// Non-wetting saturation of node i in @p state, with rock @p rock.
      double
      saturation(const State &state, const unsigned int i, const Rock rock) const
      {
        return rocks[rock].saturation.saturation(state[i][1] - state[i][0]);
      }

      /// Mass (pore volume) of each phase over non-Dirichlet nodes, with the pore volumes of
      /// @p state (or, if given, @p pore_volumes).
      std::array<double, 2>
      phase_volumes(const State &state, const std::vector<double> *pore_volumes = nullptr) const;

      /// Per phase: |mass change + dt * net outflow into Dirichlet nodes| / max(total pore
      /// volume, dt * sum of |boundary fluxes|), computed independently of the residual.
      std::array<double, 2>
      mass_defect(const State &state, const State &old, const double dt) const;

      /// Newton for one step from old_state to state (state holds the initial guess). Never
      /// throws on non-convergence: the result says converged = false.
      StepResult
      solve_time_step(const double dt, ConditionalOStream &verbose);

      /**
       * Starts a time step: old_state = state, and the pore volume of every node is stored as
       * the old one, so that the accumulation of scheme (11a) is (PV S)^{n+1} - (PV S)^n even
       * when porosity and apertures change between steps (coupled scenes).
       */
      void
      begin_time_step();

      /**
       * Biot storage of paper eq. (11d) in matrix cells: phi_K = porosity_base_K + (p_E,K -
       * p_E_reference_K) * inverse_biot_modulus, with p_E the equivalent pressure of the
       * current unknowns (implicit: residual and Jacobian include it). Without a call, phi_K is
       * the grid's porosity. Vectors per matrix cell (active cell index).
       */
      void
      set_biot_storage(const std::vector<double> &porosity_base,
                       const std::vector<double> &p_E_reference,
                       const double               inverse_biot_modulus,
                       const bool                 capillary_energy);
      /// Replaces porosity_base (phi_0 + b div(u - u_0) from the mechanics).
      void
      set_porosity_base(const std::vector<double> &porosity_base);

      /**
       * p_E = sum_alpha p^alpha s^alpha - U(p_c) of node i (11d) with its rock's laws; without
       * U if the Biot storage was set with capillary_energy = false (Remark 3.1). Matrix cells
       * are nodes 0..n_matrix_cells-1, the fracture cell of CutMesh fracture face f is node
       * n_matrix_cells + f.
       */
      double
      equivalent_pressure(const State &s, const unsigned int i) const;
      /// Porosity of matrix cell K in state @p s (the Biot law if set, else the grid's).
      double
      porosity(const State &s, const unsigned int K) const;
      /// Pore volume of node i in state @p s (|K| phi_K, |sigma| d_f, 0 for massless nodes).
      double
      pore_volume(const State &s, const unsigned int i) const;

      /// Energy exchanged during a step (paper estimate (19), doc/coupling.md).
      struct EnergyExchange
      {
        /// dt sum_alpha sum_c F^alpha_c (p^alpha_a - p^alpha_b) over every connection with an
        /// unknown end (>= 0 with upwinded, non-negative mobilities).
        double dissipation = 0;
        /// -dt sum_alpha sum_c F^alpha_{a->b} p^alpha_b over connections to Dirichlet nodes b:
        /// the energy supplied through the Dirichlet boundaries.
        double boundary_work = 0;
      };
      EnergyExchange
      energy_exchange(const State &s, const double dt) const;

      State state;
      State old_state;
      /// If positive, the residual tolerance is relative to max(|R_0|, residual_scale) instead
      /// of |R_0|: warm-started solves inside coupled iterations start next to the solution, so
      /// |R_0| is no scale for them (the coupler passes the residual of the step's old state).
      double residual_scale = 0;
      /// Optional: times "Flow: assembly" and "Flow: linear solve (UMFPACK)".
      TimerOutput *timer = nullptr;

      const TpfaGrid<dim>          &grid;
      const std::array<RockType, 2> rocks;
      const NewtonParameters        parameters;

      SparsityPattern      sparsity;
      SparseMatrix<double> jacobian;

    private:
      std::vector<double>       old_pore_volume; ///< empty until begin_time_step()
      bool                      biot_storage = false;
      std::vector<double>       porosity_base, p_E_reference;
      double                    inverse_biot_modulus = 0;
      bool                      capillary_energy     = true;
      /// d p_E / d (p^w, p^nw) of node i.
      std::array<double, 2>
      equivalent_pressure_derivatives(const State &s, const unsigned int i) const;
      std::vector<unsigned int> node_dof;
      unsigned int              n_free;
      double                    total_pore_volume() const;
      double                    pressure_scale(const Rock rock) const;
      double                    slope(const RockType &rock, const double pc) const;
      mutable bool              entry_slope_active = false;
      double                    mean_pore_volume   = 0;

      /// Phase flux a -> b over connection c with derivatives with respect to
      /// (p^w_a, p^nw_a, p^w_b, p^nw_b).
      double
      flux(const typename TpfaGrid<dim>::Connection &c, const State &state, const unsigned int phase,
           std::array<double, 4> &derivative) const;
    };
  } // namespace flow
} // namespace porofrac

#endif
