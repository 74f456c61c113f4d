// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_SPARSE_CHOLESKY_H
#define POROFRAC_MECHANICS_SPARSE_CHOLESKY_H

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
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
     * Solves one right-hand side or a block of them (column-major), the latter with level-3 BLAS,
     * and forms B^T K^{-1} B for a sparse B (the multiplier Schur complement).
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

      /**
       * Factorizes rows and columns [0, n) of @p matrix (only its upper triangle is read).
       * Between the symbolic analysis and the numeric factorization, @p check_memory (if given)
       * receives the size in MB of the factor about to be allocated, and may throw to stop
       * before it is.
       */
      void
      factorize(const SparseMatrix<double>        &matrix,
                const unsigned int                 n,
                const std::function<void(double)> &check_memory = {});

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
       * G = B^T K^{-1} B (m x m, dense, symmetric) for a sparse n x m matrix B given column by
       * column as (row, value) pairs, as G = Y^T Y with Y = L^{-1} P B. A column of B that lives
       * on a few rows only reaches the supernodes on their paths to the root of the elimination
       * tree, so the forward substitution runs supernode by supernode on the columns that reach
       * it (dense triangular solve and update, level-3 BLAS) and each supernode adds its rows of
       * Y to G (rank-k update). Y is kept for gram_factor_*(). Before Y is allocated,
       * @p check_memory (if given) receives its size in MB, which the column reach of the
       * elimination tree fixes, and may throw to stop first. Returns the number of nonzeros of
       * Y.
       */
      std::size_t
      inverse_gram(const std::vector<std::vector<std::pair<unsigned int, double>>> &columns,
                   FullMatrix<double>                                              &G,
                   const std::function<void(double)> &check_memory = {}) const;
      /// z = L^{-1} P z (forward half of a solve).
      void
      forward(std::vector<double> &z) const;

      /// x = P^T L^{-T} x (backward half of a solve).
      void
      backward(std::vector<double> &x) const;

      /// out = Y^T z with the Y of the last inverse_gram(): B^T K^{-1} b = Y^T (L^{-1} P b).
      void
      gram_factor_transpose_vmult(const std::vector<double> &z, Vector<double> &out) const;

      /// z -= Y v: K^{-1} (b - B v) = P^T L^{-T} (L^{-1} P b - Y v).
      void
      gram_factor_vmult_subtract(const Vector<double> &v, std::vector<double> &z) const;

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
