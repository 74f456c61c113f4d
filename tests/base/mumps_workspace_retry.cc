// SPDX-License-Identifier: LGPL-2.1-or-later
// MumpsFactorization's workspace retry: the 5-point pattern of an n x n grid is analysed with
// diagonally dominant values and no workspace relaxation (ICNTL(14) = 0), then refactorized with
// the same unsymmetric off-diagonal entries and a diagonal of 1e-8: MUMPS must delay most pivots
// beyond the workspace the analysis reserved (INFOG(1) = -9). The factorization is repeated with
// a larger relaxation and succeeds. Printed: whether the first values factorized without a
// retry, whether the second took at least one, and whether its solution equals that of a
// factorization analysed with a generous relaxation (400 %) to 1e-8 relative (the second
// matrix is badly conditioned, so its residual is no measure of the factors). The failed attempts
// write nothing on the standard error (Amesos's own error report is held back), which the
// comparison with the expected output checks.
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/mumps_factorization.h>

#include <iostream>

#include "../grid_pattern.h"

using namespace dealii;

namespace
{
  constexpr unsigned int n = 60;

  unsigned int
  index(const unsigned int i, const unsigned int j)
  {
    return i * n + j;
  }

  /// The 5-point stencil with the given diagonal and unsymmetric off-diagonal entries of order 1.
  void
  set_values(TrilinosWrappers::SparseMatrix &A, const double diagonal)
  {
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const unsigned int row = index(i, j);
          A.set(row, row, diagonal);
          if (i > 0)
            A.set(row, index(i - 1, j), -1.);
          if (i + 1 < n)
            A.set(row, index(i + 1, j), -0.5);
          if (j > 0)
            A.set(row, index(i, j - 1), -0.7);
          if (j + 1 < n)
            A.set(row, index(i, j + 1), -1.3);
        }
    A.compress(VectorOperation::insert);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  IndexSet                         rows(n * n);
  rows.add_range(0, n * n);
  const DynamicSparsityPattern   dsp = five_point_pattern(n);
  TrilinosWrappers::SparseMatrix A;
  A.reinit(rows, rows, dsp, MPI_COMM_WORLD);

  porofrac::MumpsFactorization lu("test factorization");
  lu.set_workspace_relaxation(0);
  set_values(A, 10.);
  lu.factorize(A);
  std::cout << "diagonally dominant values: factorized without a retry: "
            << (lu.workspace_retries() == 0 ? "yes" : "no") << std::endl;

  set_values(A, 1e-8);
  try
    {
      lu.factorize(A);
    }
  catch (const porofrac::SolverFailure &e)
    {
      std::cout << "diagonal 1e-8: " << e.what() << std::endl;
      return 0;
    }
  std::cout << "diagonal 1e-8: factorized after at least one retry: "
            << (lu.workspace_retries() > 0 ? "yes" : "no") << std::endl;

  porofrac::MumpsFactorization generous("generous factorization");
  generous.set_workspace_relaxation(400);
  generous.factorize(A);
  TrilinosWrappers::MPI::Vector x(rows, MPI_COMM_WORLD), y(x), b(x);
  b = 1;
  lu.solve(x, b);
  generous.solve(y, b);
  y -= x;
  std::cout << "the same solution as with a generous workspace (1e-8 relative): "
            << (y.l2_norm() <= 1e-8 * x.l2_norm() ? "yes" : "no") << std::endl;
}
