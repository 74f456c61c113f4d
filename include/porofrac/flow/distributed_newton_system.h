// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_DISTRIBUTED_NEWTON_SYSTEM_H
#define POROFRAC_FLOW_DISTRIBUTED_NEWTON_SYSTEM_H

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <porofrac/base/distributed_linear_solver.h>

#include <memory>
#include <string>

namespace porofrac
{
  namespace flow
  {
    /**
     * The Newton systems of a TwoPhaseSolver shared by the processes of a communicator. Each
     * process assembles the rows of the unknowns it owns (a contiguous range, @p owned) into
     * the whole-size serial Jacobian and residual; sum() completes the residual on every
     * process, and solve() copies the owned rows into a Trilinos matrix, solves with the
     * registered distributed linear solver @p solver_name (DistributedLinearSolverRegistry;
     * MUMPS, CPR- or AMG-preconditioned GMRES) and gives every process the whole update. Rows
     * assembled by one process only and summed with zeros are exact, so every process holds the
     * same bits and takes the same Newton decisions.
     */
    class DistributedNewtonSystem
    {
    public:
      /// @p max_iterations: Krylov iterations before an iterative solver falls back to MUMPS;
      /// @p amg: the settings of the AMG of an iterative solver.
      DistributedNewtonSystem(const MPI_Comm                 communicator,
                              const dealii::SparsityPattern &sparsity,
                              const dealii::IndexSet        &owned,
                              const std::string             &solver_name,
                              const unsigned int             max_iterations,
                              const AmgSettings             &amg);

      /// Sums @p v over the processes, in place (each entry is assembled by one of them).
      void
      sum(dealii::Vector<double> &v) const;

      /// update = J^{-1} residual with the owned rows of @p jacobian, to the relative residual
      /// @p relative_tolerance for iterative solvers; the whole update on every process.
      /// Throws SolverFailure on every process if the solver fails. With @p reuse_setup, the
      /// matrix and the solver's factors or preconditioner of the last call are used again (the
      /// caller has checked that @p jacobian has not changed).
      void
      solve(const dealii::SparseMatrix<double> &jacobian,
            const dealii::Vector<double>       &residual,
            dealii::Vector<double>             &update,
            const double                        relative_tolerance,
            const bool                          reuse_setup = false);

      /// The distributed linear solver (its name and statistics).
      const DistributedLinearSolver &
      linear_solver() const
      {
        return *solver;
      }

      /// Whether @p value holds on every process.
      bool
      all_processes(const bool value) const;

      /// Nonzeros of the distributed matrix, all processes' rows.
      dealii::types::global_dof_index
      n_nonzeros() const
      {
        return matrix.n_nonzero_elements();
      }

      const MPI_Comm communicator;

    private:
      /// Copies the owned rows of @p jacobian into the distributed matrix and sets the solver up.
      void
      set_up(const dealii::SparseMatrix<double> &jacobian);

      const dealii::IndexSet                 owned;
      dealii::TrilinosWrappers::SparseMatrix matrix;
      /// Right-hand side and solution of the owned rows, kept between solves.
      dealii::TrilinosWrappers::MPI::Vector    b, x;
      std::unique_ptr<DistributedLinearSolver> solver;
    };
  } // namespace flow
} // namespace porofrac

#endif
