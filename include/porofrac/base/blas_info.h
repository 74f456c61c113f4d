// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_BLAS_INFO_H
#define POROFRAC_BASE_BLAS_INFO_H

#include <string>

namespace porofrac
{
  /**
   * The BLAS this process runs with, for summary.json: "OpenBLAS 0.3.21, Cooperlake kernels"
   * where the loaded library is OpenBLAS (its version and the kernels it chose, which
   * OPENBLAS_CORETYPE overrides), otherwise "not OpenBLAS". Dense factorizations round
   * differently with different kernels, and iteration counts near a convergence limit can move
   * with them (doc/benchmarks/penny.md §4).
   */
  std::string
  blas_description();
} // namespace porofrac

#endif
