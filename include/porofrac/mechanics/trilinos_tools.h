// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_TRILINOS_TOOLS_H
#define POROFRAC_MECHANICS_TRILINOS_TOOLS_H

#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>

#include <Epetra_CrsMatrix.h>

namespace porofrac
{
  namespace mechanics
  {
    /**
     * Calls @p visit(row, column, value) (global indices) for every stored entry of the
     * locally owned row @p row of @p matrix. Reads Epetra's row view: deal.II's row iterators
     * need the next row to be locally owned too, which non-contiguous row sets (the
     * multipliers of the faces a process owns) do not give.
     */
    template <typename Visit>
    void
    for_entries_of_row(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                       const dealii::types::global_dof_index         row,
                       const Visit                                  &visit)
    {
      const Epetra_CrsMatrix &A     = matrix.trilinos_matrix();
      const int               local = A.RowMap().LID(static_cast<int>(row));
      int                     n     = 0;
      double                 *values;
      int                    *columns;
      A.ExtractMyRowView(local, n, values, columns);
      for (int k = 0; k < n; ++k)
        visit(row,
              static_cast<dealii::types::global_dof_index>(A.ColMap().GID(columns[k])),
              values[k]);
    }

    /// for_entries_of_row() for every locally owned row.
    template <typename Visit>
    void
    for_owned_entries(const dealii::TrilinosWrappers::SparseMatrix &matrix, const Visit &visit)
    {
      const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
      for (int local = 0; local < A.NumMyRows(); ++local)
        for_entries_of_row(matrix,
                           static_cast<dealii::types::global_dof_index>(A.RowMap().GID(local)),
                           visit);
    }

    /// Sets the stored entries of the locally owned row @p row of @p matrix to zero; the
    /// sparsity pattern stays.
    inline void
    zero_row(dealii::TrilinosWrappers::SparseMatrix &matrix,
             const dealii::types::global_dof_index   row)
    {
      Epetra_CrsMatrix &A     = const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
      const int         local = A.RowMap().LID(static_cast<int>(row));
      int               n     = 0;
      double           *values;
      int              *columns;
      A.ExtractMyRowView(local, n, values, columns);
      std::fill(values, values + n, 0.);
    }

    /// The owned entries of a (u, lambda) vector, in the order of its index set, are those of
    /// the displacements followed by those of the multipliers (all displacement indices are
    /// below the multiplier ones): copies them into @p u and @p lambda.
    inline void
    split(const dealii::TrilinosWrappers::MPI::Vector &x,
          dealii::TrilinosWrappers::MPI::Vector       &u,
          dealii::TrilinosWrappers::MPI::Vector       &lambda)
    {
      AssertDimension(x.locally_owned_size(), u.locally_owned_size() + lambda.locally_owned_size());
      const auto middle = x.begin() + u.locally_owned_size();
      std::copy(x.begin(), middle, u.begin());
      std::copy(middle, x.end(), lambda.begin());
    }

    /// The inverse of split().
    inline void
    join(const dealii::TrilinosWrappers::MPI::Vector &u,
         const dealii::TrilinosWrappers::MPI::Vector &lambda,
         dealii::TrilinosWrappers::MPI::Vector       &x)
    {
      AssertDimension(x.locally_owned_size(), u.locally_owned_size() + lambda.locally_owned_size());
      std::copy(lambda.begin(), lambda.end(), std::copy(u.begin(), u.end(), x.begin()));
    }
  } // namespace mechanics
} // namespace porofrac

#endif
