// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/mumps_factorization.h>
#include <porofrac/mechanics/distributed_contact_linear_solver.h>

#include <memory>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /**
       * Distributed LU of the whole (u, lambda) Jacobian by MUMPS (through Trilinos Amesos):
       * the symbolic analysis once (the pattern of the Jacobian never changes), a numerical
       * factorization whenever a face row changed, otherwise only the triangular solves. With
       * `Reuse factorization iterations` > 0, a Jacobian whose face rows changed on fewer faces
       * than that is first solved by GMRES preconditioned with the last factors (only face rows
       * differ, a low-rank change), as the serial full-system solver does.
       */
      template <int dim>
      class DistributedDirectSolver : public DistributedContactLinearSolver<dim>
      {
      public:
        using VectorType = TrilinosWrappers::MPI::Vector;

        DistributedDirectSolver(const DistributedElasticitySystem<dim> &system,
                                const unsigned int                      reuse_iterations)
            : system(system)
            , jacobian(system, DistributedJacobian<dim>::Storage::whole_matrix)
            , lu("contact mechanics")
            , reuse_iterations(reuse_iterations)
        {
        }

        void
        solve(const FaceRows<dim> &rows,
              const unsigned int   n_changed_faces,
              const VectorType    &rhs,
              VectorType          &x) override
        {
          if (factorized && same_owned_rows(system, rows, factorized_rows))
            {
              Timer clock;
              lu.solve(x, rhs);
              this->stats.time_solves += clock.wall_time();
              return;
            }
          jacobian.assemble(rows);
          // Every process must take the same branch (both are collective); the face states of
          // faces a process does not own may lag, so its count of changed faces may differ.
          const unsigned int changed =
            Utilities::MPI::max(n_changed_faces, system.get_communicator());
          if (factorized && reuse_iterations > 0 && dim * changed < reuse_iterations &&
              this->solve_with_old_factors(
                jacobian.matrix(), OldFactors{lu}, rhs, x, reuse_iterations))
            return;
          factorize(rows);
          Timer clock;
          lu.solve(x, rhs);
          this->stats.time_solves += clock.wall_time();
        }

        void
        reset() override
        {
          factorized      = false;
          factorized_rows = FaceRows<dim>();
        }

        std::string
        name() const override
        {
          return "direct";
        }

      private:
        /// The last LU factors as a preconditioner.
        struct OldFactors
        {
          const MumpsFactorization &lu;
          void
          vmult(VectorType &dst, const VectorType &src) const
          {
            lu.solve(dst, src);
          }
        };

        void
        factorize(const FaceRows<dim> &rows)
        {
          Timer clock;
          lu.factorize(jacobian.matrix());
          factorized      = true;
          factorized_rows = rows;
          ++this->stats.factorizations;
          this->stats.direct_workspace_retries   = lu.workspace_retries();
          this->stats.estimated_direct_memory_mb = lu.estimated_memory_mb();
          this->stats.time_factorization += clock.wall_time();
        }

        const DistributedElasticitySystem<dim> &system;
        DistributedJacobian<dim>                jacobian;
        MumpsFactorization                      lu;
        const unsigned int                      reuse_iterations;
        bool                                    factorized = false;
        FaceRows<dim>                           factorized_rows;
      };

      const std::string description =
        "direct: MUMPS (through Trilinos Amesos) LU of the whole distributed (u, lambda) "
        "Jacobian, refactorized whenever a face row changed (after GMRES on the last factors "
        "with Reuse factorization iterations > 0).";

      template <int dim>
      std::unique_ptr<DistributedContactLinearSolver<dim>>
      make_direct_solver(const DistributedElasticitySystem<dim> &system,
                         const ContactParameters                &prm,
                         ConditionalOStream &,
                         TimerOutput &)
      {
        return std::make_unique<DistributedDirectSolver<dim>>(system, prm.reuse_iterations);
      }
    } // namespace

    POROFRAC_REGISTER(DistributedContactLinearSolverRegistry<2>,
                      "direct",
                      description,
                      make_direct_solver<2>)
    POROFRAC_REGISTER(DistributedContactLinearSolverRegistry<3>,
                      "direct",
                      description,
                      make_direct_solver<3>)
  } // namespace mechanics
} // namespace porofrac
