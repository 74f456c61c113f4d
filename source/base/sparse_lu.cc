// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/sparse_lu.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace porofrac
{
  using namespace dealii;

  namespace
  {
    const std::string advice = "use a coarser mesh or an iterative or distributed linear solver";
  }

  SparseLU::SparseLU(const unsigned int refinement_steps, const bool symmetric)
  {
    umfpack_dl_defaults(control);
    control[UMFPACK_IRSTEP] = refinement_steps;
    if (symmetric)
      control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
  }

  SparseLU::~SparseLU()
  {
    free_numeric();
    free_symbolic();
  }

  void
  SparseLU::free_numeric()
  {
    if (numeric)
      umfpack_dl_free_numeric(&numeric);
    numeric = nullptr;
  }

  void
  SparseLU::free_symbolic()
  {
    if (symbolic)
      umfpack_dl_free_symbolic(&symbolic);
    symbolic = nullptr;
  }

  namespace
  {
    /// Whether the stored entries of @p A's rows are in ascending column order, except a
    /// diagonal stored first if @p diagonal_first (deal.II's layout for square matrices).
    bool
    rows_in_column_order(const SparseMatrix<double> &A, const bool diagonal_first)
    {
      for (std::size_t r = 0; r < A.m(); ++r)
        {
          auto e = A.begin(r);
          if (diagonal_first && (e == A.end(r) || e->column() != r))
            return false;
          if (diagonal_first)
            ++e;
          bool        first    = true;
          std::size_t previous = 0;
          for (; e != A.end(r); ++e, first = false)
            {
              const std::size_t c = e->column();
              if ((!first && c <= previous) || (diagonal_first && c == r))
                return false;
              previous = c;
            }
        }
      return true;
    }

    /// out[start + j] = field(j-th entry of row @p r in column order), for rows that
    /// rows_in_column_order() accepts: a diagonal stored first goes to its sorted slot.
    template <typename Field, typename T>
    void
    copy_row(const SparseMatrix<double> &A,
             const std::size_t           r,
             const bool                  diagonal_first,
             SuiteSparse_long            slot,
             const Field                &field,
             std::vector<T>             &out)
    {
      auto e = A.begin(r);
      if (diagonal_first)
        {
          const T diagonal = field(*e);
          for (++e; e != A.end(r) && e->column() < r; ++e)
            out[slot++] = field(*e);
          out[slot++] = diagonal;
        }
      for (; e != A.end(r); ++e)
        out[slot++] = field(*e);
    }
  } // namespace



  void
  SparseLU::analyse(const SparseMatrix<double> &A)
  {
    free_numeric();
    free_symbolic();
    pattern               = nullptr;
    const std::size_t n   = A.m();
    const std::size_t nnz = A.get_sparsity_pattern().n_nonzero_elements();
    diagonal_first        = A.m() == A.n();
    // deal.II's layout (SparsityPattern): each row sorted by column, a square matrix's diagonal
    // first; the copy relies on it to place the values without an index array.
    if (!rows_in_column_order(A, diagonal_first))
      throw std::runtime_error("SparseLU: the matrix rows are not in column order");
    // The previous pattern's arrays go before the new ones are sized.
    std::vector<SuiteSparse_long>().swap(row_start);
    std::vector<SuiteSparse_long>().swap(columns);
    std::vector<double>().swap(values);
    check_analysis_memory(n, nnz);
    row_start.assign(n + 1, 0);
    columns.resize(nnz);
    for (std::size_t r = 0; r < n; ++r)
      {
        row_start[r + 1] = row_start[r] + (A.end(r) - A.begin(r));
        copy_row(
          A,
          r,
          diagonal_first,
          row_start[r],
          [](const auto &e) { return SuiteSparse_long(e.column()); },
          columns);
      }
    double    info[UMFPACK_INFO];
    const int status = umfpack_dl_symbolic(
      n, n, row_start.data(), columns.data(), nullptr, &symbolic, control, info);
    if (status == UMFPACK_ERROR_out_of_memory)
      throw InsufficientMemory("the UMFPACK analysis of " + std::to_string(n) +
                               " rows ran out of memory; " + advice);
    if (status != UMFPACK_OK)
      throw std::runtime_error("UMFPACK symbolic analysis failed with status " +
                               std::to_string(status));
    pattern      = &A.get_sparsity_pattern();
    pattern_size = nnz;
    // UMFPACK's own peak estimates are upper bounds 5-28 times the peaks measured on our
    // matrices; the symmetric analysis's count of L + U nonzeros (AMD on A + A^T, diagonal
    // pivots) was 0.69-0.95 times the count factorized, so their values (8 bytes each) are a
    // lower bound of what the factorization stores (doc/mechanics.md).
    minimum_memory_mb = info[UMFPACK_STRATEGY_USED] == UMFPACK_STRATEGY_SYMMETRIC ?
                          8. * info[UMFPACK_SYMMETRIC_LUNZ] / (1024. * 1024.) :
                          0.;
  }



  double
  SparseLU::analysis_memory_estimate_mb(const std::size_t n, const std::size_t nnz)
  {
    // The copy of the pattern: row starts and columns, 8 bytes each (the values are copied after
    // the analysis, whose peak they would raise). The symbolic analysis (the ordering of
    // A + A^T: AMD, METIS) took 25-43 bytes per nonzero of the process's memory on our matrices
    // (doc/mechanics.md); 20 are counted.
    const double bytes = 8. * (n + 1) + (8. + 20.) * nnz;
    return bytes / (1024. * 1024.);
  }



  void
  SparseLU::check_analysis_memory(const std::size_t n, const std::size_t nnz) const
  {
    require_memory(analysis_memory_estimate_mb(n, nnz),
                   "the UMFPACK analysis of " + std::to_string(n) + " rows and " +
                     std::to_string(nnz) + " nonzeros (its copy of the pattern and the ordering)",
                   "factorize it",
                   advice);
  }



  void
  SparseLU::check_memory(const std::size_t n) const
  {
    const double values_mb = values.empty() ? 8. * pattern_size / (1024. * 1024.) : 0.;
    require_memory(minimum_memory_mb + values_mb,
                   "the values of the L and U factors of the UMFPACK LU factorization of " +
                     std::to_string(n) + " rows",
                   "factorize it",
                   advice);
  }



  void
  SparseLU::factorize(const SparseMatrix<double> &A)
  {
    const SparsityPattern &sp = A.get_sparsity_pattern();
    if (pattern != &sp || pattern_size != sp.n_nonzero_elements() || row_start.size() != A.m() + 1)
      analyse(A);
    free_numeric();
    check_memory(A.m());
    values.resize(pattern_size);
    for (std::size_t r = 0; r < A.m(); ++r)
      copy_row(
        A, r, diagonal_first, row_start[r], [](const auto &e) { return e.value(); }, values);
    double    info[UMFPACK_INFO];
    const int status = umfpack_dl_numeric(
      row_start.data(), columns.data(), values.data(), symbolic, &numeric, control, info);
    factor_nonzeros = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
    if (status == UMFPACK_ERROR_out_of_memory)
      {
        free_numeric();
        throw InsufficientMemory("the UMFPACK LU factorization of " + std::to_string(A.m()) +
                                 " rows ran out of memory; " + advice);
      }
    if (status != UMFPACK_OK)
      {
        free_numeric();
        throw std::runtime_error(
          "UMFPACK numeric factorization failed with status " + std::to_string(status) +
          (status == UMFPACK_WARNING_singular_matrix ? " (singular matrix)" : ""));
      }
  }



  void
  SparseLU::solve(Vector<double> &x) const
  {
    if (!numeric)
      throw std::runtime_error("SparseLU::solve called without a factorization");
    const Vector<double> b = x;
    double               info[UMFPACK_INFO];
    // The arrays hold A row by row, i.e. A^T column by column: solve (A^T)^T x = b.
    const int status = umfpack_dl_solve(UMFPACK_At,
                                        row_start.data(),
                                        columns.data(),
                                        values.data(),
                                        x.begin(),
                                        b.begin(),
                                        numeric,
                                        control,
                                        info);
    if (status != UMFPACK_OK)
      throw std::runtime_error("UMFPACK solve failed with status " + std::to_string(status));
  }

  void
  SparseLU::vmult(Vector<double> &dst, const Vector<double> &src) const
  {
    dst = src;
    solve(dst);
  }
} // namespace porofrac
