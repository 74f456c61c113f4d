// SPDX-License-Identifier: LGPL-2.1-or-later
// The address space a test process maps, for the tests that set an address-space limit
// (RLIMIT_AS) a known distance above it.
#ifndef POROFRAC_TESTS_ADDRESS_SPACE_H
#define POROFRAC_TESTS_ADDRESS_SPACE_H

#include <fstream>
#include <string>

namespace porofrac_tests
{
  /// The address space this process maps, in kB (VmSize of /proc/self/status).
  inline double
  mapped_kb()
  {
    std::ifstream file("/proc/self/status");
    std::string   line;
    while (std::getline(file, line))
      if (line.rfind("VmSize:", 0) == 0)
        return std::stod(line.substr(7));
    return 0;
  }
} // namespace porofrac_tests

#endif
