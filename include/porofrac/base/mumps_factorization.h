// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_MUMPS_FACTORIZATION_H
#define POROFRAC_BASE_MUMPS_FACTORIZATION_H

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>

#include <mpi.h>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace porofrac
{
  /**
   * Distributed LU factors of a Trilinos matrix by MUMPS (through Trilinos Amesos). The
   * symbolic analysis is done once for the matrix given to the first factorize(); later
   * calls refactorize the same matrix object (same pattern, new values). Failures throw
   * SolverFailure naming @p what.
   *
   * After each analysis, MUMPS's estimate of the factorization's memory (INFO(15) of every
   * process, summed over the processes of each machine) is compared with the memory the machine
   * has available (available_memory_mb(), or set_memory_limit()): a factorization that
   * would not fit throws SolverFailure before it starts, instead of exhausting the machine.
   *
   * An empty matrix (n = 0, which MUMPS refuses) is accepted: factorize() and solve() do
   * nothing.
   *
   * A factorization that runs out of MUMPS's workspace (INFOG(1) = -8, -9, -14, -15, -17 or
   * -20: more pivoting than the analysis foresaw, typically on new values of the analysed
   * pattern) is analysed and factorized again with the workspace relaxation ICNTL(14) doubled,
   * at most max_workspace_retries times; the larger relaxation is kept for later analyses.
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

    /// Checks against @p megabytes per machine instead of the available memory (0: the
    /// available memory again).
    void
    set_memory_limit(const double megabytes)
    {
      memory_limit_mb = megabytes;
    }

    /// MUMPS's estimate of the last analysed factorization's memory, in MB (the largest over
    /// the machines of the processes).
    double
    estimated_memory_mb() const
    {
      return estimate_mb;
    }

    bool
    factorized() const
    {
      return done;
    }

    /// ICNTL(14) of the next analysis: the percentage by which MUMPS enlarges the workspace
    /// the analysis estimates (MUMPS's default 20).
    void
    set_workspace_relaxation(const int percent)
    {
      workspace_relaxation = percent;
    }

    /// Factorizations repeated so far with a larger workspace relaxation.
    unsigned int
    workspace_retries() const
    {
      return retries;
    }

    static constexpr unsigned int max_workspace_retries = 3;

  private:
    /// A new symbolic analysis of @p matrix with the current workspace relaxation.
    void
    analyse(const dealii::TrilinosWrappers::SparseMatrix &matrix);

    /// Whether the last MUMPS call failed for want of workspace (a larger ICNTL(14) helps).
    bool
    out_of_workspace() const;

    void
    check(const int status, const char *step) const;

    /// Throws (on every process of @p comm) if the analysed factorization needs more memory than
    /// some machine has, or than some process may allocate.
    void
    check_memory(const MPI_Comm comm);

    /// Throws (on every process) before the analysis of @p matrix if the matrix's copy and its
    /// ordering would not fit: 16 bytes per local nonzero on each process (the coordinate
    /// triplets MUMPS is given) and 20 per nonzero of the whole matrix on the host, which orders
    /// the whole graph (as UMFPACK's ordering, base/sparse_lu.h: a lower bound).
    void
    check_analysis_memory(const dealii::TrilinosWrappers::SparseMatrix &matrix) const;

    /// Throws InsufficientMemory on every process of @p comm where this process's @p process_mb,
    /// summed over its machine, exceeds the memory available there, or exceeds the process's
    /// own headroom (process_memory_headroom_mb()). @p needs says what needs it, with % where
    /// the amount goes ("MUMPS would need an estimated % for its factorization").
    void
    require(double process_mb, const std::string &needs, MPI_Comm comm) const;

    const std::string                     what;
    std::unique_ptr<Epetra_LinearProblem> problem;
    std::unique_ptr<Amesos_BaseSolver>    solver;
    /// The Epetra matrix of the symbolic analysis (deal.II may replace it on a deep copy).
    const void  *analysed             = nullptr;
    bool         done                 = false;
    bool         empty                = false; ///< the last factorized matrix has no rows
    double       memory_limit_mb      = 0;
    double       estimate_mb          = 0;
    int          workspace_relaxation = 20;
    unsigned int retries              = 0;
  };
} // namespace porofrac

#endif
