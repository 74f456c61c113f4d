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

#include <porofrac/base/mumps_factorization.h>

namespace porofrac
{
  namespace flow
  {
    /**
     * The Newton systems of a TwoPhaseSolver shared by the processes of a communicator. Each
     * process assembles the rows of the unknowns it owns (a contiguous range, @p owned) into
     * the whole-size serial Jacobian and residual; sum() completes the residual on every
     * process, and solve() copies the owned rows into a Trilinos matrix, solves with MUMPS and
     * gives every process the whole update. Rows assembled by one process only and summed
     * with zeros are exact, so every process holds the same bits and takes the same Newton
     * decisions.
     */
    class DistributedNewtonSystem
    {
    public:
      DistributedNewtonSystem(const MPI_Comm                 communicator,
                              const dealii::SparsityPattern &sparsity,
                              const dealii::IndexSet        &owned);

      /// Sums @p v over the processes, in place (each entry is assembled by one of them).
      void
      sum(dealii::Vector<double> &v) const;

      /// update = J^{-1} residual with the owned rows of @p jacobian; the whole update on
      /// every process. Throws SolverFailure on every process if MUMPS fails.
      void
      solve(const dealii::SparseMatrix<double> &jacobian,
            const dealii::Vector<double>       &residual,
            dealii::Vector<double>             &update);

      /// Whether @p value holds on every process.
      bool
      all_processes(const bool value) const;

      const MPI_Comm communicator;

    private:
      const dealii::IndexSet                 owned;
      dealii::TrilinosWrappers::SparseMatrix matrix;
      /// Right-hand side and solution of the owned rows, kept between solves.
      dealii::TrilinosWrappers::MPI::Vector b, x;
      MumpsFactorization                    lu;
    };
  } // namespace flow
} // namespace porofrac

#endif
