// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/multiplier_schur_complement.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

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
      const std::vector<bool>                       &constrained,
      const MultiplierStabilization                 &stabilization)
        : n_u(n_u)
        , n_f(coupling.size())
        , entries(coupling.size())
        , measures(face_measures)
    {
      for (unsigned int f = 0; f < n_f; ++f)
        for (const CouplingEntry &e : coupling[f])
          if (!constrained[e.dof])
            entries[f].push_back(e);

      // The dense matrices first, before the symbolic analysis of K takes its own memory, then
      // with the factor that analysis sizes, then with Y (below).
      check_memory(0., 0.);
      Timer clock;
      K.factorize(base_matrix, n_u, [this](const double factor_mb) {
        check_memory(factor_mb, 0.);
      });
      time_cholesky = clock.wall_time();

      // W = J K^{-1} B^T = G M with G = J K^{-1} J^T (M = face measures): the columns of J^T
      // live on the few dofs of one face each, so G is formed by the sparse-column Gram
      // product of the Cholesky factor (SparseCholesky::inverse_gram).
      clock.restart();
      const unsigned int                                        m = dim * n_f;
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
      // The factor is held by now (the run's available memory no longer includes it): Y = L^{-1}
      // P J^T, which the elimination tree sizes before it is allocated, and the dense matrices.
      reach_entries =
        K.inverse_gram(columns, G, [this](const double solves_mb) { check_memory(0., solves_mb); });
      W.reinit(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          W(i, j) = G(i, j) * measures[j / dim];
      for (unsigned int f = 0; f < stabilization.size(); ++f)
        for (const auto &[g, s] : stabilization[f])
          for (unsigned int k = 0; k < dim; ++k)
            {
              W(dim * f + k, dim * f + k) += s;
              W(dim * f + k, dim * g + k) -= s;
            }
      time_form_W = clock.wall_time();
    }

    template <int dim>
    bool
    MultiplierSchurComplement<dim>::set_rows(const std::vector<Tensor<2, dim>> &AlR,
                                             const std::vector<Tensor<2, dim>> &AjR)
    {
      if (factorized && AlR == rows_l && AjR == rows_j)
        return true;
      Timer clock;
      rows_l = AlR;
      rows_j = AjR;
      assemble_reduced();
      const unsigned int m_r = offset[n_f];
      null_right.clear();
      null_left.clear();
      svd_rank = 0;
      if (m_r > 0)
        {
          // LAPACK reports a zero pivot by an exception; the face rows of this iterate make
          // the contact Jacobian singular, a failed step rather than an internal error.
          bool singular = false;
          try
            {
              S.compute_lu_factorization();
            }
          catch (const dealii::ExceptionBase &)
            {
              singular = true;
            }
          // A numerically singular S (on 3D meshes where the face-wise constant multipliers
          // are not inf-sup stable against P2, some multiplier directions load no
          // displacement, and face rows that leave them free make the Jacobian singular)
          // shows pivots at round-off, and LU alone returns a step of arbitrary size along its
          // null space. Such systems get the minimum-norm least-squares step instead: with
          // orthonormal bases V, L of the right and left null spaces (one step of inverse
          // iteration from the LU factors each: the pivot gap is ~1e-16 against >= 1e-4 on
          // the meshes measured), t = (I - V V^T) LU^{-1} (I - L L^T) r.
          // An exactly zero pivot leaves no usable LU factors: the truncated SVD gives the
          // same minimum-norm step (numerical rank at 1e-10 of the largest singular value).
          if (singular)
            {
              assemble_reduced();
              S.compute_svd();
              const double smax = S.singular_value(0);
              while (svd_rank < m_r && S.singular_value(svd_rank) > 1e-10 * smax)
                ++svd_rank;
              if (svd_rank == 0)
                {
                  clear_rows();
                  throw SolverFailure("the multiplier Schur complement (" + std::to_string(m_r) +
                                      " unknowns) of the contact Jacobian is zero");
                }
              factorized = true;
              ++n_dense_factorizations;
              time_dense_lu += clock.wall_time();
              return false;
            }
          double pmax = 0;
          for (unsigned int i = 0; i < m_r; ++i)
            pmax = std::max(pmax, std::abs(S(i, i)));
          unsigned int rank_deficit = 0;
          for (unsigned int i = 0; i < m_r; ++i)
            rank_deficit += !(std::abs(S(i, i)) > 1e-10 * pmax);
          if (rank_deficit > 0)
            {
              null_right = null_space(rank_deficit, false);
              null_left  = null_space(rank_deficit, true);
            }
        }
      factorized = true;
      ++n_dense_factorizations;
      time_dense_lu += clock.wall_time();
      return false;
    }



    template <int dim>
    std::vector<Vector<double>>
    MultiplierSchurComplement<dim>::null_space(const unsigned int n, const bool transposed) const
    {
      // Inverse iteration from fixed pseudo-random vectors: the LU solve amplifies the null
      // directions by 1/(round-off pivot); two steps, then Gram-Schmidt.
      const unsigned int          m_r = offset[n_f];
      std::vector<Vector<double>> basis;
      for (unsigned int k = 0; k < n; ++k)
        {
          Vector<double> v(m_r);
          unsigned int   seed = 12345u + 7919u * k;
          for (unsigned int i = 0; i < m_r; ++i)
            {
              seed = 1664525u * seed + 1013904223u;
              v(i) = static_cast<double>(seed) / 4294967296. - 0.5;
            }
          for (unsigned int step = 0; step < 2; ++step)
            {
              S.solve(v, transposed);
              for (const Vector<double> &b : basis)
                v.add(-(v * b), b);
              v /= v.l2_norm();
            }
          basis.push_back(v);
        }
      return basis;
    }



    template <int dim>
    void
    MultiplierSchurComplement<dim>::assemble_reduced()
    {
      const std::vector<Tensor<2, dim>> &AlR = rows_l, &AjR = rows_j;
      const unsigned int                 m = dim * n_f;

      // Split each face's rows; for the rows without jump term, E_f^+ = E^T (E E^T)^{-1} and an
      // orthonormal basis of null(E_f) (Gram-Schmidt on the columns of I - E_f^+ E_f).
      kept_rows.assign(n_f, {});
      free_rows.assign(n_f, {});
      pseudo_inverse.assign(n_f, FullMatrix<double>());
      null_basis.assign(n_f, FullMatrix<double>());
      offset.assign(n_f + 1, 0);
      for (unsigned int f = 0; f < n_f; ++f)
        {
          for (unsigned int i = 0; i < dim; ++i)
            {
              bool has_jump = false;
              for (unsigned int k = 0; k < dim; ++k)
                has_jump = has_jump || AjR[f][i][k] != 0;
              (has_jump ? kept_rows[f] : free_rows[f]).push_back(i);
            }
          const unsigned int n_free = free_rows[f].size();
          offset[f + 1]             = offset[f] + dim - n_free;
          FullMatrix<double> E(n_free, dim), projector(dim, dim);
          for (unsigned int r = 0; r < n_free; ++r)
            for (unsigned int k = 0; k < dim; ++k)
              E(r, k) = AlR[f][free_rows[f][r]][k];
          projector = IdentityMatrix(dim);
          if (n_free > 0)
            {
              FullMatrix<double> EEt(n_free, n_free), EEt_inverse(n_free, n_free);
              E.mTmult(EEt, E);
              EEt_inverse.invert(EEt);
              pseudo_inverse[f].reinit(dim, n_free);
              E.Tmmult(pseudo_inverse[f], EEt_inverse);
              FullMatrix<double> PE(dim, dim);
              pseudo_inverse[f].mmult(PE, E);
              projector.add(-1., PE);
            }
          null_basis[f].reinit(dim, dim - n_free);
          unsigned int found = 0;
          for (unsigned int k = 0; k < dim && found < dim - n_free; ++k)
            {
              Vector<double> v(dim);
              for (unsigned int r = 0; r < dim; ++r)
                v(r) = projector(r, k);
              for (unsigned int b = 0; b < found; ++b)
                {
                  double dot = 0;
                  for (unsigned int r = 0; r < dim; ++r)
                    dot += v(r) * null_basis[f](r, b);
                  for (unsigned int r = 0; r < dim; ++r)
                    v(r) -= dot * null_basis[f](r, b);
                }
              // The columns of the orthogonal projector onto null(E_f) have squared norms
              // summing to its rank, so while the basis is incomplete the leftover squared
              // norms sum to >= 1 and (dim <= 3) a column with norm > 0.5 remains: that
              // threshold always completes the basis and never normalizes round-off.
              const double norm = v.l2_norm();
              if (norm > 0.5)
                {
                  for (unsigned int r = 0; r < dim; ++r)
                    null_basis[f](r, found) = v(r) / norm;
                  ++found;
                }
            }
          AssertThrow(found == dim - n_free, ExcInternalError());
        }
      const unsigned int m_r = offset[n_f];

      // WN = W blockdiag(N_f): the columns of W for the reduced unknowns.
      FullMatrix<double> WN(m, m_r);
      for (unsigned int row = 0; row < m; ++row)
        for (unsigned int g = 0; g < n_f; ++g)
          for (unsigned int t = 0; t < null_basis[g].n(); ++t)
            {
              double s = 0;
              for (unsigned int k = 0; k < dim; ++k)
                s += W(row, dim * g + k) * null_basis[g](k, t);
              WN(row, offset[g] + t) = s;
            }
      // S = (A_l - A_j W) N on the kept rows, each row equilibrated by its largest entry (the
      // rows mix multiplier rows of order 1 with jump rows scaled by c, Section 5.1).
      S.reinit(m_r, m_r);
      row_scale.assign(m_r, 1.);
      for (unsigned int f = 0; f < n_f; ++f)
        for (unsigned int r = 0; r < kept_rows[f].size(); ++r)
          {
            const unsigned int i = kept_rows[f][r], row = offset[f] + r;
            for (unsigned int col = 0; col < m_r; ++col)
              {
                double s = 0;
                for (unsigned int k = 0; k < dim; ++k)
                  if (AjR[f][i][k] != 0)
                    s -= AjR[f][i][k] * WN(dim * f + k, col);
                S(row, col) = s;
              }
            for (unsigned int t = 0; t < null_basis[f].n(); ++t)
              for (unsigned int k = 0; k < dim; ++k)
                S(row, offset[f] + t) += AlR[f][i][k] * null_basis[f](k, t);
            double big = 0;
            for (unsigned int col = 0; col < m_r; ++col)
              big = std::max(big, std::abs(S(row, col)));
            if (big > 0)
              {
                row_scale[row] = 1. / big;
                for (unsigned int col = 0; col < m_r; ++col)
                  S(row, col) *= row_scale[row];
              }
          }
    }

    template <int dim>
    void
    MultiplierSchurComplement<dim>::clear_rows()
    {
      rows_l.clear();
      rows_j.clear();
      kept_rows.clear();
      free_rows.clear();
      pseudo_inverse.clear();
      null_basis.clear();
      offset.clear();
      row_scale.clear();
      S.reinit(0, 0);
      null_right.clear();
      null_left.clear();
      svd_rank   = 0;
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
      // (A_l - A_j W) dl = r_l - A_j J K^{-1} r_u. Rows without jump term first: their part
      // of dl is x_f = E_f^+ e_f; the kept rows then solve for t, dl_f = x_f + N_f t_f.
      Vector<double> j(m), dl(m), x(m);
      K.gram_factor_transpose_vmult(y, j);
      bool any_free = false;
      for (unsigned int f = 0; f < n_f; ++f)
        for (unsigned int r = 0; r < free_rows[f].size(); ++r)
          {
            const double e = rhs(n_u + dim * f + free_rows[f][r]);
            for (unsigned int k = 0; k < dim; ++k)
              x(dim * f + k) += pseudo_inverse[f](k, r) * e;
            any_free = true;
          }
      Vector<double> Wx(m);
      if (any_free)
        W.vmult(Wx, x);
      const unsigned int m_r = offset[n_f];
      Vector<double>     t(m_r);
      for (unsigned int f = 0; f < n_f; ++f)
        for (unsigned int r = 0; r < kept_rows[f].size(); ++r)
          {
            const unsigned int i = kept_rows[f][r];
            double             b = rhs(n_u + dim * f + i);
            for (unsigned int k = 0; k < dim; ++k)
              b -= rows_j[f][i][k] * (j(dim * f + k) - Wx(dim * f + k)) +
                   rows_l[f][i][k] * x(dim * f + k);
            t(offset[f] + r) = b * row_scale[offset[f] + r];
          }
      if (m_r > 0 && svd_rank > 0)
        {
          // t = V diag(1/s_i, i < rank) U^T t
          const LAPACKFullMatrix<double> &U = S.get_svd_u(), &Vt = S.get_svd_vt();
          Vector<double>                  c(svd_rank);
          for (unsigned int i = 0; i < svd_rank; ++i)
            {
              double s = 0;
              for (unsigned int r = 0; r < m_r; ++r)
                s += U(r, i) * t(r);
              c(i) = s / S.singular_value(i);
            }
          for (unsigned int r = 0; r < m_r; ++r)
            {
              double s = 0;
              for (unsigned int i = 0; i < svd_rank; ++i)
                s += Vt(i, r) * c(i);
              t(r) = s;
            }
        }
      else if (m_r > 0)
        {
          for (const Vector<double> &l : null_left)
            t.add(-(t * l), l);
          S.solve(t);
          for (const Vector<double> &v : null_right)
            t.add(-(t * v), v);
        }
      for (unsigned int f = 0; f < n_f; ++f)
        for (unsigned int k = 0; k < dim; ++k)
          {
            double v = x(dim * f + k);
            for (unsigned int c = 0; c < null_basis[f].n(); ++c)
              v += null_basis[f](k, c) * t(offset[f] + c);
            dl(dim * f + k) = v;
          }
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

    template <int dim>
    void
    MultiplierSchurComplement<dim>::check_memory(const double factor_mb,
                                                 const double solves_mb) const
    {
      // W, and during the contact iterations the reduced complement S with its column block W N:
      // three dense matrices of order m = dim x faces at least (the SVD of a singular S adds two;
      // while W is formed, G and its accumulator take the place of S and W N).
      const double             m        = dim * n_f;
      const double             dense_mb = 3. * 8. * m * m / (1024. * 1024.);
      std::vector<std::string> parts;
      if (factor_mb > 0)
        parts.push_back("the Cholesky factor of K (" + memory_size_text(factor_mb) + ")");
      if (solves_mb > 0)
        parts.push_back("the solves of its factor with the " + std::to_string(dim * n_f) +
                        " multiplier columns (" + memory_size_text(solves_mb) + ")");
      parts.push_back("the dense matrices for " + std::to_string(dim * n_f) + " multipliers" +
                      (parts.empty() ? "" : " (" + memory_size_text(dense_mb) + ")"));
      std::string listed = parts[0];
      for (unsigned int i = 1; i < parts.size(); ++i)
        listed += (i + 1 == parts.size() ? " and " : ", ") + parts[i];
      require_memory(factor_mb + solves_mb + dense_mb,
                     "multiplier Schur complement: " + listed,
                     "solve the contact problem",
                     "use a coarser mesh or the iterative distributed solver (Distributed = "
                     "always, or Coupling/Distributed contact mechanics = true, with "
                     "Mechanics/Distributed linear solver = iterative)");
    }



    template class MultiplierSchurComplement<2>;
    template class MultiplierSchurComplement<3>;
  } // namespace mechanics
} // namespace porofrac
