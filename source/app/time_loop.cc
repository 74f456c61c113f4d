// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/time_loop.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/interrupt.h>
#include <porofrac/io/text.h>

#include <new>

namespace porofrac
{
  namespace app
  {
    namespace
    {
      /// One step: attempts, halving the step after each failure; false after the last cut.
      bool
      take_step(AdaptiveTimeStepper                               &stepper,
                const std::string                                 &label,
                const std::function<StepOutcome(const double dt)> &attempt,
                std::string                                       &failure,
                dealii::ConditionalOStream                        &progress)
      {
        while (true)
          {
            const StepOutcome outcome = attempt(stepper.step_size());
            if (outcome.converged)
              return true;
            failure             = outcome.failure;
            const double failed = stepper.step_size();
            if (!stepper.cut())
              return false;
            progress << "    " << label << ": step of " << failed
                     << " s from t = " << stepper.time() << " s failed (" << failure
                     << "), halving it to " << stepper.step_size() << " s" << std::endl;
          }
      }
    } // namespace



    void
    run_time_loop(AdaptiveTimeStepper                                 &stepper,
                  const std::string                                   &label,
                  const std::function<void()>                         &start,
                  const std::function<StepOutcome(const double dt)>   &attempt,
                  const std::function<void()>                         &accept,
                  const std::function<void(const bool restore_first)> &write_accepted_state,
                  dealii::ConditionalOStream                          &progress,
                  const MPI_Comm                                       communicator,
                  const std::function<void()>                         &on_stop)
    {
      const auto stop = [&](const bool restore_first) {
        write_accepted_state(restore_first);
        if (on_stop)
          on_stop();
      };
      const auto at = [&]() { return " at t = " + io::to_text(stepper.time()) + " s"; };
      // An output file that cannot be written: the totals of the accepted steps still go to
      // summary.json, also at t = 0 (none); a restart that stopped after restoring the stepper
      // has no totals to report.
      const auto reporting_totals = [&](const std::function<void()> &write,
                                        const bool                   may_restore) {
        try
          {
            write();
          }
        catch (const InputError &)
          {
            if (on_stop && !(may_restore && stepper.step_number() > 0))
              on_stop();
            throw;
          }
      };
      reporting_totals(start, true);
      while (!stepper.finished())
        {
          std::string failure;
          bool        converged = false;
          try
            {
              converged = take_step(stepper, label, attempt, failure, progress);
            }
          catch (const InsufficientMemory &e)
            {
              stop(true);
              throw InsufficientMemory(label + ": " + e.what() + "; stopped in the step from t = " +
                                       io::to_text(stepper.time()) +
                                       " s. The last accepted state is written.");
            }
          catch (const std::bad_alloc &)
            {
              // On one process the step's memory is freed by now, and the accepted state can
              // still be written; processes that run the loop together cannot agree on it, so
              // there the failure goes on to main(), which stops them all.
              if (dealii::Utilities::MPI::n_mpi_processes(communicator) > 1)
                throw;
              stop(true);
              throw InsufficientMemory(
                label + ": " + out_of_memory_reason + "; stopped in the step from t = " +
                io::to_text(stepper.time()) + " s. The last accepted state is written.");
            }
          catch (const Interrupted &)
            {
              stop(true);
              throw Interrupted(
                label + ": " + std::string(interrupt_description()) +
                " received during the step from t = " + io::to_text(stepper.time()) +
                " s; the last accepted state is written.");
            }
          if (!converged)
            {
              stop(true);
              throw SolverFailure(label + ": no convergence" + at() + " after " +
                                  std::to_string(stepper.cuts()) +
                                  " time-step cuts; last failure: " + failure +
                                  ". The last accepted state is written.");
            }
          stepper.accept();
          reporting_totals(accept, false);
          if (dealii::Utilities::MPI::max(interrupt_signal(), communicator) != 0 &&
              !stepper.finished())
            {
              stop(false);
              throw Interrupted(label + ": " + std::string(interrupt_description()) +
                                " received; stopped after step " +
                                std::to_string(stepper.step_number()) + at() +
                                ", which is written.");
            }
        }
    }
  } // namespace app
} // namespace porofrac
