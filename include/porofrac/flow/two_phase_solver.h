// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_TWO_PHASE_SOLVER_H
#define POROFRAC_FLOW_TWO_PHASE_SOLVER_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <porofrac/base/sparse_lu.h>
#include <porofrac/flow/laws.h>
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
    /// Stopping rules of the flow Newton method (specs.md 1.1).
    struct NewtonParameters
    {
      unsigned int max_iterations = 50;
      /// Stop when ||R||_2 / ||R_0||_2 < residual_tolerance ...
      double residual_tolerance = 1e-5;
      /// ... or max |delta p| / max |p| < update_tolerance ...
      double update_tolerance = 1e-4;
      /// ... and, in both cases, the relative mass defect of each phase < mass_tolerance.
      double mass_tolerance = 1e-11;
      /// Largest change of a node's capillary pressure per iteration, in units of the pressure
      /// scale (R or P_r) of its rock's saturation law; 0 = no limit.
      double capillary_chop = 1.;
      /// Largest change of a node's non-wetting saturation per iteration (Appleyard chop); at
      /// interface nodes under both the matrix and the fracture law. 0 = no limit.
      double saturation_chop = 0.;
      /// Jacobian only: use the entry slope S'(0+) instead of 0 where p_c <= 0 (inexact Newton
      /// across the kink of S at p_c = 0). false = exact analytic Jacobian.
      bool entry_slope = true;
      /// Number of Newton iterations per step that use the entry slope.
      unsigned int entry_slope_iterations = 1000;
      /// Give up (so that the caller cuts the time step) after this many iterations in which
      /// neither the residual nor the mass defect fell below half its best value; 0 = never.
      unsigned int stagnation_iterations = 10;
      /// If positive, a stagnated solve whose last normalized update is below this value and
      /// whose mass defect meets mass_tolerance counts as converged (inner solves of a coupling
      /// loop ask for tighter tolerances than Newton's noise floor allows).
      double stagnation_update_tolerance = 0.;
      /// Mass-defect bound of that fallback (0: mass_tolerance).
      double stagnation_mass_tolerance = 0.;
      /// Newton: a node leaving the two-phase region (p_c > 0 to p_c < 0) stops at p_c = 0 first.
      bool kink_stop = true;
      /// Keep p_c >= 0 at every node (projection after each update; the Jacobian uses S'(0+) at
      /// the bound). With zero-entry-pressure laws S = 0 for p_c <= 0, so with no non-wetting
      /// mobility floor the bound does not change the solution: it removes the non-wetting
      /// pressure of a saturated node, which no equation determines, from the Newton iteration.
      bool capillary_bound = false;
      /// Backtracking: halve the update (at most line_search_steps times) while |R| grows.
      bool         line_search       = false;
      unsigned int line_search_steps = 4;
    };

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
     * Implicit Euler, fully coupled two-phase TPFA (paper scheme (11a), specs.md 3b), with the
     * phase pressures (p^w, p^nw) of every non-Dirichlet flow node as unknowns, S^nw = S_rock(p^nw
     * - p^w), phase-potential upwinding of the mobilities, and Newton's method with the analytic
     * Jacobian and UMFPACK.
     *
     * Interface and intersection unknowns are solved monolithically with the cell unknowns (not
     * eliminated by a local solver); they are massless, so their rows are pure flux balances.
     *
     * Equations (multiplied by dt, i.e. in units of volume): for node i and phase alpha,
     *   PV_i(p_i) S^alpha_i - PV_i,old S^alpha_i,old + dt sum_c F^alpha_c = 0,
     *   F^alpha_c = T_c eta^alpha(S_up) (p^alpha_a - p^alpha_b), up = a if p^alpha_a >= p^alpha_b.
     * PV_i,old is the pore volume stored by begin_time_step(), so porosity and aperture may change
     * between steps. The matrix pore volume is |K| phi_K with, after set_biot_storage(), the
     * linearised Biot storage of eq. (11d):
     *   phi_K = porosity_base_K + (p^E_K - p^E_ref,K) / M,
     *   p^E = sum_alpha p^alpha s^alpha - U(p_c) (eq. (6); without U with capillary_energy = false,
     *   Remark 3.1), which depends on the unknowns (residual and Jacobian include it).
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

      TwoPhaseSolver(const TpfaGrid<dim>           &grid,
                     const std::array<RockType, 2> &rocks,
                     const NewtonParameters        &parameters);

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
      assemble(const State          &state,
               const State          &old,
               const double          dt,
               Vector<double>       &residual,
               SparseMatrix<double> *jacobian) const;

      /// Non-wetting saturation of node i in @p state, with rock @p rock.
      double
      saturation(const State &state, const unsigned int i, const Rock rock) const
      {
        return rocks[rock].saturation.saturation(state[i][1] - state[i][0]);
      }

      /// Start of a time step: old_state = state, and stores the pore volume of every node
      /// (grid porosity or Biot porosity of old_state, current grid.aperture) as PV_old.
      void
      begin_time_step();

      /**
       * Biot storage in matrix cells (eq. (11d)): phi_K = porosity_base[K] + (p^E_K -
       * p_E_reference[K]) * inverse_biot_modulus, vectors per matrix cell (active_cell_index),
       * p^E with the capillary energy U of the rock's law if @p capillary_energy (paper eq. (6)),
       * else sum_alpha p^alpha s^alpha (Remark 3.1). Without a call, phi_K = grid.porosity[K].
       * Takes effect for the pore volume of the current state; PV_old is the one stored by
       * begin_time_step(). InputError("Flow/Biot modulus") for a negative or non-finite 1/M.
       */
      void
      set_biot_storage(const std::vector<double> &porosity_base,
                       const std::vector<double> &p_E_reference,
                       const double               inverse_biot_modulus,
                       const bool                 capillary_energy);

      /// Replaces porosity_base (e.g. phi_0 + b div(u - u_0) from the mechanics), keeping the
      /// reference p^E and 1/M of set_biot_storage() (without it: 1/M = 0).
      void
      set_porosity_base(const std::vector<double> &porosity_base);

      /// Equivalent pressure p^E = sum_alpha p^alpha s^alpha - U(p_c) of node @p node (matrix
      /// cell K = node K, fracture cell of fracture face f = node n_matrix_cells + f), with its
      /// rock's law; without U if capillary_energy = false in set_biot_storage().
      double
      equivalent_pressure(const State &state, const unsigned int node) const;

      /// Porosity phi_K of matrix cell @p K in @p state (see set_biot_storage()).
      double
      porosity(const State &state, const unsigned int K) const;

      /// Pore volume of node @p i in @p state: |K| phi_K(state), |sigma| d_f (grid.aperture), or 0.
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
      /// Optional: times "Flow: assembly" and "Flow: linear solve (UMFPACK)".
      TimerOutput *timer = nullptr;

      const TpfaGrid<dim>          &grid;
      const std::array<RockType, 2> rocks;
      const NewtonParameters        parameters;

      SparsityPattern      sparsity;
      SparseMatrix<double> jacobian;

    private:
      /// LU of the Jacobian; keeps the symbolic analysis of the fixed sparsity pattern.
      std::shared_ptr<SparseLU> lu;
      std::vector<unsigned int> node_dof;
      /// Pore volume of every node at begin_time_step().
      std::vector<double> old_pore_volume;
      /// Biot storage (set_biot_storage); biot = false: phi_K = grid.porosity[K].
      bool                biot = false;
      std::vector<double> porosity_base_, p_E_reference_;
      double              inverse_biot_modulus_ = 0;
      bool                capillary_energy_     = true;
      /// Pore volume of node i and its derivatives with respect to (p^w_i, p^nw_i).
      double
                   pore_volume(const State           &state,
                               const unsigned int     i,
                               std::array<double, 2> &derivative) const;
      unsigned int n_free;
      double
      total_pore_volume() const;
      double
      pressure_scale(const Rock rock) const;
      double
      slope(const RockType &rock, const double pc) const;
      /// The stagnation fallback of NewtonParameters: mass defect and normalized update small
      /// enough for a stalled solve to count as converged.
      bool
                   stagnation_fallback_holds(const double mass_defect, const double update) const;
      mutable bool entry_slope_active = false;
      double       mean_pore_volume   = 0;

      /// Phase flux a -> b over connection c with derivatives with respect to
      /// (p^w_a, p^nw_a, p^w_b, p^nw_b).
      double
      flux(const typename TpfaGrid<dim>::Connection &c,
           const State                              &state,
           const unsigned int                        phase,
           std::array<double, 4>                    &derivative) const;
    };
  } // namespace flow
} // namespace porofrac

#endif
