// SPDX-License-Identifier: LGPL-2.1-or-later
// MumpsFactorization's memory check: a tridiagonal matrix (3, -1; n = 20000) factorizes and solves
// within the machine's available memory (residual printed); the same matrix with a memory limit
// below the bound of the analysis (the triplets and the ordering) throws InsufficientMemory before
// the analysis, and with a limit between that bound and MUMPS's estimate after the analysis,
// before the factorization, naming the factorization; the object then still works with the limit
// lifted. The estimate is kept. An
// empty matrix (n = 0, which MUMPS itself refuses) factorizes and solves as a no-op.
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/mumps_factorization.h>

#include <iostream>

using namespace dealii;

namespace
{
  double
  solve_and_residual(porofrac::MumpsFactorization         &lu,
                     const TrilinosWrappers::SparseMatrix &A,
                     const IndexSet                       &rows)
  {
    TrilinosWrappers::MPI::Vector x(rows, MPI_COMM_WORLD), b(x), r(x);
    b = 1;
    lu.factorize(A);
    lu.solve(x, b);
    A.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n = 20000;
  IndexSet                         rows(n);
  rows.add_range(0, n);
  DynamicSparsityPattern dsp(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
      dsp.add(i, j);
  TrilinosWrappers::SparseMatrix A;
  A.reinit(rows, rows, dsp, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
      A.set(i, j, i == j ? 3. : -1.);
  A.compress(VectorOperation::insert);

  porofrac::MumpsFactorization fits("test factorization");
  std::cout << "within the available memory: relative residual below 1e-10: "
            << (solve_and_residual(fits, A, rows) < 1e-10 ? "yes" : "no") << std::endl;
  std::cout << "memory estimate recorded: " << (fits.estimated_memory_mb() > 0 ? "yes" : "no")
            << std::endl;

  // Below the analysis's own bound (36 bytes per nonzero on one process): refused before the
  // analysis; between it and MUMPS's estimate: refused after the analysis, naming the
  // factorization.
  porofrac::MumpsFactorization limited("test factorization");
  const double                 analysis_mb = 36. * A.n_nonzero_elements() / (1024. * 1024.);
  std::cout << "MUMPS's estimate above 1.05 times the analysis bound: "
            << (fits.estimated_memory_mb() > 1.05 * analysis_mb ? "yes" : "no") << std::endl;
  for (const double limit : {1e-3, 1.05 * analysis_mb})
    {
      limited.set_memory_limit(limit);
      try
        {
          solve_and_residual(limited, A, rows);
          std::cout << "limit " << limit << " MB: no error" << std::endl;
        }
      catch (const porofrac::SolverFailure &e)
        {
          // MUMPS's estimate itself depends on its version: left out.
          const std::string message  = e.what();
          const auto        cut      = message.find(" would need");
          const auto        estimate = message.find(" an estimated");
          std::cout << (limit < 1 ? "limit 1 kB: " : "limit 1.05 x the analysis bound: ")
                    << message.substr(0, estimate != std::string::npos ? estimate : cut) << " ..."
                    << message.substr(message.find(", more than")) << std::endl
                    << "factorized: " << (limited.factorized() ? "yes" : "no") << std::endl;
        }
    }
  limited.set_memory_limit(0);
  std::cout << "limit lifted: relative residual below 1e-10: "
            << (solve_and_residual(limited, A, rows) < 1e-10 ? "yes" : "no") << std::endl;

  const IndexSet                 none(0);
  TrilinosWrappers::SparseMatrix empty;
  empty.reinit(none, none, DynamicSparsityPattern(0, 0), MPI_COMM_WORLD);
  TrilinosWrappers::MPI::Vector x(none, MPI_COMM_WORLD), b(x);
  porofrac::MumpsFactorization  nothing("test factorization");
  nothing.factorize(empty);
  nothing.solve(x, b);
  std::cout << "empty matrix: factorized: " << (nothing.factorized() ? "yes" : "no")
            << ", solution size " << x.size() << std::endl;
}
