// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_SPARSE_LU_H
#define POROFRAC_BASE_SPARSE_LU_H

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

#include <umfpack.h>

namespace porofrac
{
  /**
   * UMFPACK LU factorization of dealii::SparseMatrix<double> matrices that share one sparsity
   * pattern, as in Newton's method: the symbolic analysis (fill-reducing ordering) is done once for
   * the pattern and reused by every numeric factorization; only the values are copied per call.
   * deal.II's SparseDirectUMFPACK redoes both for every matrix and always refines the solution
   * iteratively (up to two extra solves and residuals per call).
   *
   * The matrices of PoroFrac (TPFA Jacobians, contact-mechanics saddle points) have symmetric
   * patterns, so UMFPACK's symmetric strategy (AMD on A + A^T, diagonal pivots preferred) is
   * the default: on the paper's 5.3 mesh it factorizes the flow Jacobian about 20 % faster than
   * the automatic choice (doc/coupling.md).
   *
   * factorize() throws std::runtime_error for a singular matrix or any UMFPACK error, and
   * InsufficientMemory, before it allocates, when a lower bound of the memory of the analysis
   * or of the factorization exceeds the memory the run has (available_memory_mb(), counted once
   * per ReplicatedSerialSolves copy): on Linux an allocation beyond it would not fail but have
   * the process killed. The analysis's bound is its copy of the pattern and less than the
   * symbolic analysis was measured to take (analysis_memory_estimate_mb()); the
   * factorization's, the values of the L and U nonzeros that UMFPACK's symmetric analysis counts
   * (its own peak estimates are far above the peaks) and the copy of the matrix values. So a run
   * a little above the memory can still be killed; one far above it is refused.
   */
  class SparseLU
  {
  public:
    /// @p refinement_steps: UMFPACK's iterative refinement steps per solve (0: none, as in a
    /// Newton iteration, which corrects its own linear-solve error).
    explicit SparseLU(const unsigned int refinement_steps = 0, const bool symmetric = true);
    ~SparseLU();
    SparseLU(const SparseLU &) = delete;
    SparseLU &
    operator=(const SparseLU &) = delete;

    /// Numeric factorization of @p matrix (symbolic analysis the first time a pattern is seen).
    void
    factorize(const dealii::SparseMatrix<double> &matrix);

    /// Overwrites @p x = b with the solution of A x = b for the last factorized A.
    void
    solve(dealii::Vector<double> &x) const;

    /// dst = A^{-1} src (the preconditioner interface of deal.II's solvers).
    void
    vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const;

    /// Nonzeros of L and U in the last factorization (UMFPACK Info).
    double
    n_factor_nonzeros() const
    {
      return factor_nonzeros;
    }

    /// The lower bound (MB) of the numeric factorization's memory that the memory check uses,
    /// from the last symbolic analysis; 0 before the first, and if UMFPACK did not use its
    /// symmetric strategy (no bound, no check).
    double
    minimum_memory_estimate_mb() const
    {
      return minimum_memory_mb;
    }

    /// The memory (MB) that the analysis of a pattern of @p n rows and @p nnz nonzeros needs at
    /// least and checks before it allocates: the copy of the pattern (row starts, columns) and
    /// the symbolic analysis.
    static double
    analysis_memory_estimate_mb(std::size_t n, std::size_t nnz);

  private:
    void
    analyse(const dealii::SparseMatrix<double> &matrix);
    /// Throws InsufficientMemory if the analysis of a pattern of @p n rows and @p nnz nonzeros
    /// would need more than the available memory.
    void
    check_analysis_memory(std::size_t n, std::size_t nnz) const;
    /// Throws InsufficientMemory if the factorization of @p n rows (and the copy of the values,
    /// the first time) would need more than the available memory.
    void
    check_memory(std::size_t n) const;
    void
    free_numeric();
    void
    free_symbolic();

    const dealii::SparsityPattern *pattern      = nullptr;
    std::size_t                    pattern_size = 0;
    /// Row-compressed copy with sorted columns (UMFPACK's column form of the transpose).
    std::vector<SuiteSparse_long> row_start, columns;
    std::vector<double>           values;
    /// Whether each stored row starts with the diagonal (deal.II's square matrices), which the
    /// copy moves to its sorted slot.
    bool   diagonal_first = false;
    void  *symbolic       = nullptr;
    void  *numeric        = nullptr;
    double control[UMFPACK_CONTROL];
    double factor_nonzeros   = 0;
    double minimum_memory_mb = 0;
  };
} // namespace porofrac

#endif
