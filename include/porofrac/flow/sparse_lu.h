// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_SPARSE_LU_H
#define POROFRAC_FLOW_SPARSE_LU_H

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <umfpack.h>

#include <vector>

namespace porofrac
{
  namespace flow
  {
    using namespace dealii;

    /**
     * UMFPACK LU factorization of SparseMatrix<double> matrices that share one sparsity pattern,
     * as in Newton's method: the symbolic analysis (fill-reducing ordering) is done once for the
     * pattern and reused by every numeric factorization; only the values are copied per call.
     * deal.II's SparseDirectUMFPACK redoes both for every matrix, which costs about as much as
     * the numeric factorization itself on the flow Jacobians.
     *
     * factorize() throws std::runtime_error for a singular matrix or any UMFPACK error.
     */
    class SparseLU
    {
    public:
      SparseLU();
      ~SparseLU();
      SparseLU(const SparseLU &) = delete;
      SparseLU &
      operator=(const SparseLU &) = delete;

      /// Numeric factorization of @p matrix (symbolic analysis the first time a pattern is seen).
      void
      factorize(const SparseMatrix<double> &matrix);

      /// Overwrites @p x = b with the solution of A x = b for the last factorized A.
      void
      solve(Vector<double> &x) const;

      /// Nonzeros of L and U in the last factorization (UMFPACK Info).
      double
      n_factor_nonzeros() const
      {
        return factor_nonzeros;
      }

    private:
      void
      analyse(const SparseMatrix<double> &matrix);
      void
      free_numeric();
      void
      free_symbolic();

      const SparsityPattern *pattern      = nullptr;
      std::size_t            pattern_size = 0;
      /// Row-compressed copy with sorted columns (UMFPACK's column form of the transpose).
      std::vector<SuiteSparse_long> row_start, columns;
      std::vector<double>           values;
      /// values[position[k]] = k-th stored value of the SparseMatrix.
      std::vector<SuiteSparse_long> position;
      void                         *symbolic = nullptr;
      void                         *numeric  = nullptr;
      double                        control[UMFPACK_CONTROL];
      double                        factor_nonzeros = 0;
    };
  } // namespace flow
} // namespace porofrac

#endif
