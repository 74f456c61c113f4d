// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_CONTACT_LINEAR_SOLVER_H
#define POROFRAC_MECHANICS_CONTACT_LINEAR_SOLVER_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/vector.h>

#include <porofrac/base/registry.h>
#include <porofrac/mechanics/elasticity_system.h>
#include <porofrac/mechanics/parameters.h>

#include <string>

namespace porofrac
{
  namespace mechanics
  {
    /// Work done by a contact linear solver since it was created (wall times in s).
    struct ContactLinearSolverStatistics
    {
      /// Factorizations (of the whole Jacobian, or of the dense Schur complement).
      unsigned int factorizations = 0;
      /// Solves done by GMRES preconditioned by older factors instead of a factorization.
      unsigned int reused_factorizations = 0;
      /// Krylov iterations of iterative solvers, and their steps solved directly instead.
      unsigned int linear_iterations = 0;
      unsigned int direct_fallbacks  = 0;
      /// Factorizations by the direct solver the Krylov solver fell back to (it reuses its
      /// factors while the face rows do not change).
      unsigned int fallback_factorizations = 0;
      /// MUMPS factorizations repeated with a larger workspace (MumpsFactorization).
      unsigned int direct_workspace_retries = 0;
      /// MUMPS's memory estimate for the last factorization (distributed direct solver), MB.
      double estimated_direct_memory_mb = 0;
      double time_factorization         = 0;
      double time_solves                = 0;
      /// Set-up that depends on the mesh only (Cholesky of K and W for the Schur complement).
      double time_cholesky = 0, time_form_W = 0;
    };

    /**
     * The linear solves of the contact iterations: J x = rhs for the Jacobian of the contact
     * problem (27), whose displacement rows are those of the ElasticitySystem (K and B^T, with
     * constraints) and whose multiplier rows are the face rows of the contact method. Only the
     * face rows change from one iteration to the next, and often only a few of them: solvers
     * keep what they can (factorizations, Schur complements) while rows do not change.
     *
     * Implementations register with ContactLinearSolverRegistry (deck entry
     * Mechanics/Linear solver, the name is the deck's value) for the serial ElasticitySystem,
     * and with DistributedContactLinearSolverRegistry (Mechanics/Distributed linear solver)
     * for the DistributedElasticitySystem: they receive the same rows, and vectors of the
     * system's VectorType.
     */
    template <int dim, typename System = ElasticitySystem<dim>>
    class ContactLinearSolver
    {
    public:
      using VectorType = typename System::VectorType;

      virtual ~ContactLinearSolver() = default;

      /**
       * Solves J x = rhs (rhs zero on constrained displacement dofs) with face rows @p rows.
       * @p n_changed_faces is the number of faces whose state changed since the previous call
       * (a hint for solvers that update old factors). Throws SolverFailure if it cannot.
       */
      virtual void
      solve(const FaceRows<dim> &rows,
            const unsigned int   n_changed_faces,
            const VectorType    &rhs,
            VectorType          &x) = 0;

      /// Iterative solvers: the relative residual the next solves must reach (inexact Newton
      /// steps); direct solvers ignore it.
      virtual void
      set_tolerance(const double)
      {
      }

      /// Forgets everything that depends on face rows (the next solve refactorizes).
      virtual void
      reset() = 0;

      /// What solves the systems, for reports ("full system", ...).
      virtual std::string
      name() const = 0;

      const ContactLinearSolverStatistics &
      statistics() const
      {
        return stats;
      }

    protected:
      /**
       * GMRES (right-preconditioned, relative residual 1e-12, at most @p max_steps steps) on
       * @p matrix with older LU factors @p factors (anything with vmult) as preconditioner, for
       * a Jacobian whose face rows changed on a few faces only; counted as a reused
       * factorization. False if it needs more steps (then the caller refactorizes).
       */
      template <typename MatrixType, typename Factors>
      bool
      solve_with_old_factors(const MatrixType  &matrix,
                             const Factors     &factors,
                             const VectorType  &rhs,
                             VectorType        &x,
                             const unsigned int max_steps)
      {
        dealii::Timer                   clock;
        dealii::SolverControl           control(max_steps, 1e-12 * rhs.l2_norm(), false, false);
        dealii::SolverGMRES<VectorType> gmres(
          control, typename dealii::SolverGMRES<VectorType>::AdditionalData(max_steps + 2, true));
        x         = 0;
        bool done = false;
        try
          {
            gmres.solve(matrix, x, rhs, factors);
            done = true;
            ++stats.reused_factorizations;
          }
        catch (const dealii::SolverControl::NoConvergence &)
          {
          }
        stats.time_solves += clock.wall_time();
        return done;
      }

      ContactLinearSolverStatistics stats;
    };

    template <int dim, typename System = ElasticitySystem<dim>>
    using ContactLinearSolverRegistry = Registry<ContactLinearSolver<dim, System>,
                                                 const System &,
                                                 const ContactParameters &,
                                                 ConditionalOStream &,
                                                 TimerOutput &>;
  } // namespace mechanics
} // namespace porofrac

#endif
