// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/sparse_lu.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace porofrac
{
  using namespace dealii;

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

  void
  SparseLU::analyse(const SparseMatrix<double> &A)
  {
    free_numeric();
    free_symbolic();
    const SparsityPattern &sp = A.get_sparsity_pattern();
    const std::size_t      n  = A.m();
    row_start.assign(n + 1, 0);
    columns.clear();
    position.clear();
    columns.reserve(sp.n_nonzero_elements());
    position.reserve(sp.n_nonzero_elements());
    std::vector<std::pair<SuiteSparse_long, SuiteSparse_long>> row; // (column, stored index)
    SuiteSparse_long                                           k = 0;
    for (std::size_t r = 0; r < n; ++r)
      {
        row.clear();
        for (auto e = A.begin(r); e != A.end(r); ++e)
          row.emplace_back(e->column(), k++);
        std::sort(row.begin(), row.end());
        for (const auto &[c, index] : row)
          {
            (void)index;
            columns.push_back(c);
          }
        row_start[r + 1] = columns.size();
      }
    // position: stored index -> sorted slot.
    position.assign(columns.size(), 0);
    k = 0;
    for (std::size_t r = 0; r < n; ++r)
      {
        row.clear();
        for (auto e = A.begin(r); e != A.end(r); ++e)
          row.emplace_back(e->column(), k++);
        std::sort(row.begin(), row.end());
        for (std::size_t j = 0; j < row.size(); ++j)
          position[row[j].second] = row_start[r] + j;
      }
    values.assign(columns.size(), 0.);
    double    info[UMFPACK_INFO];
    const int status = umfpack_dl_symbolic(
      n, n, row_start.data(), columns.data(), nullptr, &symbolic, control, info);
    if (status != UMFPACK_OK)
      throw std::runtime_error("UMFPACK symbolic analysis failed with status " +
                               std::to_string(status));
    pattern      = &sp;
    pattern_size = sp.n_nonzero_elements();
    // UMFPACK's own peak estimates are upper bounds 5-28 times the peaks measured on our
    // matrices; the symmetric analysis's count of L + U nonzeros (AMD on A + A^T, diagonal
    // pivots) was 0.69-0.95 times the count factorized, so their values (8 bytes each) are a
    // lower bound of what the factorization stores (doc/mechanics.md).
    minimum_memory_mb = info[UMFPACK_STRATEGY_USED] == UMFPACK_STRATEGY_SYMMETRIC ?
                          8. * info[UMFPACK_SYMMETRIC_LUNZ] / (1024. * 1024.) :
                          0.;
  }

  void
  SparseLU::check_memory(const std::size_t n) const
  {
    const unsigned int copies    = ReplicatedSerialSolves::copies_per_machine();
    const double       need      = copies * minimum_memory_mb;
    const double       available = available_memory_mb();
    if (!(available > 0 && need > available))
      return;
    throw InsufficientMemory(
      "the UMFPACK LU factorization of " + std::to_string(n) + " rows would need at least " +
      memory_size_text(need) + " for the values of its factors" +
      (copies > 1 ? " for the " + std::to_string(copies) +
                      " processes on this machine that each factorize it" :
                    "") +
      ", more than the " + memory_size_text(available) +
      " available to this run on this machine; use a coarser mesh or an iterative or "
      "distributed linear solver");
  }

  void
  SparseLU::factorize(const SparseMatrix<double> &A)
  {
    const SparsityPattern &sp = A.get_sparsity_pattern();
    if (pattern != &sp || pattern_size != sp.n_nonzero_elements() || row_start.size() != A.m() + 1)
      analyse(A);
    SuiteSparse_long k = 0;
    for (std::size_t r = 0; r < A.m(); ++r)
      for (auto e = A.begin(r); e != A.end(r); ++e)
        values[position[k++]] = e->value();
    free_numeric();
    check_memory(A.m());
    double    info[UMFPACK_INFO];
    const int status = umfpack_dl_numeric(
      row_start.data(), columns.data(), values.data(), symbolic, &numeric, control, info);
    factor_nonzeros = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
    if (status == UMFPACK_ERROR_out_of_memory)
      {
        free_numeric();
        throw InsufficientMemory("the UMFPACK LU factorization of " + std::to_string(A.m()) +
                                 " rows ran out of memory; use a coarser mesh or an iterative "
                                 "or distributed linear solver");
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
