// SPDX-License-Identifier: LGPL-2.1-or-later
// SparseLU's memory check (UMFPACK): on a five-point Laplacian of a 120 x 120 grid (shifted to be
// regular), the symbolic analysis records a lower bound of the factorization's memory, the values
// of the L + U nonzeros it counts (0.9 to 1 times those factorized: diagonal pivots); with the
// available memory capped at half that bound the factorization stops with InsufficientMemory
// before it starts (no factor is left to solve with), and the message names the rows and what to
// do; capped at 1.5 times the bound it factorizes and solves (residual printed), so the check
// counts the bound and nothing more; the same cap with two copies per machine
// (ReplicatedSerialSolves) stops again. A new pattern is refused before the analysis allocates
// anything when the memory is below half the analysis's bound (its copy of the pattern and the
// ordering), and analysed and solved once the cap is lifted. Behind the linear-solver seam
// ("umfpack", as the flow's Newton solver uses it) the refusal stays an InsufficientMemory, which
// the flow and coupled solvers do not answer with a time-step cut.
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/linear_solver.h>
#include <porofrac/base/registry.h>
#include <porofrac/base/sparse_lu.h>

#include <iostream>
#include <regex>

#include "../grid_pattern.h"

using namespace dealii;

namespace
{
  /// |A x - b| / |b| after factorizing A and solving with b = 1; an InsufficientMemory goes
  /// to the caller.
  double
  solve_and_residual(porofrac::SparseLU &lu, const SparseMatrix<double> &A)
  {
    Vector<double> b(A.m()), x(A.m()), r(A.m());
    b = 1;
    lu.factorize(A);
    lu.vmult(x, b);
    A.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }

  /// The message of the InsufficientMemory that factorizing @p A throws (sizes masked), or
  /// "solved" with the residual's size.
  std::string
  attempt(porofrac::SparseLU &lu, const SparseMatrix<double> &A)
  {
    try
      {
        return std::string("solved, relative residual below 1e-12: ") +
               (solve_and_residual(lu, A) < 1e-12 ? "yes" : "no");
      }
    catch (const porofrac::InsufficientMemory &e)
      {
        return "refused: " +
               std::regex_replace(std::string(e.what()), std::regex("[0-9.]+ (kB|MB|GB)"), "# $1");
      }
  }
} // namespace

int
main()
{
  const unsigned int n = 120;
  SparsityPattern    pattern;
  pattern.copy_from(five_point_pattern(n));
  SparseMatrix<double> A(pattern);
  for (unsigned int k = 0; k < n * n; ++k)
    for (auto e = A.begin(k); e != A.end(k); ++e)
      e->value() = (e->column() == k ? 4.5 : -1.);

  porofrac::SparseLU lu;
  std::cout << "no cap: " << attempt(lu, A) << std::endl;
  const double estimate      = lu.minimum_memory_estimate_mb();
  const double factorized_mb = 8 * lu.n_factor_nonzeros() / (1024. * 1024.);
  std::cout << "lower bound recorded, 0.9 to 1 times the values factorized: "
            << (estimate > 0.9 * factorized_mb && estimate <= factorized_mb ? "yes" : "no")
            << std::endl;

  // The analysis (done uncapped) is kept; the caps below meet the factorization's check alone.
  porofrac::SparseLU capped;
  attempt(capped, A);
  porofrac::limit_available_memory(0.5 * estimate);
  std::cout << "cap 0.5 x bound: " << attempt(capped, A) << std::endl;
  Vector<double> x(n * n);
  try
    {
      capped.solve(x);
      std::cout << "  a factor left to solve with: yes" << std::endl;
    }
  catch (const std::runtime_error &)
    {
      std::cout << "  a factor left to solve with: no" << std::endl;
    }

  porofrac::limit_available_memory(1.5 * estimate);
  std::cout << "cap 1.5 x bound: " << attempt(capped, A) << std::endl;
  {
    const porofrac::ReplicatedSerialSolves two(2);
    std::cout << "the same cap, 2 copies per machine: " << attempt(capped, A) << std::endl;
  }

  porofrac::limit_available_memory(0.5 * estimate);
  auto solver = porofrac::SerialLinearSolverRegistry::instance().create("umfpack", "test");
  try
    {
      solver->initialize(A);
      std::cout << "behind the seam, cap 0.5 x bound: factorized" << std::endl;
    }
  catch (const porofrac::InsufficientMemory &)
    {
      std::cout << "behind the seam, cap 0.5 x bound: InsufficientMemory" << std::endl;
    }
  catch (const porofrac::SolverFailure &)
    {
      std::cout << "behind the seam, cap 0.5 x bound: another solver failure" << std::endl;
    }
  porofrac::limit_available_memory(0);
  std::cout << "cap lifted: " << attempt(capped, A) << std::endl;

  // A new pattern is analysed: its copy of the pattern and the ordering are checked first.
  const double analysis_mb =
    porofrac::SparseLU::analysis_memory_estimate_mb(A.m(), pattern.n_nonzero_elements());
  std::cout << "analysis bound at least the pattern copy's 8 bytes per nonzero: "
            << (analysis_mb * 1024 * 1024 >= 8. * pattern.n_nonzero_elements() ? "yes" : "no")
            << std::endl;
  porofrac::limit_available_memory(0.5 * analysis_mb);
  porofrac::SparseLU fresh;
  std::cout << "cap 0.5 x analysis bound: " << attempt(fresh, A) << std::endl;
  porofrac::limit_available_memory(0);
  std::cout << "cap lifted: " << attempt(fresh, A) << std::endl;
}
