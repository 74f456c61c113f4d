// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/base/linear_solver.h>
#include <porofrac/base/registry.h>
#include <porofrac/base/sparse_lu.h>

#include <stdexcept>

namespace porofrac
{
  namespace
  {
    /// UMFPACK LU (SparseLU) behind the linear-solver seam: the symbolic analysis is kept while
    /// the sparsity pattern stays the same, no iterative refinement (Newton corrects its own
    /// linear-solve error).
    class UmfpackLinearSolver : public SerialLinearSolver
    {
    public:
      void
      initialize(const dealii::SparseMatrix<double> &matrix) override
      {
        try
          {
            lu.factorize(matrix);
          }
        catch (const SolverFailure &)
          {
            throw;
          }
        catch (const std::runtime_error &e)
          {
            throw SolverFailure(e.what());
          }
      }

      void
      solve(const dealii::Vector<double> &b,
            dealii::Vector<double>       &x,
            const double /*relative_tolerance*/) override
      {
        x = b;
        ++stats.solves;
        try
          {
            lu.solve(x);
          }
        catch (const std::runtime_error &e)
          {
            throw SolverFailure(e.what());
          }
      }

      std::string
      name() const override
      {
        return "umfpack";
      }

    private:
      SparseLU lu;
    };
  } // namespace

  POROFRAC_REGISTER(SerialLinearSolverRegistry,
                    "umfpack",
                    "sparse direct LU factorization (UMFPACK, symmetric strategy), its symbolic "
                    "analysis reused while the sparsity pattern stays the same.",
                    [] { return std::make_unique<UmfpackLinearSolver>(); })
} // namespace porofrac
