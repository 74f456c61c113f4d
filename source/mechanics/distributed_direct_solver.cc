// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/distributed_contact_linear_solver.h>

#include <memory>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /**
       * Distributed LU of the whole (u, lambda) Jacobian by MUMPS (through Trilinos Amesos):
       * the symbolic analysis once (the pattern of the Jacobian never changes), a numerical
       * factorization whenever a face row changed, otherwise only the triangular solves.
       */
      template <int dim>
      class DistributedDirectSolver : public DistributedContactLinearSolver<dim>
      {
      public:
        using VectorType = TrilinosWrappers::MPI::Vector;

        explicit DistributedDirectSolver(const DistributedElasticitySystem<dim> &system)
            : system(system)
            , jacobian(system)
        {
        }

        void
        solve(const FaceRows<dim> &rows,
              const unsigned int,
              const VectorType &rhs,
              VectorType       &x) override
        {
          if (!factorized || !same_owned_rows(system, rows, factorized_rows))
            factorize(rows);
          Timer clock;
          problem.SetLHS(&x.trilinos_vector());
          problem.SetRHS(const_cast<Epetra_MultiVector *>(&rhs.trilinos_vector()));
          check(solver->Solve(), "solve");
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
        void
        factorize(const FaceRows<dim> &rows)
        {
          Timer clock;
          jacobian.assemble(rows);
          if (!solver)
            {
              problem.SetOperator(
                const_cast<Epetra_CrsMatrix *>(&jacobian.matrix().trilinos_matrix()));
              Amesos factory;
              solver.reset(factory.Create("Amesos_Mumps", problem));
              if (!solver)
                throw SolverFailure("contact mechanics: Amesos has no MUMPS");
              check(solver->SymbolicFactorization(), "symbolic factorization");
            }
          check(solver->NumericFactorization(), "factorization");
          factorized      = true;
          factorized_rows = rows;
          ++this->stats.factorizations;
          this->stats.time_factorization += clock.wall_time();
        }

        static void
        check(const int status, const char *what)
        {
          if (status != 0)
            throw SolverFailure(std::string("contact mechanics: MUMPS ") + what +
                                " failed (Amesos status " + std::to_string(status) + ")");
        }

        const DistributedElasticitySystem<dim> &system;
        DistributedJacobian<dim>                jacobian;
        Epetra_LinearProblem                    problem;
        std::unique_ptr<Amesos_BaseSolver>      solver;
        bool                                    factorized = false;
        FaceRows<dim>                           factorized_rows;
      };

      const std::string description =
        "direct: MUMPS (through Trilinos Amesos) LU of the whole distributed (u, lambda) "
        "Jacobian, refactorized whenever a face row changed.";

      template <int dim>
      std::unique_ptr<DistributedContactLinearSolver<dim>>
      make_direct_solver(const DistributedElasticitySystem<dim> &system,
                         const ContactParameters &,
                         ConditionalOStream &,
                         TimerOutput &)
      {
        return std::make_unique<DistributedDirectSolver<dim>>(system);
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
