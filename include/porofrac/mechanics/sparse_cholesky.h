// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_SPARSE_CHOLESKY_H
#define POROFRAC_MECHANICS_SPARSE_CHOLESKY_H

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    /**
     * Sparse Cholesky factorization K = L L^T (CHOLMOD, supernodal, fill-reducing ordering) of
     * the leading n x n block of a symmetric positive definite deal.II matrix: the constrained
     * elasticity block of the contact system, which never changes across contact iterations.
     * Solves one right-hand side or a block of them (column-major), the latter with level-3 BLAS.
     * Throws SolverFailure when the block is not positive definite (e.g. a body without
     * Dirichlet condition that only the contact rows hold in place).
     */
    class SparseCholesky
    {
    public:
      SparseCholesky();
      ~SparseCholesky();
      SparseCholesky(const SparseCholesky &) = delete;
      SparseCholesky &
      operator=(const SparseCholesky &) = delete;

      /// Factorizes rows and columns [0, n) of @p matrix (only its upper triangle is read).
      void
      factorize(const SparseMatrix<double> &matrix, const unsigned int n);

      /// x = K^{-1} x.
      void
      solve(Vector<double> &x) const;

      /// Column-major block of @p n_columns right-hand sides of length n, overwritten by K^{-1}.
      void
      solve(std::vector<double> &block, const unsigned int n_columns) const;

      unsigned int
      size() const
      {
        return n;
      }

      /**
       * Sparse forward substitution y = L^{-1} P b for a sparse @p b given as (row, value) pairs:
       * only the entries in the reach of b in the elimination tree are computed, and returned as
       * (row of L, value) pairs in @p y. The first call converts the factor to simplicial form
       * (CHOLMOD restricts sparse solves to it); the solves above keep working with it.
       */
      void
      forward_sparse(const std::vector<std::pair<unsigned int, double>> &b,
                     std::vector<std::pair<unsigned int, double>>       &y);

      /// Number of nonzeros of the factor L.
      double
      factor_nonzeros() const;

    private:
      unsigned int n = 0;
      struct Data;
      Data *data;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
