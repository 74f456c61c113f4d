// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/base/mumps_factorization.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>

namespace porofrac
{
  MumpsFactorization::MumpsFactorization(const std::string &what)
      : what(what)
  {
  }



  MumpsFactorization::~MumpsFactorization() = default;



  void
  MumpsFactorization::check(const int status, const char *step) const
  {
    if (status != 0)
      throw SolverFailure(what + ": MUMPS " + step + " failed (Amesos status " +
                          std::to_string(status) + ")");
  }



  void
  MumpsFactorization::factorize(const dealii::TrilinosWrappers::SparseMatrix &matrix)
  {
    done = false;
    if (analysed != &matrix.trilinos_matrix())
      {
        problem = std::make_unique<Epetra_LinearProblem>();
        problem->SetOperator(const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
        Amesos factory;
        solver.reset(factory.Create("Amesos_Mumps", *problem));
        if (!solver)
          throw SolverFailure(what + ": Trilinos Amesos was built without MUMPS");
        check(solver->SymbolicFactorization(), "symbolic factorization");
        analysed = &matrix.trilinos_matrix();
      }
    check(solver->NumericFactorization(), "factorization");
    done = true;
  }



  void
  MumpsFactorization::solve(dealii::TrilinosWrappers::MPI::Vector       &x,
                            const dealii::TrilinosWrappers::MPI::Vector &b) const
  {
    problem->SetLHS(&x.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(
      static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
    check(solver->Solve(), "solve");
  }
} // namespace porofrac
