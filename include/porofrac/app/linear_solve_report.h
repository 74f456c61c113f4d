// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_LINEAR_SOLVE_REPORT_H
#define POROFRAC_APP_LINEAR_SOLVE_REPORT_H

#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/io/run_context.h>
#include <porofrac/mechanics/distributed_contact_problem.h>

namespace porofrac
{
  namespace app
  {
    /**
     * Mechanics/Report linear solve time where the contact problem is distributed: one linear
     * elasticity solve (every fracture open) by the run's distributed solver on its mesh
     * (mechanics::solve_linear_elasticity), its iterations, and how far its displacement lies
     * from the contact solution (zero when every face is open and lambda = 0), to the report;
     * times to summary.json (mechanics/linear_solve_time_s), with contact_linear_ratio where
     * the run recorded one contact solve's time (contact_solve_time_s). Collective.
     */
    template <int dim>
    void
    report_linear_elasticity_solve(const mechanics::DistributedContactProblem<dim> &problem,
                                   io::RunContext                                  &context);

    /// @p parameters for the postprocessors of a run whose contact problem is distributed:
    /// without the serial linear solve timing, which report_linear_elasticity_solve() replaces.
    PhysicsParameters
    without_serial_linear_solve(const PhysicsParameters &parameters);
  } // namespace app
} // namespace porofrac

#endif
