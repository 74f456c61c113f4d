// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/mpi_tools.h>
#include <porofrac/base/mumps_factorization.h>
#include <porofrac/base/quiet_standard_error.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>

namespace porofrac
{
  namespace
  {
    /// The status of the Amesos call @p call, made without Amesos's report of MUMPS's error
    /// codes on std::cerr: it comes on every failed call, also for a factorization the
    /// workspace retry then repeats with success; check() reports a failure that stays.
    template <typename Call>
    int
    quietly(const Call &call)
    {
      const QuietStandardError quiet;
      return call();
    }
  } // namespace



  MumpsFactorization::MumpsFactorization(const std::string &what)
      : what(what)
  {
  }



  MumpsFactorization::~MumpsFactorization() = default;



  void
  MumpsFactorization::check(const int status, const char *step) const
  {
    if (status == 0)
      return;
    std::string reason = "Amesos status " + std::to_string(status);
    if (auto *mumps = dynamic_cast<Amesos_Mumps *>(solver.get()))
      {
        // INFOG(1) is MUMPS's own error code, INFOG(2) its detail (users' guide, section 8).
        const int *infog = mumps->GetINFOG();
        reason += ", INFOG(1) = " + std::to_string(infog[0]);
        if (infog[0] == -10)
          reason += ": numerically singular matrix, " + std::to_string(infog[1]) +
                    " pivots eliminated of " +
                    std::to_string(problem->GetMatrix()->NumGlobalRows());
        else if (infog[0] == -9 || infog[0] == -8)
          reason += ": MUMPS ran out of its working memory";
        else if (infog[0] == -7 || infog[0] == -13)
          // An allocation that failed: INFOG(1) is the same on every process, so all stop.
          throw InsufficientMemory(what + ": MUMPS " + step + " failed (" + reason +
                                   ": an allocation of its working memory failed); use more "
                                   "machines, a coarser mesh or an iterative linear solver");
        else
          reason += ", INFOG(2) = " + std::to_string(infog[1]);
      }
    throw SolverFailure(what + ": MUMPS " + step + " failed (" + reason + ")");
  }



  void
  MumpsFactorization::check_memory(const MPI_Comm comm)
  {
    const auto *mumps = dynamic_cast<Amesos_Mumps *>(solver.get());
    // INFO(15): this process's estimate, in MB, of MUMPS's in-core factorization.
    const double process_need = mumps ? const_cast<Amesos_Mumps *>(mumps)->GetINFO()[14] : 0.;
    estimate_mb = dealii::Utilities::MPI::max(sum_on_this_machine(process_need, comm), comm);
    require(process_need, "MUMPS would need an estimated % for its factorization", comm);
  }



  void
  MumpsFactorization::check_analysis_memory(
    const dealii::TrilinosWrappers::SparseMatrix &matrix) const
  {
    const MPI_Comm comm = matrix.get_mpi_communicator();
    const double   host = dealii::Utilities::MPI::this_mpi_process(comm) == 0 ? 1. : 0.;
    const double   bytes =
      16. * matrix.trilinos_matrix().NumMyNonzeros() + host * 20. * matrix.n_nonzero_elements();
    require(bytes / (1024. * 1024.),
            "the MUMPS analysis of " + std::to_string(matrix.m()) + " rows and " +
              std::to_string(matrix.n_nonzero_elements()) +
              " nonzeros (their copy and the ordering) would need at least %",
            comm);
  }



  void
  MumpsFactorization::require(const double       process_mb,
                              const std::string &needs,
                              const MPI_Comm     comm) const
  {
    require_memory_on_every_process(process_mb,
                                    what + ": " + needs,
                                    "use more machines, a coarser mesh or an iterative linear "
                                    "solver",
                                    comm,
                                    memory_limit_mb);
  }



  bool
  MumpsFactorization::out_of_workspace() const
  {
    auto *mumps = dynamic_cast<Amesos_Mumps *>(solver.get());
    if (!mumps)
      return false;
    // The codes for which MUMPS's users' guide (section 8) advises a larger ICNTL(14); INFOG
    // is the same on every process, so every process takes the same decision.
    const int code = mumps->GetINFOG()[0];
    return code == -8 || code == -9 || code == -14 || code == -15 || code == -17 || code == -20;
  }



  void
  MumpsFactorization::analyse(const dealii::TrilinosWrappers::SparseMatrix &matrix)
  {
    analysed = nullptr; // until the new analysis has passed its checks
    solver.reset();     // before the problem it refers to
    check_analysis_memory(matrix);
    problem = std::make_unique<Epetra_LinearProblem>();
    problem->SetOperator(const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
    Amesos factory;
    solver.reset(factory.Create("Amesos_Mumps", *problem));
    if (!solver)
      throw SolverFailure(what + ": Trilinos Amesos was built without MUMPS");
    // Amesos hands ICNTL to MUMPS in the symbolic factorization only.
    if (auto *mumps = dynamic_cast<Amesos_Mumps *>(solver.get()))
      mumps->SetICNTL(14, workspace_relaxation);
    check(quietly([this] { return solver->SymbolicFactorization(); }), "symbolic factorization");
    check_memory(matrix.get_mpi_communicator());
    analysed = &matrix.trilinos_matrix();
  }



  void
  MumpsFactorization::factorize(const dealii::TrilinosWrappers::SparseMatrix &matrix)
  {
    done = false;
    // MUMPS refuses n = 0; an empty system has nothing to factorize, and solve() nothing to do.
    empty = matrix.m() == 0;
    if (empty)
      {
        done = true;
        return;
      }
    for (unsigned int attempt = 0;; ++attempt)
      {
        if (analysed != &matrix.trilinos_matrix())
          analyse(matrix);
        const int status = quietly([this] { return solver->NumericFactorization(); });
        if (status != 0 && out_of_workspace() && attempt < max_workspace_retries)
          {
            workspace_relaxation = 2 * std::max(workspace_relaxation, 20);
            ++retries;
            analysed = nullptr;
            continue;
          }
        check(status, "factorization");
        break;
      }
    done = true;
  }



  void
  MumpsFactorization::solve(dealii::TrilinosWrappers::MPI::Vector       &x,
                            const dealii::TrilinosWrappers::MPI::Vector &b) const
  {
    if (empty)
      return;
    problem->SetLHS(&x.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(
      static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
    check(quietly([this] { return solver->Solve(); }), "solve");
  }
} // namespace porofrac
