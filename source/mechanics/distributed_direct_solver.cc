// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/distributed_contact_linear_solver.h>
#include <porofrac/mechanics/mumps_factorization.h>

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
            , lu("contact mechanics")
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
        void
        factorize(const FaceRows<dim> &rows)
        {
          Timer clock;
          jacobian.assemble(rows);
          lu.factorize(jacobian.matrix());
          factorized      = true;
          factorized_rows = rows;
          ++this->stats.factorizations;
          this->stats.time_factorization += clock.wall_time();
        }

        const DistributedElasticitySystem<dim> &system;
        DistributedJacobian<dim>                jacobian;
        MumpsFactorization                      lu;
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
