// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_DISTRIBUTED_LINEAR_SOLVER_H
#define POROFRAC_BASE_DISTRIBUTED_LINEAR_SOLVER_H

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <porofrac/base/amg_preconditioner.h>
#include <porofrac/base/linear_solver.h>

#include <memory>
#include <string>

namespace porofrac
{
  /// Linear solvers for Trilinos (Epetra) matrices and vectors distributed over MPI processes.
  using DistributedLinearSolver =
    LinearSolver<dealii::TrilinosWrappers::SparseMatrix, dealii::TrilinosWrappers::MPI::Vector>;

  /// What a distributed solver is told about the system it will solve.
  struct DistributedLinearSolverOptions
  {
    /// Unknowns per node, numbered consecutively (node k owns unknowns b k, ..., b k + b - 1):
    /// the point blocks of AMG and the equations/unknowns a CPR pressure stage sums.
    unsigned int block_size = 1;
    /// Krylov iterations after which an iterative solver hands the system to MUMPS.
    unsigned int max_iterations = 200;
    /// The AMG of iterative solvers (Trilinos ML): aggregation threshold and scheme.
    AmgSettings amg;
    /// Names the system in failure messages.
    std::string what = "linear system";
  };

  using DistributedLinearSolverRegistry =
    Registry<DistributedLinearSolver, const DistributedLinearSolverOptions &>;

  /// A new instance of the distributed linear solver registered as @p name; an InputError
  /// naming @p parameter if there is none.
  std::unique_ptr<DistributedLinearSolver>
  create_distributed_linear_solver(const std::string                    &name,
                                   const std::string                    &parameter,
                                   const DistributedLinearSolverOptions &options);
} // namespace porofrac

#endif
