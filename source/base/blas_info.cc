// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/blas_info.h>

#include <dlfcn.h>

namespace porofrac
{
  std::string
  blas_description()
  {
    // Looked up at run time: the BLAS is chosen when the program is loaded (Debian's
    // alternatives), not when it is built.
    using Text          = char *(*)();
    const auto corename = reinterpret_cast<Text>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
    const auto config   = reinterpret_cast<Text>(dlsym(RTLD_DEFAULT, "openblas_get_config"));
    if (!corename || !config)
      return "not OpenBLAS";
    // The configuration starts with "OpenBLAS <version>", then build options.
    std::string version = config();
    const auto  end     = version.find(' ', version.find(' ') + 1);
    if (end != std::string::npos)
      version.resize(end);
    return version + ", " + corename() + " kernels";
  }
} // namespace porofrac
