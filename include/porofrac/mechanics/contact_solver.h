// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_CONTACT_SOLVER_H
#define POROFRAC_MECHANICS_CONTACT_SOLVER_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/vector.h>

#include <porofrac/mechanics/contact_law.h>
#include <porofrac/mechanics/contact_linear_solver.h>
#include <porofrac/mechanics/contact_method.h>
#include <porofrac/mechanics/elasticity_system.h>
#include <porofrac/mechanics/friction_field.h>
#include <porofrac/mechanics/parameters.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /// What one solve of the contact problem did (wall times in s).
    struct ContactStatistics
    {
      unsigned int iterations = 0;
      bool         converged  = false;
      /// Relative residual of every iterate (the stopping criterion).
      std::vector<double> residual_history;
      /// Diagnostic: |G(x_k)| / |G(x_0)| with G of eq. (27) unscaled (mechanical rows in N,
      /// C_n in Pa, C_tau in Pa^2), x_0 the initial guess: one reading of the paper's
      /// "relative residual" (not used for stopping).
      std::vector<double> initial_relative_history;
      /// The three terms of the stopping test at every iterate (doc/algorithms.md §1.3): |C| /
      /// |lambda|, |f - K u - B^T lambda| / |f| and the slip of stick faces over the slip
      /// scale; residual_history holds their maximum.
      std::vector<std::array<double, 3>> residual_terms_history;
      /// Face states each Newton step was computed with (open, stick, slip) and how many faces
      /// changed state from the previous step's.
      std::vector<std::array<unsigned int, 4>> face_state_history;
      /// Step lengths taken (1 = full step), line-search backtracks, active-set cycles.
      std::vector<double> step_history;
      unsigned int        backtracks      = 0;
      unsigned int        cycles_detected = 0;
      /// Factorizations of this solve, and solves done by GMRES on older factors.
      unsigned int factorizations = 0, reused_factorizations = 0;
      /// Krylov iterations of an iterative linear solver over this solve, its steps solved
      /// directly because GMRES did not converge, and the factorizations these took.
      unsigned int linear_iterations = 0, direct_fallbacks = 0, fallback_factorizations = 0;
      /// MUMPS factorizations of this solve repeated with a larger workspace.
      unsigned int direct_workspace_retries = 0;
      /// Time in computing the face rows, factorizing, triangular solves, and residual and
      /// line-search evaluations; set-up of the Schur complement (first solve only).
      double time_contact_rows = 0, time_factorization = 0, time_solves = 0, time_residuals = 0,
             time_cholesky = 0, time_form_W = 0;
    };

    /**
     * The nonlinear iteration of the contact problem (paper Section 5.1): at each iterate the
     * contact method gives the face rows, the linear solver the Newton step on (u, lambda),
     * and the globalization of the deck (all off by default: the paper's plain method) chooses
     * the step length:
     * - a backtracking (Armijo) line search on the merit max(|C| / |lambda|, |r_mech| / |f|) of
     *   (25)-(26), optionally non-monotone, from the start or once the residual stagnates;
     * - damping of steps that revisit the face states of an earlier, non-consecutive iterate;
     * - continuation in c (the complementarity functions have the same zeros for every c > 0).
     * Stops when the relative residual is below the tolerance at the target c.
     *
     * @p System is the serial ElasticitySystem or the DistributedElasticitySystem (the
     * interface is described with ElasticitySystem). With more than one process, each
     * computes the rows of the faces it owns; norms are summed and face-state comparisons voted
     * over all processes, so that every process takes the same steps.
     */
    template <int dim, typename System = ElasticitySystem<dim>>
    class ContactSolver
    {
    public:
      using VectorType = typename System::VectorType;

      ContactSolver(const System             &system,
                    const FrictionField<dim> &friction,
                    const ContactParameters  &parameters,
                    ConditionalOStream       &progress,
                    TimerOutput              &timer);

      /**
       * Iterates from (u, lambda), or from the deck's initial guess when @p cold_start, until
       * convergence; leaves the last iterate in (u, lambda). Throws SolverFailure after
       * max_iterations. At least one iteration is always done, so that small load changes
       * (finite differences of a coupled map) are resolved exactly; with an unchanged active
       * set it costs one solve with the stored factorization.
       */
      const ContactStatistics &
      solve(VectorType &u, VectorType &lambda, const bool cold_start);

      /// Forgets what depends on face rows (the next solve refactorizes); keeps what depends
      /// on the mesh only (K, its Cholesky factors, W).
      void
      reset();
      /**
       * Time-dependent problems: the face jumps [u_old]_sigma (global frame) of the previous
       * time step, from which the Coulomb conditions (25) count the tangential jump
       * [u - u_old]_tau. Without a call (static problems) u_old = 0.
       */
      void
      set_previous_jumps(const std::vector<Tensor<1, dim>> &jumps);

      /// Forgets the linear solver altogether (after the system was set up again).
      void
      clear();

      /// Face state of face @p f with jump @p jump and multiplier @p lambda (global frame) with
      /// the target c.
      FaceState
      state(const Tensor<1, dim> &jump, const Tensor<1, dim> &lambda, const unsigned int f) const;
      /// Current friction coefficient of face @p f at jump @p jump (global frame).
      double
      friction(const Tensor<1, dim> &jump, const unsigned int f) const;

      /// Statistics of the last solve (also after a SolverFailure).
      const ContactStatistics &
      statistics() const
      {
        return stats;
      }

      /// Name of the linear solver in use ("" before the first solve).
      std::string
      linear_solver_name() const;
      /// Statistics of the linear solver over all solves (null before the first solve).
      const ContactLinearSolverStatistics *
      linear_solver_statistics() const;

    private:
      using LinearSolver = ContactLinearSolver<dim, System>;

      /// Squared, |sigma|-weighted norms at (u, lambda) with parameter c: scaled complementarity
      /// residual (25)-(26), multipliers, c [u]; mechanical residual and load.
      struct ResidualParts
      {
        double contact = 0, lambda = 0, c_jump = 0, mechanical = 0, load = 0;
        /// |sigma|-weighted squared norm of the unscaled (25)-(26) (C_tau in Pa^2).
        double contact_unscaled = 0;
        /// |sigma|-weighted squared norms of [u]_tau over the stick faces, and of [u] over all
        /// faces; the face measure |Gamma| and max |u| over the displacement dofs.
        double stick_slip = 0, jump = 0, measure = 0, u_max = 0;
      };
      ResidualParts
      residual_parts(const VectorType &u, const VectorType &lambda, const double c) const;
      /// Line-search merit: relative contact and mechanical residuals, multiplier scale given.
      static double
      merit(const ResidualParts &r, const double scale2);
      /// |C| / |lambda|, |f - K u - B^T lambda| / |f| and |[u]_tau on stick faces| / slip scale
      /// at the target c (doc/algorithms.md §1.3); the relative residual is their maximum. |c [u]|
      /// scales C when lambda is zero or round-off against it.
      std::array<double, 3>
      stopping_terms(const VectorType &u, const VectorType &lambda) const;
      /// Face-state counts (open, stick, slip) of @p states over all processes, and how many
      /// faces differ from the last recorded states.
      std::array<unsigned int, 4>
      state_counts(const std::vector<FaceState> &states) const;
      /// Multiplier and jump of a face in its local frame (the tangential jump counted from
      /// the previous jumps, if set), and its slip |[u]_tau| (total), from the face-mean jump
      /// @p jump and the multiplier @p lambda in the global frame.
      struct FaceValues
      {
        Tensor<1, dim> lambda, jump;
        double         slip = 0;
      };
      FaceValues
      local_values(const Tensor<1, dim> &jump,
                   const Tensor<1, dim> &lambda,
                   const unsigned int    f) const;
      /// The same value on every process: whether @p a and @p b agree on every face.
      bool
      same_states(const std::vector<FaceState> &a, const std::vector<FaceState> &b) const;
      /// The local law of face @p f at slip @p slip with parameter @p c.
      LocalContactLaw<dim>
      local_law(const unsigned int f, const double slip, const double c) const;

      void
      set_initial_guess(VectorType &u, VectorType &lambda) const;
      /// Right-hand side (mechanical residual, face residuals) and face rows at (u, lambda).
      void
      linearize(const VectorType       &u,
                const VectorType       &lambda,
                const double            c,
                FaceRows<dim>          &rows,
                VectorType             &rhs,
                std::vector<FaceState> &states) const;
      /// The step factor of the cycling safeguard for face states @p states.
      double
      cycle_damping_factor(const std::vector<FaceState> &states, const unsigned int iteration);
      /// Chooses the step length along @p delta from (u_old, lambda_old) and sets (u, lambda).
      double
      take_step(const VectorType &u_old,
                const VectorType &lambda_old,
                const VectorType &delta,
                const double      alpha_max,
                const double      c,
                VectorType       &u,
                VectorType       &lambda);
      /// Stops the iterations (Interrupted, on every process) if any process got a signal.
      void
      stop_if_interrupted() const;
      /// Resets the statistics of a solve; creates the method and the linear solver if needed.
      void
      prepare();
      /// The Newton step: J delta = rhs to the tolerance the last residual asks for.
      void
      solve_linear_system(const FaceRows<dim>          &rows,
                          const std::vector<FaceState> &states,
                          const VectorType             &rhs,
                          VectorType                   &delta);
      /// Linear-solver counts and times of this solve since @p start.
      void
      record_linear_statistics(const ContactLinearSolverStatistics &start);
      /// One progress line per iteration.
      void
      report_iteration(const double residual, const double alpha, const double c_now);

      /// The message of a linear solve that failed in the current contact iteration.
      std::string
      linear_failure_message(const std::string &reason) const;

      const System             &system;
      const FrictionField<dim> &friction_field;
      const ContactParameters  &prm;
      ConditionalOStream       &progress;
      TimerOutput              &timer;

      std::unique_ptr<ContactMethod<dim>> method;
      std::string                         method_name;
      std::unique_ptr<LinearSolver>       linear_solver;

      /// State of the current solve: its statistics, the face states of every iterate (for
      /// the cycling safeguard) and whether the line search has been switched on.
      std::vector<Tensor<1, dim>>         previous_jump;
      ContactStatistics                   stats;
      std::vector<std::vector<FaceState>> seen_states;
      bool                                line_search_on = false;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
