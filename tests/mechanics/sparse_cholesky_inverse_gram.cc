// SPDX-License-Identifier: LGPL-2.1-or-later
// SparseCholesky::inverse_gram, the kernel of the Schur complement solver's W = J K^{-1} J^T:
// on the five-point Laplacian of a 40 x 40 grid (Dirichlet rows, SPD) with 60 sparse columns of
// two to four entries each, G = B^T K^{-1} B agrees with dense solves of K; the size of
// Y = L^{-1} P B that the memory hook receives before Y is allocated is exactly the size of the
// Y formed (8 bytes per entry of the returned count); Y^T (L^{-1} P b) = B^T K^{-1} b; and a
// hook that throws stops the call before G is formed.
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <porofrac/mechanics/sparse_cholesky.h>

#include <cmath>
#include <iostream>
#include <stdexcept>

#include "../grid_pattern.h"

using namespace dealii;

int
main()
{
  const unsigned int N = 40, n = N * N;
  SparsityPattern    pattern;
  pattern.copy_from(five_point_pattern(N));
  SparseMatrix<double> K(pattern);
  for (unsigned int r = 0; r < n; ++r)
    for (auto it = pattern.begin(r); it != pattern.end(r); ++it)
      K.set(r, it->column(), it->column() == r ? 4. : -1.);

  // Column k: entries on a short run of grid points, as a fracture face's P2 dofs are.
  const unsigned int                                        m = 60;
  std::vector<std::vector<std::pair<unsigned int, double>>> columns(m);
  for (unsigned int k = 0; k < m; ++k)
    {
      const unsigned int first = (37 * k + 11) % (n - 4), count = 2 + k % 3;
      for (unsigned int a = 0; a < count; ++a)
        columns[k].emplace_back(first + a, 1. + 0.25 * a - 0.1 * (k % 5));
    }

  porofrac::mechanics::SparseCholesky cholesky;
  cholesky.factorize(K, n);

  double             hook_mb = -1;
  FullMatrix<double> G;
  const std::size_t  entries =
    cholesky.inverse_gram(columns, G, [&](const double mb) { hook_mb = mb; });
  // The count depends on CHOLMOD's fill-reducing ordering; the columns reach part of it.
  std::cout << "Y entries between 1 and n x m: " << (entries > 0 && entries < std::size_t(n) * m)
            << ", hook called: " << (hook_mb >= 0) << ", hook size equals the Y formed: "
            << (hook_mb * 1024. * 1024. == 8. * double(entries)) << std::endl;

  // Dense reference: G_ij = b_i . K^{-1} b_j.
  std::vector<Vector<double>> solved(m, Vector<double>(n));
  double                      max_error = 0, max_entry = 0;
  for (unsigned int k = 0; k < m; ++k)
    {
      for (const auto &[row, value] : columns[k])
        solved[k](row) += value;
      cholesky.solve(solved[k]);
    }
  for (unsigned int i = 0; i < m; ++i)
    for (unsigned int j = 0; j < m; ++j)
      {
        double reference = 0;
        for (const auto &[row, value] : columns[i])
          reference += value * solved[j](row);
        max_error = std::max(max_error, std::abs(G(i, j) - reference));
        max_entry = std::max(max_entry, std::abs(reference));
      }
  std::cout << "G = B^T K^{-1} B: max error relative to max entry below 1e-12: "
            << (max_error <= 1e-12 * max_entry) << std::endl;

  // Y^T (L^{-1} P b) = B^T K^{-1} b for b = e_0 + e_(n-1).
  Vector<double> b(n), x(n), product(m);
  b(0) = b(n - 1) = 1;
  x               = b;
  cholesky.solve(x);
  std::vector<double> z(b.begin(), b.end());
  cholesky.forward(z);
  cholesky.gram_factor_transpose_vmult(z, product);
  double transpose_error = 0;
  for (unsigned int k = 0; k < m; ++k)
    {
      double reference = 0;
      for (const auto &[row, value] : columns[k])
        reference += value * x(row);
      transpose_error = std::max(transpose_error, std::abs(product(k) - reference));
    }
  std::cout << "Y^T L^{-1} P b = B^T K^{-1} b: " << (transpose_error <= 1e-12 * x.linfty_norm())
            << std::endl;

  FullMatrix<double> G_refused;
  try
    {
      cholesky.inverse_gram(columns, G_refused, [](double) {
        throw std::runtime_error("refused");
      });
      std::cout << "a throwing hook: not propagated" << std::endl;
    }
  catch (const std::runtime_error &e)
    {
      std::cout << "a throwing hook: propagated (" << e.what()
                << "), G not formed: " << (G_refused.m() == 0) << std::endl;
    }
}
