// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/time_loop.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/io/text.h>

namespace porofrac
{
  namespace app
  {
    void
    run_time_loop(AdaptiveTimeStepper                               &stepper,
                  const std::string                                 &label,
                  const std::function<StepOutcome(const double dt)> &attempt,
                  const std::function<void()>                       &accept,
                  const std::function<void()>                       &write_last_good,
                  dealii::ConditionalOStream                        &progress)
    {
      while (!stepper.finished())
        {
          StepOutcome outcome = attempt(stepper.step_size());
          while (!outcome.converged)
            {
              const double failed = stepper.step_size();
              if (!stepper.cut())
                {
                  write_last_good();
                  throw SolverFailure(label +
                                      ": no convergence at t = " + io::to_text(stepper.time()) +
                                      " s after " + std::to_string(stepper.cuts()) +
                                      " time-step cuts; last failure: " + outcome.failure +
                                      ". The last accepted state is written.");
                }
              progress << "    " << label << ": step of " << failed
                       << " s from t = " << stepper.time() << " s failed (" << outcome.failure
                       << "), halving it to " << stepper.step_size() << " s" << std::endl;
              outcome = attempt(stepper.step_size());
            }
          stepper.accept();
          accept();
        }
    }
  } // namespace app
} // namespace porofrac
