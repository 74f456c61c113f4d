// SPDX-License-Identifier: LGPL-2.1-or-later
// process_memory_headroom_mb() and require_memory() under an address-space limit (ulimit -v):
// without a limit there is no headroom to respect (0); with the soft RLIMIT_AS set 200 MB above
// the address space the process maps, the headroom is about 200 MB, a need of 50 MB passes and one
// of 400 MB is refused with a message that names the address-space limit. The limit is lifted
// again at the end.
#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>

#include <fstream>
#include <iostream>
#include <string>

#include "../address_space.h"
#include <sys/resource.h>

namespace
{
  void
  require(const double megabytes)
  {
    try
      {
        porofrac::require_memory(megabytes, "a test allocation", "", "");
        std::cout << "  " << megabytes << " MB: passes" << std::endl;
      }
    catch (const porofrac::InsufficientMemory &e)
      {
        const std::string message = e.what();
        std::cout << "  " << megabytes << " MB: refused, naming the address-space limit: "
                  << (message.find("under its address-space limit (ulimit -v or -d)") !=
                          std::string::npos ?
                        "yes" :
                        "no")
                  << std::endl;
      }
  }
} // namespace

int
main()
{
  rlimit original{};
  getrlimit(RLIMIT_AS, &original);
  if (original.rlim_cur != RLIM_INFINITY)
    {
      // The test needs to set the limit itself.
      std::cout << "the test runs under an address-space limit already" << std::endl;
      return 1;
    }
  std::cout << "without a limit: headroom " << porofrac::process_memory_headroom_mb() << " MB"
            << std::endl;

  rlimit limited   = original;
  limited.rlim_cur = static_cast<rlim_t>((porofrac_tests::mapped_kb() + 200 * 1024.) * 1024.);
  setrlimit(RLIMIT_AS, &limited);
  const double headroom = porofrac::process_memory_headroom_mb();
  std::cout << "200 MB above the mapped address space: headroom between 150 and 200 MB: "
            << (headroom > 150 && headroom <= 200 ? "yes" : "no") << std::endl;
  require(50);
  require(400);
  setrlimit(RLIMIT_AS, &original);
  std::cout << "limit lifted: headroom " << porofrac::process_memory_headroom_mb() << " MB"
            << std::endl;
}
