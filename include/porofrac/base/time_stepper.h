// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_TIME_STEPPER_H
#define POROFRAC_BASE_TIME_STEPPER_H

#include <vector>

namespace porofrac
{
  /**
   * The adaptive time steps of the flow and coupled scenes: dt_{k+1/2} = min(rho dt_{k-1/2},
   * dt_max) after an accepted step (a step shortened only to land on a target does not count
   * as the previous step), halved after a failed attempt (at most max_cuts times per
   * step), and shortened so that steps land exactly on the output times and on the final time.
   * A step that would stop short of such a target by less than 1e-6 of its length is stretched
   * to it, so that no sliver step is left (a final time that is a sum of equal steps).
   *
   * Use: while (!finished()) { attempt step_size(); on failure cut() (false: give up), on
   * success accept() }.
   */
  class AdaptiveTimeStepper
  {
  public:
    AdaptiveTimeStepper(const double              final_time,
                        const double              initial_step,
                        const double              maximum_step,
                        const double              growth,
                        const unsigned int        maximum_cuts,
                        const std::vector<double> output_times = {});

    bool
    finished() const;
    /// Time of the last accepted state, and number of accepted steps.
    double
    time() const
    {
      return t;
    }
    unsigned int
    step_number() const
    {
      return n_steps;
    }
    /// Length of the current attempt.
    double
    step_size() const
    {
      return attempt;
    }
    /// Length of the last accepted step.
    double
    last_step_size() const
    {
      return last_step;
    }
    /// Halves the current attempt; false when the step has been cut maximum_cuts times.
    bool
    cut();
    /// Cuts of the current attempt.
    unsigned int
    cuts() const
    {
      return n_cuts;
    }
    /// Cuts of the last accepted step.
    unsigned int
    last_step_cuts() const
    {
      return last_cuts;
    }
    /// Accepts the current attempt: advances the time and proposes the next step.
    void
    accept();
    /// Whether the last accepted step ended on an output time (or the final time).
    bool
    at_output_time() const
    {
      return landed_on_output;
    }

    /// Everything that changes while stepping, for checkpoints: restore(state()) continues
    /// exactly where the stepper was.
    struct State
    {
      double       t, regular, attempt, last_step;
      unsigned int next_output, n_steps, n_cuts, last_cuts;
      bool         landed_on_output, attempt_lands;
    };
    State
    state() const
    {
      return {t,
              regular,
              attempt,
              last_step,
              next_output,
              n_steps,
              n_cuts,
              last_cuts,
              landed_on_output,
              attempt_lands};
    }
    void
    restore(const State &s)
    {
      t                = s.t;
      regular          = s.regular;
      attempt          = s.attempt;
      last_step        = s.last_step;
      next_output      = s.next_output;
      n_steps          = s.n_steps;
      n_cuts           = s.n_cuts;
      last_cuts        = s.last_cuts;
      landed_on_output = s.landed_on_output;
      attempt_lands    = s.attempt_lands;
    }

  private:
    /// Proposes the attempt from the regular step: shortened to the next target.
    void
    propose();

    const double        final_time, maximum_step, growth;
    const unsigned int  maximum_cuts;
    std::vector<double> output_times; ///< sorted, those in (0, final_time)
    unsigned int        next_output = 0;
    double              t = 0, regular = 0, attempt = 0, last_step = 0;
    unsigned int        n_steps = 0, n_cuts = 0, last_cuts = 0;
    bool                landed_on_output = false;
    bool                attempt_lands    = false;
  };
} // namespace porofrac

#endif
