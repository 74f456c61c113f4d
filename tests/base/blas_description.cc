// SPDX-License-Identifier: LGPL-2.1-or-later
// blas_description(), the "blas" entry of summary.json: the test suite runs with OpenBLAS
// (contrib/install-dependencies) and OPENBLAS_CORETYPE=Prescott, so the description must name
// OpenBLAS with its version and the kernels that variable asks for.
#include <porofrac/base/blas_info.h>

#include <cstdlib>
#include <iostream>
#include <regex>

int
main()
{
  const std::string text     = porofrac::blas_description();
  const char       *coretype = std::getenv("OPENBLAS_CORETYPE");
  std::cout << "OPENBLAS_CORETYPE: " << (coretype ? coretype : "(not set)") << std::endl;
  std::cout << "OpenBLAS with its version: "
            << std::regex_search(text, std::regex("^OpenBLAS [0-9]+\\.[0-9]+\\.[0-9]+, "))
            << std::endl;
  const std::string suffix = std::string(", ") + (coretype ? coretype : "?") + " kernels";
  std::cout << "the kernels asked for: "
            << (text.size() >= suffix.size() &&
                text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0)
            << std::endl;
}
