// SPDX-License-Identifier: LGPL-2.1-or-later
// AdaptiveTimeStepper: growth dt_{k+1/2} = min(rho dt_{k-1/2}, dt_max), steps that land exactly
// on the output times and on the final time, no sliver step when the final time is a sum of
// equal steps up to round-off, halving on failure with the cut limit, and growth from the cut
// step. Printed: the accepted steps (time, dt, whether they end on an output time).
#include <porofrac/base/time_stepper.h>

#include <iomanip>
#include <iostream>

using porofrac::AdaptiveTimeStepper;

namespace
{
  void
  run(const char *title, AdaptiveTimeStepper s, const unsigned int fail_at = 0)
  {
    std::cout << title << std::endl << std::setprecision(12);
    while (!s.finished())
      {
        if (s.step_number() + 1 == fail_at && s.cuts() < 2)
          {
            const bool ok = s.cut();
            std::cout << "  cut -> dt = " << s.step_size() << (ok ? "" : " (limit)") << std::endl;
            continue;
          }
        s.accept();
        std::cout << "  step " << s.step_number() << ": t = " << s.time() << ", cuts "
                  << s.last_step_cuts() << (s.at_output_time() ? ", on a target" : "") << std::endl;
      }
  }
} // namespace

int
main()
{
  run("growth 2 from 1, dt_max 5, final time 20:", AdaptiveTimeStepper(20, 1, 5, 2, 3));
  run("same, output times 2.5 and 11:", AdaptiveTimeStepper(20, 1, 5, 2, 3, {11, 2.5}));
  run("ten steps of 0.1 to 1 (round-off in the sum):", AdaptiveTimeStepper(1, 0.1, 1, 1, 3));
  run("steps of 0.25 to 1 + 1e-9 (no sliver step of 1e-9):",
      AdaptiveTimeStepper(1 + 1e-9, 0.25, 1, 1, 3));
  run("growth 2 from 1, the second step cut twice:", AdaptiveTimeStepper(10, 1, 5, 2, 3), 2);

  AdaptiveTimeStepper limit(1, 1, 1, 1, 2);
  std::cout << "cut limit 2: " << limit.cut() << limit.cut() << limit.cut() << ", dt "
            << limit.step_size() << std::endl;
}
