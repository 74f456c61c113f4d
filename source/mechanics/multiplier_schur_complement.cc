// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/mechanics/multiplier_schur_complement.h>

#include <algorithm>
#include <cmath>

namespace porofrac
{
  namespace mechanics
  {
    template <int dim>
    MultiplierSchurComplement<dim>::MultiplierSchurComplement(
      const SparseMatrix<double>                    &base_matrix,
      const unsigned int                             n_u,
      const std::vector<std::vector<CouplingEntry>> &coupling,
      const std::vector<double>                     &face_measures,
      const std::vector<bool>                       &constrained)
      : n_u(n_u)
      , n_f(coupling.size())
      , entries(coupling.size())
      , measures(face_measures)
    {
      for (unsigned int f = 0; f < n_f; ++f)
        for (const CouplingEntry &e : coupling[f])
          if (!constrained[e.dof])
            entries[f].push_back(e);

      Timer clock;
      K.factorize(base_matrix, n_u);
      time_cholesky = clock.wall_time();

      // W = J K^{-1} B^T = G M with G = J K^{-1} J^T (M = face measures): the columns of J^T
      // live on the few dofs of one face each, so G is formed by the sparse-column Gram
      // product of the Cholesky factor (SparseCholesky::inverse_gram).
      clock.restart();
      const unsigned int m = dim * n_f;
      std::vector<std::vector<std::pair<unsigned int, double>>> columns(m);
      for (unsigned int k = 0; k < m; ++k)
        {
          const unsigned int g = k / dim, d = k % dim;
          auto              &b = columns[k];
          for (const CouplingEntry &e : entries[g])
            if (e.component == d)
              b.emplace_back(e.dof, e.value / measures[g]);
          // merge repeated dofs
          std::sort(b.begin(), b.end());
          unsigned int w = 0;
          for (unsigned int i = 0; i < b.size(); ++i)
            if (w > 0 && b[w - 1].first == b[i].first)
              b[w - 1].second += b[i].second;
            else
              b[w++] = b[i];
          b.resize(w);
        }
      FullMatrix<double> G;
      reach_entries = K.inverse_gram(columns, G);
      W.reinit(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          W(i, j) = G(i, j) * measures[j / dim];
      time_form_W = clock.wall_time();
    }

    template <int dim>
    bool
    MultiplierSchurComplement<dim>::set_rows(const std::vector<Tensor<2, dim>> &AlR,
                                             const std::vector<Tensor<2, dim>> &AjR)
    {
      if (factorized && AlR == rows_l && AjR == rows_j)
        return true;
      Timer              clock;
      const unsigned int m = dim * n_f;
      rows_l               = AlR;
      rows_j               = AjR;
      S.reinit(m, m);
      row_scale.assign(m, 1.);
      // S = A_l - A_j W (face-block rows), each row equilibrated by its largest entry (the
      // rows mix multiplier rows of order 1 with jump rows scaled by c, Section 5.1).
      for (unsigned int f = 0; f < n_f; ++f)
        for (unsigned int i = 0; i < dim; ++i)
          {
            const unsigned int row = dim * f + i;
            double             big = 0;
            for (unsigned int col = 0; col < m; ++col)
              {
                double s = 0;
                for (unsigned int k = 0; k < dim; ++k)
                  if (AjR[f][i][k] != 0)
                    s -= AjR[f][i][k] * W(dim * f + k, col);
                S(row, col) = s;
              }
            for (unsigned int k = 0; k < dim; ++k)
              S(row, dim * f + k) += AlR[f][i][k];
            for (unsigned int col = 0; col < m; ++col)
              big = std::max(big, std::abs(S(row, col)));
            if (big > 0)
              {
                row_scale[row] = 1. / big;
                for (unsigned int col = 0; col < m; ++col)
                  S(row, col) *= row_scale[row];
              }
          }
      S.compute_lu_factorization();
      factorized = true;
      ++n_dense_factorizations;
      time_dense_lu += clock.wall_time();
      return false;
    }

    template <int dim>
    void
    MultiplierSchurComplement<dim>::clear_rows()
    {
      rows_l.clear();
      rows_j.clear();
      row_scale.clear();
      S.reinit(0, 0);
      factorized = false;
    }

    template <int dim>
    void
    MultiplierSchurComplement<dim>::solve(const Vector<double> &rhs, Vector<double> &solution) const
    {
      Assert(factorized, ExcInternalError());
      const unsigned int m = dim * n_f;
      Timer              clock;
      // z = L^{-1} P r_u; J K^{-1} r_u = Y^T z with Y = L^{-1} P J^T (kept from forming W).
      std::vector<double> y(rhs.begin(), rhs.begin() + n_u);
      K.forward(y);
      time_solves += clock.wall_time();
      // (A_l - A_j W) dl = r_l - A_j J K^{-1} r_u
      Vector<double> j(m), dl(m);
      K.gram_factor_transpose_vmult(y, j);
      for (unsigned int f = 0; f < n_f; ++f)
        for (unsigned int i = 0; i < dim; ++i)
          {
            double r = rhs(n_u + dim * f + i);
            for (unsigned int k = 0; k < dim; ++k)
              r -= rows_j[f][i][k] * j(dim * f + k);
            dl(dim * f + i) = r * row_scale[dim * f + i];
          }
      S.solve(dl);
      // du = K^{-1} (r_u - B^T dl) = P^T L^{-T} (z - Y M dl): one triangular solve pair per
      // iteration.
      clock.restart();
      Vector<double> scaled(m);
      for (unsigned int i = 0; i < m; ++i)
        scaled(i) = measures[i / dim] * dl(i);
      K.gram_factor_vmult_subtract(scaled, y);
      K.backward(y);
      time_solves += clock.wall_time();
      for (unsigned int i = 0; i < n_u; ++i)
        solution(i) = y[i];
      for (unsigned int i = 0; i < m; ++i)
        solution(n_u + i) = dl(i);
    }

    template class MultiplierSchurComplement<2>;
    template class MultiplierSchurComplement<3>;
  } // namespace mechanics
} // namespace porofrac
