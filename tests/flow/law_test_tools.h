// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks shared by the unit tests of the flow laws: each prints "ok: what" or the failing
// values, and counts the failures.
#ifndef POROFRAC_TESTS_FLOW_LAW_TOOLS_H
#define POROFRAC_TESTS_FLOW_LAW_TOOLS_H

#include <porofrac/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>

namespace law_test
{
  inline unsigned int failures = 0;

  /// |value - expected| / max(1, |expected|) <= tol.
  inline void
  check(const std::string &what, const double value, const double expected, const double tol)
  {
    const double err = std::abs(value - expected) / std::max(1., std::abs(expected));
    if (err <= tol)
      std::cout << "ok: " << what << std::endl;
    else
      {
        ++failures;
        std::cout << "FAILED: " << what << " value " << value << " expected " << expected
                  << std::endl;
      }
  }

  /// Centred finite difference of @p f at @p x with step @p h.
  inline double
  fd(const std::function<double(double)> &f, const double x, const double h)
  {
    return (f(x + h) - f(x - h)) / (2 * h);
  }

  /// Prints the InputError that @p f must throw, or counts a failure.
  template <typename F>
  void
  expect_error(const std::string &what, F f)
  {
    try
      {
        f();
        ++failures;
        std::cout << "FAILED: no error for " << what << std::endl;
      }
    catch (const porofrac::InputError &e)
      {
        std::cout << "error (" << what << "): " << e.what() << std::endl;
      }
  }
} // namespace law_test

#endif
