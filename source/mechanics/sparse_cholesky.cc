// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/sparse_cholesky.h>

#include <cholmod.h>

#include <cstring>
#include <sstream>

namespace porofrac
{
  namespace mechanics
  {
    struct SparseCholesky::Data
    {
      cholmod_common  common;
      cholmod_factor *factor = nullptr;
      /// Workspace of the sparse solves (cholmod_solve2).
      cholmod_dense  *B = nullptr, *X = nullptr, *Y = nullptr, *E = nullptr;
      cholmod_sparse *Bset = nullptr, *Xset = nullptr;
      std::vector<int> inverse_permutation;

      void
      free_workspace()
      {
        for (cholmod_dense **d : {&B, &X, &Y, &E})
          if (*d)
            cholmod_free_dense(d, &common);
        for (cholmod_sparse **sp : {&Bset, &Xset})
          if (*sp)
            cholmod_free_sparse(sp, &common);
      }
    };

    SparseCholesky::SparseCholesky()
      : data(new Data)
    {
      cholmod_start(&data->common);
      data->common.print = 0;
      // Supernodal LL^T (level-3 BLAS in factorization and block solves).
      data->common.supernodal = CHOLMOD_SUPERNODAL;
    }

    SparseCholesky::~SparseCholesky()
    {
      data->free_workspace();
      if (data->factor)
        cholmod_free_factor(&data->factor, &data->common);
      cholmod_finish(&data->common);
      delete data;
    }

    void
    SparseCholesky::factorize(const SparseMatrix<double> &matrix, const unsigned int n_rows)
    {
      n = n_rows;
      data->free_workspace();
      data->inverse_permutation.clear();
      if (data->factor)
        cholmod_free_factor(&data->factor, &data->common);
      // Row i of the (symmetric) CSR matrix is column i of the CSC matrix; keep the entries
      // with row index <= column index (stype = 1: upper triangle).
      std::size_t nnz = 0;
      for (unsigned int i = 0; i < n; ++i)
        for (auto it = matrix.begin(i); it != matrix.end(i); ++it)
          if (it->column() <= i)
            ++nnz;
      cholmod_sparse *A =
        cholmod_allocate_sparse(n, n, nnz, /*sorted*/ 0, /*packed*/ 1, /*stype*/ 1, CHOLMOD_REAL,
                                &data->common);
      int    *Ap = static_cast<int *>(A->p);
      int    *Ai = static_cast<int *>(A->i);
      double *Ax = static_cast<double *>(A->x);
      std::size_t k = 0;
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
      Ap[n] = k;
      data->factor = cholmod_analyze(A, &data->common);
      cholmod_factorize(A, data->factor, &data->common);
      const int status = data->common.status;
      cholmod_free_sparse(&A, &data->common);
      if (status != CHOLMOD_OK || data->factor->minor < n)
        {
          std::ostringstream s;
          s << "Cholesky factorization of the elasticity block failed (CHOLMOD status " << status
            << ", leading minor " << data->factor->minor << " of " << n
            << " not positive): the elasticity block alone is singular; use "
               "'Mechanics/Linear solver = full system'";
          throw SolverFailure(s.str());
        }
    }

    void
    SparseCholesky::solve(std::vector<double> &block, const unsigned int n_columns) const
    {
      AssertDimension(block.size(), std::size_t(n) * n_columns);
      if (n_columns == 0)
        return;
      cholmod_dense B;
      B.nrow  = n;
      B.ncol  = n_columns;
      B.nzmax = std::size_t(n) * n_columns;
      B.d     = n;
      B.x     = block.data();
      B.z     = nullptr;
      B.xtype = CHOLMOD_REAL;
      B.dtype = CHOLMOD_DOUBLE;
      cholmod_dense *X = cholmod_solve(CHOLMOD_A, data->factor, &B, &data->common);
      std::memcpy(block.data(), X->x, sizeof(double) * B.nzmax);
      cholmod_free_dense(&X, &data->common);
    }

    void
    SparseCholesky::solve(Vector<double> &x) const
    {
      AssertDimension(x.size(), n);
      std::vector<double> b(x.begin(), x.end());
      solve(b, 1);
      std::copy(b.begin(), b.end(), x.begin());
    }

    void
    SparseCholesky::forward_sparse(const std::vector<std::pair<unsigned int, double>> &b,
                                   std::vector<std::pair<unsigned int, double>>       &y)
    {
      cholmod_common &c = data->common;
      if (data->inverse_permutation.empty())
        {
          // (P b)(k) = b(Perm[k]): entry b(i) goes to row IPerm[i] of L.
          data->inverse_permutation.resize(n);
          const int *perm = static_cast<const int *>(data->factor->Perm);
          for (unsigned int k = 0; k < n; ++k)
            data->inverse_permutation[perm ? perm[k] : k] = k;
          data->B    = cholmod_zeros(n, 1, CHOLMOD_REAL, &c);
          data->Bset = cholmod_allocate_sparse(n, 1, n, 0, 1, 0, CHOLMOD_PATTERN, &c);
        }
      double *Bx   = static_cast<double *>(data->B->x);
      int    *Bp   = static_cast<int *>(data->Bset->p);
      int    *Bi   = static_cast<int *>(data->Bset->i);
      Bp[0]        = 0;
      unsigned int k = 0;
      for (const auto &[i, v] : b)
        {
          const int row = data->inverse_permutation[i];
          Bx[row]       = v;
          Bi[k++]       = row;
        }
      Bp[1] = k;
      if (!cholmod_solve2(CHOLMOD_L, data->factor, data->B, data->Bset, &data->X, &data->Xset,
                          &data->Y, &data->E, &c))
        throw SolverFailure("sparse forward substitution failed (CHOLMOD status " +
                            std::to_string(c.status) + ")");
      for (unsigned int j = 0; j < k; ++j)
        Bx[Bi[j]] = 0;
      const int    *Xp = static_cast<const int *>(data->Xset->p);
      const int    *Xi = static_cast<const int *>(data->Xset->i);
      const double *Xx = static_cast<const double *>(data->X->x);
      y.clear();
      for (int p = Xp[0]; p < Xp[1]; ++p)
        if (Xx[Xi[p]] != 0)
          y.emplace_back(Xi[p], Xx[Xi[p]]);
    }

    double
    SparseCholesky::factor_nonzeros() const
    {
      return data->common.lnz;
    }
  } // namespace mechanics
} // namespace porofrac
