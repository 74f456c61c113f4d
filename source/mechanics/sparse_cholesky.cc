// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/lapack_templates.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/sparse_cholesky.h>

#include <algorithm>
#include <cstring>
#include <sstream>

#include <cholmod.h>

extern "C" void
dtrsm_(const char                    *side,
       const char                    *uplo,
       const char                    *transa,
       const char                    *diag,
       const dealii::types::blas_int *m,
       const dealii::types::blas_int *n,
       const double                  *alpha,
       const double                  *a,
       const dealii::types::blas_int *lda,
       double                        *b,
       const dealii::types::blas_int *ldb);

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /// CHOLMOD's 64-bit index type (its cholmod_l_* interface): factors of 3D P2 elasticity
      /// outgrow 32-bit indices (about 2e9 entries) before the memory of a large node.
      using Index = SuiteSparse_long;

      /// The numeric part of @p L after cholmod_l_analyze(): the supernodal values (xsize doubles)
      /// and row indices (ssize), or the lnz nonzeros of a simplicial factor, in MB.
      double
      factor_megabytes(const cholmod_factor *L, const cholmod_common &common)
      {
        const double bytes = L->is_super ? 8. * L->xsize + sizeof(Index) * L->ssize :
                                           (8. + sizeof(Index)) * common.lnz;
        return bytes / (1024. * 1024.);
      }

      const std::string advice = "use a coarser mesh or the iterative distributed solver "
                                 "(Distributed = always, Mechanics/Distributed linear solver = "
                                 "iterative)";

      /// What the copy of the upper triangle (@p nnz entries of @p n rows: an index and a value
      /// each, and the column starts) and CHOLMOD's analysis take at least, in MB. The analysis
      /// (the ordering: AMD, METIS) took 23-38 bytes per entry of the process's memory on our
      /// matrices (doc/mechanics.md); 20 are counted.
      double
      analysis_megabytes(const std::size_t n, const std::size_t nnz)
      {
        return (8. * (n + 1) + (16. + 20.) * nnz) / (1024. * 1024.);
      }

      /// Throws for a CHOLMOD call that could not allocate its result: out of memory, or a
      /// factor with more entries than CHOLMOD's indices address. Neither is a
      /// singular block, so no other direct solver is tried in its place.
      void
      check_allocated(const void *result, const cholmod_common &common, const std::string &what)
      {
        if (result && common.status >= CHOLMOD_OK)
          return;
        const std::string reason =
          common.status == CHOLMOD_TOO_LARGE ?
            "its factor would have more entries than CHOLMOD's indices address" :
          common.status == CHOLMOD_OUT_OF_MEMORY ?
            "out of memory" :
            "CHOLMOD status " + std::to_string(common.status);
        throw InsufficientMemory("Cholesky factorization of the elasticity block: " + what +
                                 " failed (" + reason + "); " + advice);
      }
    } // namespace

    struct SparseCholesky::Data
    {
      cholmod_common  common;
      cholmod_factor *factor = nullptr;

      /// Rows [first_row, first_row + n_rows) of Y = L^{-1} P B in the columns that reach them
      /// (dense, column-major): one block per supernode, kept by inverse_gram().
      struct YBlock
      {
        int                       first_row, n_rows;
        std::vector<unsigned int> columns;
        std::vector<double>       values;
      };
      std::vector<YBlock> Y;

      /// x = op(x) for the CHOLMOD solve type @p system, in place.
      void
      apply(const int system, double *x, const unsigned int n, const unsigned int n_columns)
      {
        cholmod_dense B;
        B.nrow           = n;
        B.ncol           = n_columns;
        B.nzmax          = std::size_t(n) * n_columns;
        B.d              = n;
        B.x              = x;
        B.z              = nullptr;
        B.xtype          = CHOLMOD_REAL;
        B.dtype          = CHOLMOD_DOUBLE;
        cholmod_dense *X = cholmod_l_solve(system, factor, &B, &common);
        std::memcpy(x, X->x, sizeof(double) * B.nzmax);
        cholmod_l_free_dense(&X, &common);
      }
    };

    SparseCholesky::SparseCholesky()
        : data(new Data)
    {
      cholmod_l_start(&data->common);
      data->common.print = 0;
      // Supernodal LL^T (level-3 BLAS in factorization and block solves).
      data->common.supernodal = CHOLMOD_SUPERNODAL;
    }

    SparseCholesky::~SparseCholesky()
    {
      if (data->factor)
        cholmod_l_free_factor(&data->factor, &data->common);
      cholmod_l_finish(&data->common);
      delete data;
    }

    void
    SparseCholesky::factorize(const SparseMatrix<double>        &matrix,
                              const unsigned int                 n_rows,
                              const std::function<void(double)> &check_memory)
    {
      n = n_rows;
      if (data->factor)
        cholmod_l_free_factor(&data->factor, &data->common);
      // Row i of the (symmetric) CSR matrix is column i of the CSC matrix; keep the entries
      // with row index <= column index (stype = 1: upper triangle).
      std::size_t nnz = 0;
      for (unsigned int i = 0; i < n; ++i)
        for (auto it = matrix.begin(i); it != matrix.end(i); ++it)
          if (it->column() <= i)
            ++nnz;
      // The copy and the ordering come before @p check_memory sees the factor.
      require_memory(analysis_megabytes(n, nnz),
                     "Cholesky factorization of the elasticity block: the copy of its upper "
                     "triangle (" +
                       std::to_string(nnz) + " entries) and its ordering",
                     "factorize it",
                     advice);
      cholmod_sparse *A = cholmod_l_allocate_sparse(
        n, n, nnz, /*sorted*/ 0, /*packed*/ 1, /*stype*/ 1, CHOLMOD_REAL, &data->common);
      check_allocated(A, data->common, "copying the matrix");
      Index      *Ap = static_cast<Index *>(A->p);
      Index      *Ai = static_cast<Index *>(A->i);
      double     *Ax = static_cast<double *>(A->x);
      std::size_t k  = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          Ap[i] = k;
          for (auto it = matrix.begin(i); it != matrix.end(i); ++it)
            if (it->column() <= i)
              {
                Ai[k] = it->column();
                Ax[k] = it->value();
                ++k;
              }
        }
      Ap[n]        = k;
      data->factor = cholmod_l_analyze(A, &data->common);
      try
        {
          check_allocated(data->factor,
                          data->common,
                          "the symbolic analysis of " + std::to_string(n) + " rows");
          if (check_memory)
            check_memory(factor_megabytes(data->factor, data->common));
        }
      catch (...)
        {
          cholmod_l_free_sparse(&A, &data->common);
          if (data->factor)
            cholmod_l_free_factor(&data->factor, &data->common);
          throw;
        }
      cholmod_l_factorize(A, data->factor, &data->common);
      const int status = data->common.status;
      cholmod_l_free_sparse(&A, &data->common);
      if (status == CHOLMOD_OUT_OF_MEMORY || status == CHOLMOD_TOO_LARGE)
        check_allocated(nullptr, data->common, "the numeric factorization");
      // A rigid-body mode makes the block singular; in floating point its last pivot may come
      // out tiny and positive instead of failing, so also reject a negligible reciprocal
      // condition estimate ((min_i L_ii / max_i L_ii)^2).
      const double rcond = (status == CHOLMOD_OK && data->factor->minor >= n) ?
                             cholmod_l_rcond(data->factor, &data->common) :
                             0.;
      if (status != CHOLMOD_OK || data->factor->minor < n || !(rcond > 1e-14))
        {
          std::ostringstream s;
          s << "Cholesky factorization of the elasticity block failed (CHOLMOD status " << status
            << ", leading minor " << data->factor->minor << " of " << n
            << ", reciprocal condition estimate " << rcond
            << "): the elasticity block alone is singular";
          throw SolverFailure(s.str());
        }
    }

    void
    SparseCholesky::solve(std::vector<double> &block, const unsigned int n_columns) const
    {
      AssertDimension(block.size(), std::size_t(n) * n_columns);
      if (n_columns == 0)
        return;
      data->apply(CHOLMOD_A, block.data(), n, n_columns);
    }

    void
    SparseCholesky::forward(std::vector<double> &x) const
    {
      AssertDimension(x.size(), n);
      data->apply(CHOLMOD_P, x.data(), n, 1);
      data->apply(CHOLMOD_L, x.data(), n, 1);
    }

    void
    SparseCholesky::backward(std::vector<double> &x) const
    {
      AssertDimension(x.size(), n);
      data->apply(CHOLMOD_Lt, x.data(), n, 1);
      data->apply(CHOLMOD_Pt, x.data(), n, 1);
    }

    void
    SparseCholesky::gram_factor_transpose_vmult(const std::vector<double> &z,
                                                Vector<double>            &out) const
    {
      out = 0;
      for (const auto &b : data->Y)
        for (unsigned int a = 0; a < b.columns.size(); ++a)
          {
            const double *y   = b.values.data() + std::size_t(a) * b.n_rows;
            const double *x   = z.data() + b.first_row;
            double        sum = 0;
            for (int i = 0; i < b.n_rows; ++i)
              sum += y[i] * x[i];
            out(b.columns[a]) += sum;
          }
    }

    void
    SparseCholesky::gram_factor_vmult_subtract(const Vector<double> &v,
                                               std::vector<double>  &z) const
    {
      for (const auto &b : data->Y)
        for (unsigned int a = 0; a < b.columns.size(); ++a)
          {
            const double  va = v(b.columns[a]);
            const double *y  = b.values.data() + std::size_t(a) * b.n_rows;
            double       *x  = z.data() + b.first_row;
            if (va != 0)
              for (int i = 0; i < b.n_rows; ++i)
                x[i] -= va * y[i];
          }
    }

    void
    SparseCholesky::solve(Vector<double> &x) const
    {
      AssertDimension(x.size(), n);
      std::vector<double> b(x.begin(), x.end());
      solve(b, 1);
      std::copy(b.begin(), b.end(), x.begin());
    }

    std::size_t
    SparseCholesky::inverse_gram(
      const std::vector<std::vector<std::pair<unsigned int, double>>> &columns,
      FullMatrix<double>                                              &G,
      const std::function<void(double)>                               &check_memory) const
    {
      const cholmod_factor *L = data->factor;
      data->Y.clear();
      Assert(L && L->is_super && L->is_ll, ExcInternalError());
      const int          nsuper = L->nsuper;
      const Index       *super  = static_cast<const Index *>(L->super);
      const Index       *pi     = static_cast<const Index *>(L->pi);
      const Index       *px     = static_cast<const Index *>(L->px);
      const Index       *Ls     = static_cast<const Index *>(L->s);
      const double      *Lx     = static_cast<const double *>(L->x);
      const Index       *perm   = static_cast<const Index *>(L->Perm);
      const unsigned int m      = columns.size();

      // Supernode of each (permuted) column of L, and the supernodal elimination tree: the
      // parent of s holds the first row of s below its diagonal block.
      std::vector<int> supernode_of(n), parent(nsuper, -1), row_of(n);
      for (int s = 0; s < nsuper; ++s)
        {
          for (int j = super[s]; j < super[s + 1]; ++j)
            supernode_of[j] = s;
        }
      for (int s = 0; s < nsuper; ++s)
        {
          const int n_columns = super[s + 1] - super[s];
          if (pi[s + 1] - pi[s] > n_columns)
            parent[s] = supernode_of[Ls[pi[s] + n_columns]];
        }
      for (unsigned int k = 0; k < n; ++k)
        row_of[perm ? perm[k] : k] = k; // (P b)(k) = b(perm[k])

      // Columns of B reaching each supernode (sorted, since k increases): the union of the
      // paths from the supernodes of their rows to the root.
      std::vector<std::vector<unsigned int>> reaching(nsuper);
      {
        std::vector<int> mark(nsuper, -1);
        for (unsigned int k = 0; k < m; ++k)
          for (const auto &entry : columns[k])
            for (int s = supernode_of[row_of[entry.first]]; s != -1 && mark[s] != int(k);
                 s     = parent[s])
              {
                    mark[s] = k;
                    reaching[s].push_back(k);
              }
      }
      if (check_memory)
        {
          double y_entries = 0;
          for (int s = 0; s < nsuper; ++s)
            y_entries += double(super[s + 1] - super[s]) * reaching[s].size();
          check_memory(8. * y_entries / (1024. * 1024.));
        }
      const auto position = [&](const int s, const unsigned int k) {
        return std::lower_bound(reaching[s].begin(), reaching[s].end(), k) - reaching[s].begin();
      };

      // Dense blocks of Y (rows of supernode s x columns reaching it, column-major), allocated
      // when first touched and released once s is done.
      std::vector<std::vector<double>> block(nsuper);
      const auto                       block_of = [&](const int s) -> std::vector<double>                       &{
        if (block[s].empty())
          block[s].assign(std::size_t(super[s + 1] - super[s]) * reaching[s].size(), 0.);
        return block[s];
      };
      for (unsigned int k = 0; k < m; ++k)
        for (const auto &[row, value] : columns[k])
          {
            const int j = row_of[row], s = supernode_of[j], n_columns = super[s + 1] - super[s];
            block_of(s)[(j - super[s]) + position(s, k) * n_columns] += value;
          }

      std::vector<double>         Gd(std::size_t(m) * m, 0.), update, gram;
      std::vector<std::ptrdiff_t> target_column;
      std::size_t                 nonzeros = 0;
      for (int s = 0; s < nsuper; ++s)
        {
          const std::vector<unsigned int> &cols = reaching[s];
          if (cols.empty())
            continue;
          const types::blas_int ncol = super[s + 1] - super[s], nrow = pi[s + 1] - pi[s],
                                nbelow = nrow - ncol, kk = cols.size();
          std::vector<double> &Y   = block_of(s);
          const double        *L_s = Lx + px[s];
          const double         one = 1., zero = 0.;
          // Y_s = L_ss^{-1} Y_s
          dtrsm_("L", "L", "N", "N", &ncol, &kk, &one, L_s, &nrow, Y.data(), &ncol);
          nonzeros += std::size_t(ncol) * kk;
          // G(cols, cols) += Y_s^T Y_s (upper triangle in column-major Gd: row <= column)
          if (std::size_t(kk) == m)
            syrk("U", "T", &kk, &ncol, &one, Y.data(), &ncol, &one, Gd.data(), &kk);
          else
            {
              gram.resize(std::size_t(kk) * kk);
              syrk("U", "T", &kk, &ncol, &one, Y.data(), &ncol, &zero, gram.data(), &kk);
              for (types::blas_int b = 0; b < kk; ++b)
                for (types::blas_int a = 0; a <= b; ++a)
                  Gd[cols[a] + std::size_t(cols[b]) * m] += gram[a + std::size_t(b) * kk];
            }
          // Rows below the diagonal block: Y_t -= L_bs Y_s for the ancestors t holding them.
          if (nbelow > 0)
            {
              update.resize(std::size_t(nbelow) * kk);
              gemm("N",
                   "N",
                   &nbelow,
                   &kk,
                   &ncol,
                   &one,
                   L_s + ncol,
                   &nrow,
                   Y.data(),
                   &ncol,
                   &zero,
                   update.data(),
                   &nbelow);
              const Index *rows = Ls + pi[s] + ncol;
              for (types::blas_int i = 0; i < nbelow;)
                {
                  const int t = supernode_of[rows[i]], t_columns = super[t + 1] - super[t];
                  target_column.resize(kk);
                  // cols is a subset of reaching[t] (both sorted): merge.
                  const std::vector<unsigned int> &cols_t = reaching[t];
                  for (types::blas_int a = 0, b = 0; a < kk; ++a)
                    {
                      while (cols_t[b] != cols[a])
                        ++b;
                      target_column[a] = std::ptrdiff_t(b) * t_columns;
                    }
                  std::vector<double> &Y_t = block_of(t);
                  for (; i < nbelow && supernode_of[rows[i]] == t; ++i)
                    {
                      double *y = Y_t.data() + (rows[i] - super[t]);
                      for (types::blas_int a = 0; a < kk; ++a)
                        y[target_column[a]] -= update[i + std::size_t(a) * nbelow];
                    }
                }
            }
          // Supernode s is done: its column list and block move into the kept Y (only
          // descendants, all processed, read reaching[s]).
          data->Y.push_back({int(super[s]), int(ncol), std::move(reaching[s]), std::move(Y)});
        }
      G.reinit(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = i; j < m; ++j)
          G(i, j) = G(j, i) = Gd[i + std::size_t(j) * m];
      return nonzeros;
    }

    double
    SparseCholesky::factor_nonzeros() const
    {
      return data->common.lnz;
    }
  } // namespace mechanics
} // namespace porofrac
