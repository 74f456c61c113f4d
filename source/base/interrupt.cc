// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/base/interrupt.h>

#include <csignal>
#include <string>

namespace porofrac
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;

    extern "C" void
    on_signal(int signal)
    {
      received = signal;
      // A second signal takes the default action: the user insists.
      std::signal(signal, SIG_DFL);
    }
  } // namespace



  void
  install_interrupt_handlers()
  {
    received = 0;
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
  }



  int
  interrupt_signal()
  {
    return received;
  }



  const char *
  interrupt_description()
  {
    return received == SIGINT ? "SIGINT" : (received == SIGTERM ? "SIGTERM" : "no signal");
  }



  void
  throw_if_interrupted(const char *where)
  {
    if (received != 0)
      throw Interrupted(std::string(interrupt_description()) + " received; stopped " + where);
  }
} // namespace porofrac
