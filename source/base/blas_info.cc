// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/blas_info.h>

#include <cstdlib>
#include <new>

#include <dlfcn.h>

namespace porofrac
{
  namespace
  {
    /// OpenBLAS's work buffer on x86-64 (128 MB and a page), with room to spare.
    constexpr std::size_t buffer_bytes = std::size_t(160) << 20;
  } // namespace


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



  void
  reserve_blas_workspace()
  {
    if (!dlsym(RTLD_DEFAULT, "openblas_get_config"))
      return;
    // The triangular solve takes a buffer from OpenBLAS's pool whatever its size.
    using Trsv      = void (*)(const char *,
                          const char *,
                          const char *,
                          const int *,
                          const double *,
                          const int *,
                          double *,
                          const int *);
    const auto trsv = reinterpret_cast<Trsv>(dlsym(RTLD_DEFAULT, "dtrsv_"));
    if (!trsv)
      return;
    // Where even the buffer would not fit, OpenBLAS would retry without end: fail first.
    void *probe = std::malloc(buffer_bytes);
    if (!probe)
      throw std::bad_alloc();
    std::free(probe);
    const int n = 1;
    double    a = 1, x = 1;
    trsv("U", "N", "N", &n, &a, &n, &x, &n);
  }
} // namespace porofrac
