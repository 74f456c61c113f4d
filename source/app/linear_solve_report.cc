// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>

#include <porofrac/app/linear_solve_report.h>
#include <porofrac/mechanics/linear_elasticity_solve.h>

#include <iomanip>
#include <sstream>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    template <int dim>
    void
    report_linear_elasticity_solve(const mechanics::DistributedContactProblem<dim> &problem,
                                   io::RunContext                                  &context)
    {
      const auto result =
        mechanics::solve_linear_elasticity(problem.get_system(), problem.get_parameters());
      auto difference = result.displacement;
      difference -= problem.displacement();
      // Absolute where the contact displacement is zero (no load).
      const double norm     = problem.displacement().l2_norm();
      const double relative = norm > 0 ? difference.l2_norm() / norm : difference.l2_norm();
      const double time     = result.set_up_time + result.solve_time;
      if (Utilities::MPI::this_mpi_process(context.communicator) != 0)
        return;
      context.report << "Mechanics: one linear elasticity solve (fractures open, " << result.solver
                     << "): ";
      if (result.solver == "AMG-CG")
        context.report << result.iterations << " iterations, ";
      if (!result.converged)
        context.report << "failed (" << result.failure << ")" << std::endl;
      else
        {
          std::ostringstream text;
          text << std::scientific << std::setprecision(1) << relative;
          context.report << "displacement differs from the contact solution by " << text.str()
                         << " (relative l2)" << std::endl;
        }
      context.progress << "    one linear elasticity solve: " << result.set_up_time << " s set-up, "
                       << result.solve_time << " s solve" << std::endl;
      io::Json &m                 = context.summary["mechanics"];
      m["linear_solve_solver"]    = result.solver;
      m["linear_solve_converged"] = result.converged;
      if (!result.converged)
        m["linear_solve_failure"] = result.failure;
      m["linear_solve_iterations"]    = result.iterations;
      m["linear_solve_set_up_time_s"] = result.set_up_time;
      m["linear_solve_time_s"]        = time;
      if (!result.converged)
        return;
      m["linear_solve_relative_difference"] = relative;
      if (context.summary.has("contact_solve_time_s"))
        m["contact_linear_ratio"] = context.summary["contact_solve_time_s"].as_number() / time;
    }



    PhysicsParameters
    without_serial_linear_solve(const PhysicsParameters &parameters)
    {
      PhysicsParameters p                   = parameters;
      p.mechanics.reports.linear_solve_time = false;
      return p;
    }

    template void
    report_linear_elasticity_solve(const mechanics::DistributedContactProblem<2> &,
                                   io::RunContext &);
    template void
    report_linear_elasticity_solve(const mechanics::DistributedContactProblem<3> &,
                                   io::RunContext &);
  } // namespace app
} // namespace porofrac
