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

  /**
   * Has OpenBLAS allocate its work buffer (128 MB of address space) now, while the process is
   * small, by one call of a routine that needs it; later calls reuse it. OpenBLAS (0.3.21)
   * retries a buffer allocation that fails without end, so a first BLAS call deep in a
   * factorization under an address-space limit (ulimit -v) would hang the run instead of
   * failing. Throws std::bad_alloc where the buffer does not fit; nothing where the BLAS is not
   * OpenBLAS.
   */
  void
  reserve_blas_workspace();
} // namespace porofrac

#endif
