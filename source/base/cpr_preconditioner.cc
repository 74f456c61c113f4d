// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/base/cpr_preconditioner.h>
#include <porofrac/base/exceptions.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <Epetra_CrsMatrix.h>

namespace porofrac
{
  using namespace dealii;

  namespace
  {
    /// The stored entries of a locally owned row of @p matrix, without copying (deal.II's
    /// Trilinos matrix iterators copy the row for every access; this is the hot loop of the
    /// set-up). Column indices are local to the column map.
    std::tuple<int, const double *, const int *>
    row_view(const Epetra_CrsMatrix &matrix, const types::global_dof_index row)
    {
      int     n       = 0;
      double *values  = nullptr;
      int    *columns = nullptr;
      AssertThrow(matrix.ExtractMyRowView(matrix.LRID(
                                            static_cast<TrilinosWrappers::types::int_type>(row)),
                                          n,
                                          values,
                                          columns) == 0,
                  ExcMessage("CPR: a row that is not stored on this process"));
      return {n, values, columns};
    }

    /// The global column indices of a locally owned row of @p matrix.
    void
    row_columns(const TrilinosWrappers::SparseMatrix &matrix,
                const types::global_dof_index         row,
                std::vector<types::global_dof_index> &columns)
    {
      const Epetra_CrsMatrix &epetra         = matrix.trilinos_matrix();
      const auto [n, entries, local_columns] = row_view(epetra, row);
      (void)entries;
      columns.resize(n);
      for (int e = 0; e < n; ++e)
        columns[e] = TrilinosWrappers::global_column_index(epetra, local_columns[e]);
    }
  } // namespace



  CprPreconditioner::CprPreconditioner(const unsigned int block_size,
                                       const AmgSettings &amg_settings)
      : block_size(block_size)
      , amg_settings(amg_settings)
  {
    AssertThrow(block_size >= 1, ExcMessage("CPR needs at least one unknown per node"));
  }



  void
  CprPreconditioner::make_pressure_pattern(const TrilinosWrappers::SparseMatrix &matrix)
  {
    const MPI_Comm communicator = matrix.get_mpi_communicator();
    owned                       = matrix.locally_owned_range_indices();
    AssertThrow(owned.n_elements() == 0 ||
                  (owned.is_contiguous() && *owned.begin() % block_size == 0 &&
                   owned.n_elements() % block_size == 0),
                ExcMessage("CPR: the rows of a process must be whole nodes, contiguous"));
    AssertThrow(matrix.m() % block_size == 0,
                ExcMessage("CPR: the size is no multiple of the unknowns per node"));
    owned_nodes = IndexSet(matrix.m() / block_size);
    if (owned.n_elements() > 0)
      owned_nodes.add_range(*owned.begin() / block_size,
                            (*owned.begin() + owned.n_elements()) / block_size);
    owned_nodes.compress();

    TrilinosWrappers::SparsityPattern    pattern(owned_nodes, owned_nodes, communicator);
    std::vector<types::global_dof_index> columns;
    for (const auto row : owned)
      {
        row_columns(matrix, row, columns);
        for (const auto column : columns)
          pattern.add(row / block_size, column / block_size);
      }
    pattern.compress();
    pressure.reinit(pattern);
    pressure_rhs.reinit(owned_nodes, communicator);
    pressure_x.reinit(owned_nodes, communicator);
    first.reinit(owned, communicator);
    residual.reinit(owned, communicator);
  }



  void
  CprPreconditioner::assemble_pressure(const TrilinosWrappers::SparseMatrix &matrix)
  {
    std::map<types::global_dof_index, double> row_values;
    std::vector<types::global_dof_index>      columns;
    std::vector<double>                       values;
    const Epetra_CrsMatrix                   &epetra = matrix.trilinos_matrix();
    for (const auto node : owned_nodes)
      {
        row_values.clear();
        for (unsigned int k = 0; k < block_size; ++k)
          {
            const auto [n, entries, local_columns] = row_view(epetra, node * block_size + k);
            for (int e = 0; e < n; ++e)
              row_values[TrilinosWrappers::global_column_index(epetra, local_columns[e]) /
                         block_size] += entries[e];
          }
        columns.clear();
        values.clear();
        for (const auto &[column, value] : row_values)
          {
            columns.push_back(column);
            values.push_back(value);
          }
        pressure.set(node, columns.size(), columns.data(), values.data());
      }
    pressure.compress(VectorOperation::insert);
  }



  void
  CprPreconditioner::initialize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    if (jacobian != &matrix || pressure.m() * block_size != matrix.m())
      make_pressure_pattern(matrix);
    jacobian = &matrix;
    assemble_pressure(matrix);
    // ML and Ifpack end the process where an allocation fails, so their set-up is checked
    // first, on every process together: the ILU(0) factors take at least 12 bytes per nonzero
    // of J (values and column indices), the AMG hierarchy of A_p at least as much per nonzero
    // of A_p again (a lower bound).
    const double megabytes =
      12. *
      (matrix.trilinos_matrix().NumMyNonzeros() + pressure.trilinos_matrix().NumMyNonzeros()) /
      (1024. * 1024.);
    require_memory_on_every_process(
      megabytes,
      "the CPR preconditioner of " + std::to_string(matrix.m()) + " rows and " +
        std::to_string(matrix.n_nonzero_elements()) +
        " nonzeros (its ILU(0) factors and the AMG hierarchy of the pressure block) would need "
        "at least %",
      "use more processes or a coarser mesh",
      matrix.get_mpi_communicator());

    // Smoothed aggregation with Gauss-Seidel smoothing: A_p is an M-matrix up to the upwind
    // derivatives of the mobilities, not symmetric (Chebyshev needs symmetry).
    TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
    amg_data.elliptic      = true;
    amg_data.smoother_type = "symmetric Gauss-Seidel";
    // A threshold above ML's 1e-4 keeps the strong couplings of high-contrast networks (the
    // fracture and interface nodes) in aggregates of their own; MIS aggregation lets them
    // cross process boundaries (doc/algorithms.md §16).
    initialize_amg(amg, pressure, amg_data, amg_settings);
    ilu.initialize(matrix);
  }



  void
  CprPreconditioner::vmult(VectorType &dst, const VectorType &src) const
  {
    const unsigned int n_nodes = owned_nodes.n_elements();
    // Stage 1: restrict (sum the equations of a node), AMG on A_p, prolong (same value to
    // every pressure of the node). begin() is the first locally owned entry.
    const double *r  = src.begin();
    double       *rp = pressure_rhs.begin();
    for (unsigned int j = 0; j < n_nodes; ++j)
      {
        rp[j] = 0;
        for (unsigned int k = 0; k < block_size; ++k)
          rp[j] += r[j * block_size + k];
      }
    amg.vmult(pressure_x, pressure_rhs);
    const double *xp = pressure_x.begin();
    double       *x1 = first.begin();
    for (unsigned int j = 0; j < n_nodes; ++j)
      for (unsigned int k = 0; k < block_size; ++k)
        x1[j * block_size + k] = xp[j];
    // Stage 2: ILU on the residual the pressure correction leaves.
    jacobian->vmult(residual, first);
    residual.sadd(-1., 1., src);
    ilu.vmult(dst, residual);
    dst += first;
  }
} // namespace porofrac
