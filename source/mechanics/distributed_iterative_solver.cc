// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/contact_block_preconditioner.h>
#include <porofrac/mechanics/distributed_contact_linear_solver.h>

#include <iomanip>
#include <memory>
#include <sstream>
#include <string>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /**
       * GMRES (right-preconditioned, restarted every 100 steps) on the whole (u, lambda)
       * Jacobian with the ContactBlockPreconditioner, to the relative residual the contact
       * iterations ask for (inexact steps). The preconditioner is set up when the face rows
       * change; its AMG hierarchy and G once.
       *
       * GMRES applies the Jacobian through the system's K and B_0^T and the face rows, so the
       * elasticity matrix is not copied.
       *
       * Safeguard: where the diagonal approximation of the multiplier Schur complement fails
       * (semi-smooth Newton rows with large lambda_n couplings, e.g. the second iterate from
       * the open guess, doc/parallel.md), GMRES stagnates; after Max linear iterations the step
       * is solved by the `direct` solver instead, and counted (statistics: direct fallbacks).
       * So is a step whose approximation is singular and cannot be factorized. Later steps with
       * the same face rows go to the direct solver at once, which reuses its factors.
       */
      template <int dim>
      class DistributedIterativeSolver : public DistributedContactLinearSolver<dim>
      {
      public:
        using VectorType = TrilinosWrappers::MPI::Vector;

        DistributedIterativeSolver(const DistributedElasticitySystem<dim> &system,
                                   const ContactParameters                &parameters,
                                   ConditionalOStream                     &progress,
                                   TimerOutput                            &timer)
            : system(system)
            , parameters(parameters)
            , jacobian(system, DistributedJacobian<dim>::Storage::face_rows)
            , progress(progress)
            , timer(timer)
        {
          TimerOutput::Scope t(timer, "Mechanics: AMG and multiplier block setup");
          preconditioner =
            std::make_unique<ContactBlockPreconditioner<dim>>(system,
                                                              parameters.amg_smoothed_prolongator,
                                                              parameters.schur_scaling);
        }

        void
        set_tolerance(const double relative) override
        {
          tolerance = relative;
        }

        void
        solve(const FaceRows<dim> &rows,
              const unsigned int   n_changed_faces,
              const VectorType    &rhs,
              VectorType          &x) override
        {
          Timer clock;
          if (!ready || !same_owned_rows(system, rows, current_rows))
            {
              jacobian.assemble(rows);
              set_up_preconditioner(rows);
              current_rows  = rows;
              ready         = true;
              gmres_stalled = false;
              ++this->stats.factorizations;
              this->stats.time_factorization += clock.wall_time();
              clock.restart();
            }
          x = 0;
          if (!preconditioner_usable)
            solve_directly(rows,
                           n_changed_faces,
                           rhs,
                           x,
                           "the preconditioner's Schur complement approximation is singular");
          else if (gmres_stalled)
            solve_directly(
              rows, n_changed_faces, rhs, x, "GMRES did not converge with these face rows before");
          else
            solve_by_gmres(rows, n_changed_faces, rhs, x);
          this->stats.direct_workspace_retries =
            (fallback ? fallback->statistics().direct_workspace_retries : 0) +
            preconditioner->workspace_retries();
          this->stats.time_solves += clock.wall_time();
        }

        void
        reset() override
        {
          ready = false;
          if (fallback)
            fallback->reset();
        }

        std::string
        name() const override
        {
          return "iterative";
        }

      private:
        /// The preconditioner for @p rows; where its Schur complement approximation S~ is
        /// singular (multipliers that load no displacement and whose face rows leave them free,
        /// doc/algorithms.md §2.1), the steps with these rows are solved by MUMPS instead.
        void
        set_up_preconditioner(const FaceRows<dim> &rows)
        {
          try
            {
              preconditioner->set_rows(rows);
              preconditioner_usable = true;
            }
          catch (const SolverFailure &failure)
            {
              preconditioner_usable = false;
              progress << "    " << failure.what() << std::endl;
            }
        }

        void
        solve_by_gmres(const FaceRows<dim> &rows,
                       const unsigned int   n_changed_faces,
                       const VectorType    &rhs,
                       VectorType          &x)
        {
          SolverControl           control(parameters.max_linear_iterations,
                                tolerance * rhs.l2_norm(),
                                false,
                                false);
          SolverGMRES<VectorType> gmres(control,
                                        typename SolverGMRES<VectorType>::AdditionalData(102,
                                                                                         true));
          try
            {
              gmres.solve(jacobian, x, rhs, *preconditioner);
            }
          catch (const SolverControl::NoConvergence &)
            {
              gmres_stalled = true;
              std::ostringstream reason;
              reason << "GMRES did not reach " << tolerance << " in "
                     << parameters.max_linear_iterations << " iterations";
              x = 0;
              solve_directly(rows, n_changed_faces, rhs, x, reason.str());
            }
          this->stats.linear_iterations += control.last_step();
        }

        /// The step by the `direct` solver (MUMPS on the whole Jacobian, its factors kept while
        /// the face rows do not change), counted as a direct fallback; @p reason goes to the
        /// progress output.
        void
        solve_directly(const FaceRows<dim> &rows,
                       const unsigned int   n_changed_faces,
                       const VectorType    &rhs,
                       VectorType          &x,
                       const std::string   &reason)
        {
          if (!fallback)
            fallback = DistributedContactLinearSolverRegistry<dim>::instance().create(
              "direct", "Mechanics/Distributed linear solver", system, parameters, progress, timer);
          const ContactLinearSolverStatistics before = fallback->statistics();
          fallback->solve(rows, n_changed_faces, rhs, x);
          const ContactLinearSolverStatistics &after = fallback->statistics();
          ++this->stats.direct_fallbacks;
          this->stats.fallback_factorizations    = after.factorizations;
          this->stats.reused_factorizations      = after.reused_factorizations;
          this->stats.estimated_direct_memory_mb = after.estimated_direct_memory_mb;
          std::ostringstream how;
          if (after.factorizations > before.factorizations)
            how << "factorized, estimated memory " << std::fixed << std::setprecision(1)
                << after.estimated_direct_memory_mb / 1024. << " GB";
          else if (after.reused_factorizations > before.reused_factorizations)
            how << "GMRES preconditioned by its last factors";
          else
            how << "its last factors";
          progress << "    " << reason << "; MUMPS solved this step (" << how.str() << ")"
                   << std::endl;
        }

        const DistributedElasticitySystem<dim>          &system;
        const ContactParameters                          parameters;
        double                                           tolerance = 1e-8;
        DistributedJacobian<dim>                         jacobian;
        ConditionalOStream                              &progress;
        TimerOutput                                     &timer;
        std::unique_ptr<ContactBlockPreconditioner<dim>> preconditioner;
        /// The `direct` solver, made on the first fallback.
        std::unique_ptr<DistributedContactLinearSolver<dim>> fallback;
        bool                                                 ready                 = false;
        bool                                                 preconditioner_usable = false;
        /// GMRES failed with the current face rows: their later steps go to the fallback.
        bool          gmres_stalled = false;
        FaceRows<dim> current_rows;
      };

      const std::string description =
        "iterative: GMRES on the whole distributed (u, lambda) Jacobian, preconditioned by a "
        "block upper-triangular preconditioner (smoothed-aggregation AMG with the rigid-body "
        "modes on the elasticity block, the multiplier Schur complement approximated with "
        "diag(K), factorized by MUMPS; doc/parallel.md), to the relative residual "
        "min(Linear solver tolerance, Linear solver forcing x the contact residual); a step "
        "whose GMRES does not converge in Max linear iterations, or whose Schur complement "
        "approximation is singular, is solved by the direct solver (as are later steps with the "
        "same face rows, which reuse its factors).";

      template <int dim>
      std::unique_ptr<DistributedContactLinearSolver<dim>>
      make_iterative_solver(const DistributedElasticitySystem<dim> &system,
                            const ContactParameters                &parameters,
                            ConditionalOStream                     &progress,
                            TimerOutput                            &timer)
      {
        return std::make_unique<DistributedIterativeSolver<dim>>(system,
                                                                 parameters,
                                                                 progress,
                                                                 timer);
      }
    } // namespace

    POROFRAC_REGISTER(DistributedContactLinearSolverRegistry<2>,
                      "iterative",
                      description,
                      make_iterative_solver<2>)
    POROFRAC_REGISTER(DistributedContactLinearSolverRegistry<3>,
                      "iterative",
                      description,
                      make_iterative_solver<3>)
  } // namespace mechanics
} // namespace porofrac
