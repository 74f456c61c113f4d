// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/distributed_linear_solver.h>
#include <porofrac/base/mumps_factorization.h>
#include <porofrac/base/registry.h>

namespace porofrac
{
  namespace
  {
    /// MUMPS LU (MumpsFactorization) behind the distributed linear-solver seam: the symbolic
    /// analysis is kept for later matrices of the same object, as in Newton's method.
    class MumpsLinearSolver : public DistributedLinearSolver
    {
    public:
      explicit MumpsLinearSolver(const DistributedLinearSolverOptions &options)
          : lu(options.what)
      {
      }

      void
      initialize(const dealii::TrilinosWrappers::SparseMatrix &matrix) override
      {
        lu.factorize(matrix);
        stats.direct_workspace_retries = lu.workspace_retries();
      }

      void
      solve(const dealii::TrilinosWrappers::MPI::Vector &b,
            dealii::TrilinosWrappers::MPI::Vector       &x,
            const double /*relative_tolerance*/) override
      {
        lu.solve(x, b);
        ++stats.solves;
      }

      std::string
      name() const override
      {
        return "mumps";
      }

    private:
      MumpsFactorization lu;
    };
  } // namespace

  std::unique_ptr<DistributedLinearSolver>
  create_distributed_linear_solver(const std::string                    &name,
                                   const std::string                    &parameter,
                                   const DistributedLinearSolverOptions &options)
  {
    return DistributedLinearSolverRegistry::instance().create(name, parameter, options);
  }

  POROFRAC_REGISTER(DistributedLinearSolverRegistry,
                    "mumps",
                    "sparse direct LU factorization by MUMPS (through Trilinos Amesos) on all "
                    "processes, its symbolic analysis reused for the Newton iterations.",
                    [](const DistributedLinearSolverOptions &options) {
                      return std::make_unique<MumpsLinearSolver>(options);
                    })
} // namespace porofrac
