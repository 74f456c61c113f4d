// SPDX-License-Identifier: LGPL-2.1-or-later
// The five-point sparsity pattern of an n x n grid (unknown i n + j at point (i, j)), the matrix
// structure of the linear-algebra tests.
#ifndef POROFRAC_TESTS_GRID_PATTERN_H
#define POROFRAC_TESTS_GRID_PATTERN_H

#include <deal.II/lac/dynamic_sparsity_pattern.h>

inline dealii::DynamicSparsityPattern
five_point_pattern(const unsigned int n)
{
  dealii::DynamicSparsityPattern dsp(n * n, n * n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      {
        const unsigned int k = i * n + j;
        dsp.add(k, k);
        if (i > 0)
          dsp.add(k, k - n);
        if (i + 1 < n)
          dsp.add(k, k + n);
        if (j > 0)
          dsp.add(k, k - 1);
        if (j + 1 < n)
          dsp.add(k, k + 1);
      }
  return dsp;
}

#endif
