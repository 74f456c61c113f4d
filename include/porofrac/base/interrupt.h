// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_INTERRUPT_H
#define POROFRAC_BASE_INTERRUPT_H

namespace porofrac
{
  /**
   * Graceful stop on SIGINT and SIGTERM: the first signal only raises a flag, which the solvers
   * poll at safe points (between time steps, between nonlinear iterations) and answer by
   * throwing Interrupted; a second signal ends the process at once (the default action).
   * Installing the handlers again forgets a signal received before.
   */
  void
  install_interrupt_handlers();

  /// The signal received (SIGINT or SIGTERM), or 0.
  int
  interrupt_signal();

  /// "SIGINT" or "SIGTERM" (or "no signal").
  const char *
  interrupt_description();

  /// Throws Interrupted naming the signal if one was received; @p where says what stops.
  void
  throw_if_interrupted(const char *where);
} // namespace porofrac

#endif
