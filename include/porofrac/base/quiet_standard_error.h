// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_QUIET_STANDARD_ERROR_H
#define POROFRAC_BASE_QUIET_STANDARD_ERROR_H

#include <iostream>
#include <sstream>

namespace porofrac
{
  /**
   * Holds back what is written to std::cerr while it lives, for libraries that print their own
   * diagnostics there before reporting a failure that our error message states better (deal.II
   * for muparser, Amesos for MUMPS). The stream is restored on exceptions too.
   */
  class QuietStandardError
  {
  public:
    QuietStandardError()
        : saved(std::cerr.rdbuf(sink.rdbuf()))
    {
    }

    ~QuietStandardError()
    {
      std::cerr.rdbuf(saved);
    }

    QuietStandardError(const QuietStandardError &) = delete;
    QuietStandardError &
    operator=(const QuietStandardError &) = delete;

  private:
    std::ostringstream sink;
    std::streambuf    *saved;
  };
} // namespace porofrac

#endif
