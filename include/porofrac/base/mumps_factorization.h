// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_MUMPS_FACTORIZATION_H
#define POROFRAC_BASE_MUMPS_FACTORIZATION_H

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace porofrac
{
  /**
   * Distributed LU factors of a Trilinos matrix by MUMPS (through Trilinos Amesos). The
   * symbolic analysis is done once for the matrix given to the first factorize(); later
   * calls refactorize the same matrix object (same pattern, new values). Failures throw
   * SolverFailure naming @p what.
   */
  class MumpsFactorization
  {
  public:
    explicit MumpsFactorization(const std::string &what);
    ~MumpsFactorization();

    /// Numerical factorization of @p matrix (which must outlive this object); a new symbolic
    /// analysis if the matrix is another one than last time.
    void
    factorize(const dealii::TrilinosWrappers::SparseMatrix &matrix);

    /// x = A^-1 b with the last factors.
    void
    solve(dealii::TrilinosWrappers::MPI::Vector       &x,
          const dealii::TrilinosWrappers::MPI::Vector &b) const;

    bool
    factorized() const
    {
      return done;
    }

  private:
    void
    check(const int status, const char *step) const;

    const std::string                     what;
    std::unique_ptr<Epetra_LinearProblem> problem;
    std::unique_ptr<Amesos_BaseSolver>    solver;
    /// The Epetra matrix of the symbolic analysis (deal.II may replace it on a deep copy).
    const void *analysed = nullptr;
    bool        done     = false;
  };
} // namespace porofrac

#endif
