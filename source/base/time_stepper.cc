// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/time_stepper.h>

#include <algorithm>

namespace porofrac
{
  namespace
  {
    /// Relative tolerance of "the final time is reached" (round-off of the summed steps).
    constexpr double time_tolerance = 1e-12;
    /// A step that ends closer to a target than this fraction of its length goes to it.
    constexpr double sliver = 1e-6;
  } // namespace



  AdaptiveTimeStepper::AdaptiveTimeStepper(const double              final_time,
                                           const double              initial_step,
                                           const double              maximum_step,
                                           const double              growth,
                                           const unsigned int        maximum_cuts,
                                           const std::vector<double> times)
      : final_time(final_time)
      , maximum_step(maximum_step)
      , growth(growth)
      , maximum_cuts(maximum_cuts)
      , regular(std::min(initial_step, maximum_step))
  {
    for (const double o : times)
      if (o > 0 && o < final_time * (1 - time_tolerance))
        output_times.push_back(o);
    std::sort(output_times.begin(), output_times.end());
    propose();
  }



  bool
  AdaptiveTimeStepper::finished() const
  {
    return t >= final_time * (1 - time_tolerance);
  }



  void
  AdaptiveTimeStepper::propose()
  {
    n_cuts = 0;
    while (next_output < output_times.size() &&
           output_times[next_output] <= t * (1 + time_tolerance))
      ++next_output;
    attempt       = regular;
    attempt_lands = false;
    if (t + attempt >= final_time * (1 - time_tolerance))
      {
        attempt       = final_time - t;
        attempt_lands = true;
        return;
      }
    if (next_output < output_times.size() &&
        t + attempt * (1 + sliver) >= output_times[next_output])
      {
        attempt       = output_times[next_output] - t;
        attempt_lands = true;
        return;
      }
    if (t + attempt * (1 + sliver) >= final_time)
      {
        attempt       = final_time - t;
        attempt_lands = true;
      }
  }



  bool
  AdaptiveTimeStepper::cut()
  {
    if (n_cuts >= maximum_cuts)
      return false;
    ++n_cuts;
    attempt /= 2;
    attempt_lands = false;
    return true;
  }



  void
  AdaptiveTimeStepper::accept()
  {
    ++n_steps;
    landed_on_output = attempt_lands;
    // Summed, not set to the target, so that a run without output times reproduces the plain
    // sum of its steps; targets are recognized within a relative round-off tolerance.
    t += attempt;
    last_step = attempt;
    last_cuts = n_cuts;
    // dt_{k+1/2} = min(rho dt_{k-1/2}, dt_max) from the step taken; a step shortened only to
    // land on a target does not slow the growth down.
    regular = std::min(growth * (attempt_lands && n_cuts == 0 ? regular : attempt), maximum_step);
    propose();
  }
} // namespace porofrac
