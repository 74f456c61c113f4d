// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_LINEAR_SOLVER_H
#define POROFRAC_BASE_LINEAR_SOLVER_H

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>

namespace porofrac
{
  template <typename Interface, typename... Arguments>
  class Registry;

  /**
   * A solver of linear systems A x = b, the seam between a nonlinear iteration and its linear
   * algebra. @p MatrixType and @p VectorType are deal.II's serial types
   * (SparseMatrix<double>, Vector<double>) for the direct solvers, or their distributed
   * counterparts (TrilinosWrappers::SparseMatrix, TrilinosWrappers::MPI::Vector, or PETSc's) for
   * iterative and parallel ones; the caller assembles into those types and never sees how the
   * system is solved.
   *
   * Implementations register themselves in their own source file (base/registry.h):
   *   POROFRAC_REGISTER(SerialLinearSolverRegistry, "name", "description", factory)
   * and a deck selects one by name.
   */
  /// What a linear solver did since it was created.
  struct LinearSolverStatistics
  {
    /// Calls of solve().
    unsigned long solves = 0;
    /// Krylov iterations summed over the solves (0 for direct solvers).
    unsigned long iterations = 0;
    /// Solves an iterative solver handed to a direct one after Max linear iterations.
    unsigned long direct_fallbacks = 0;
    /// Solves that used the set-up (factors, preconditioner) of an unchanged matrix again.
    unsigned long reused_setups = 0;
    /// MUMPS factorizations repeated with a larger workspace (MumpsFactorization).
    unsigned long direct_workspace_retries = 0;

    LinearSolverStatistics &
    operator+=(const LinearSolverStatistics &other)
    {
      solves += other.solves;
      iterations += other.iterations;
      direct_fallbacks += other.direct_fallbacks;
      reused_setups += other.reused_setups;
      direct_workspace_retries += other.direct_workspace_retries;
      return *this;
    }
  };

  template <typename MatrixType, typename VectorType>
  class LinearSolver
  {
  public:
    using matrix_type = MatrixType;
    using vector_type = VectorType;

    virtual ~LinearSolver() = default;

    /**
     * Prepares the solves with @p matrix: the factorization of a direct solver, the
     * preconditioner of an iterative one. Set-up that depends only on the sparsity pattern (a
     * symbolic analysis, an AMG hierarchy's aggregation) may be kept for later matrices of the
     * same pattern, as in Newton's method. @p matrix must stay alive and unchanged until the last
     * solve() (iterative solvers apply it). Throws SolverFailure (singular matrix, ...).
     */
    virtual void
    initialize(const MatrixType &matrix) = 0;

    /**
     * x = A^{-1} b for the matrix of the last initialize(). Iterative solvers stop at
     * |b - A x| <= @p relative_tolerance |b| (the forcing term of an inexact Newton method);
     * direct solvers ignore it. Throws SolverFailure.
     */
    virtual void
    solve(const VectorType &b, VectorType &x, const double relative_tolerance) = 0;

    /// The name the solver is registered under.
    virtual std::string
    name() const = 0;

    const LinearSolverStatistics &
    statistics() const
    {
      return stats;
    }

  protected:
    LinearSolverStatistics stats;
  };

  /// Linear solvers for deal.II's serial sparse matrices and vectors.
  using SerialLinearSolver = LinearSolver<dealii::SparseMatrix<double>, dealii::Vector<double>>;
  using SerialLinearSolverRegistry = Registry<SerialLinearSolver>;

  /// A new instance of the serial linear solver registered as @p name; an InputError naming
  /// @p parameter if there is none.
  std::unique_ptr<SerialLinearSolver>
  create_serial_linear_solver(const std::string &name, const std::string &parameter);
} // namespace porofrac

#endif
