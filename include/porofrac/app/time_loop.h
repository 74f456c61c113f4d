// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_TIME_LOOP_H
#define POROFRAC_APP_TIME_LOOP_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <porofrac/base/time_stepper.h>

#include <functional>
#include <string>

namespace porofrac
{
  namespace app
  {
    /// What one attempt at a time step did: converged, or why not.
    struct StepOutcome
    {
      bool        converged = false;
      std::string failure;
    };

    /**
     * The time loop shared by the time-dependent scenes. It first calls @p start (the state at
     * t = 0, or the one a checkpoint restores, written). Per step it calls @p attempt with the
     * stepper's step size until a step converges, halving the step after each failure; an
     * attempt starts from the accepted state and must leave it intact when it fails. After a
     * converged attempt the stepper advances and @p accept records the step.
     *
     * When a step still fails after the allowed cuts, or the run is interrupted (SIGINT,
     * SIGTERM: base/interrupt.h) during or between steps, @p write_accepted_state writes the
     * last accepted state (its argument: whether the scene must first restore it, because an
     * attempt changed it) and a SolverFailure or Interrupted naming @p label and the time is
     * thrown. The processes of @p communicator (that run the loop together) stop after the
     * same step when a signal reaches any of them. Before it is thrown, @p on_stop (if given)
     * records what the scene reports of a finished run (summary.json totals); so it does before
     * an InputError of @p accept, or of @p start at step 0 (an output file that cannot be
     * written), goes on.
     */
    void
    run_time_loop(AdaptiveTimeStepper                                 &stepper,
                  const std::string                                   &label,
                  const std::function<void()>                         &start,
                  const std::function<StepOutcome(const double dt)>   &attempt,
                  const std::function<void()>                         &accept,
                  const std::function<void(const bool restore_first)> &write_accepted_state,
                  dealii::ConditionalOStream                          &progress,
                  const MPI_Comm                                       communicator = MPI_COMM_SELF,
                  const std::function<void()>                         &on_stop      = {});
  } // namespace app
} // namespace porofrac

#endif
