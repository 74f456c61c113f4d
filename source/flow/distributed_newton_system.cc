// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/array_view.h>

#include <porofrac/flow/distributed_newton_system.h>

#include <vector>

namespace porofrac
{
  namespace flow
  {
    using namespace dealii;

    DistributedNewtonSystem::DistributedNewtonSystem(const MPI_Comm         communicator,
                                                     const SparsityPattern &sparsity,
                                                     const IndexSet        &owned,
                                                     const std::string     &solver_name,
                                                     const unsigned int     max_iterations,
                                                     const AmgSettings     &amg)
        : communicator(communicator)
        , owned(owned)
    {
      DistributedLinearSolverOptions options;
      options.block_size     = 2; // (p^w, p^nw) of a node, consecutive (TwoPhaseSolver::dof)
      options.max_iterations = max_iterations;
      options.amg            = amg;
      options.what           = "Flow: the Newton system";
      solver =
        create_distributed_linear_solver(solver_name, "Flow/Distributed linear solver", options);
      matrix.reinit(owned, owned, sparsity, communicator);
      b.reinit(owned, communicator);
      x.reinit(owned, communicator);
    }



    void
    DistributedNewtonSystem::sum(Vector<double> &v) const
    {
      const ArrayView<double> values = make_array_view(v);
      Utilities::MPI::sum(ArrayView<const double>(values), communicator, values);
    }



    void
    DistributedNewtonSystem::solve(const SparseMatrix<double> &jacobian,
                                   const Vector<double>       &residual,
                                   Vector<double>             &update,
                                   const double                relative_tolerance,
                                   const bool                  reuse_setup)
    {
      if (!reuse_setup)
        set_up(jacobian);
      for (const auto row : owned)
        b[row] = residual(row);
      b.compress(VectorOperation::insert);
      solver->solve(b, x, relative_tolerance);
      update = 0;
      for (const auto row : owned)
        update(row) = x[row];
      sum(update);
    }



    void
    DistributedNewtonSystem::set_up(const SparseMatrix<double> &jacobian)
    {
      std::vector<types::global_dof_index> columns;
      std::vector<double>                  values;
      for (const auto row : owned)
        {
          columns.clear();
          values.clear();
          for (auto entry = jacobian.begin(row); entry != jacobian.end(row); ++entry)
            {
              columns.push_back(entry->column());
              values.push_back(entry->value());
            }
          matrix.set(row, columns.size(), columns.data(), values.data());
        }
      matrix.compress(VectorOperation::insert);
      solver->initialize(matrix);
    }



    bool
    DistributedNewtonSystem::all_processes(const bool value) const
    {
      return Utilities::MPI::min(value ? 1 : 0, communicator) == 1;
    }
  } // namespace flow
} // namespace porofrac
