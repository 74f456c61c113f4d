// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_CONTACT_REPORT_H
#define POROFRAC_APP_CONTACT_REPORT_H

#include <deal.II/base/timer.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/json.h>
#include <porofrac/io/run_context.h>
#include <porofrac/mechanics/contact_output.h>
#include <porofrac/mechanics/contact_solver.h>
#include <porofrac/mechanics/parameters.h>

#include <string>
#include <vector>

namespace porofrac
{
  namespace app
  {
    /**
     * The results of a static contact solve as the contact-mechanics scenes report them, serial
     * or distributed: the settings and statistics of the solve, the linear solver that ran, and
     * the contact values of every fracture face (gathered on the process that reports).
     */
    template <int dim>
    struct ContactSolution
    {
      const mechanics::ContactParameters &parameters;
      const mechanics::ContactStatistics &statistics;
      /// The linear solver that ran and the one the deck asked for (they differ when the
      /// Schur complement fell back to the full system).
      std::string                                           linear_solver, requested_solver;
      const geometry::CutMesh<dim>                         &mesh;
      const std::vector<mechanics::ContactFaceValues<dim>> &faces;
    };

    /// Iterations, face states per fracture, ranges of the face values (local frame), to the
    /// results report.
    template <int dim>
    void
    report_contact_solution(const ContactSolution<dim> &solution, io::RunContext &context);

    /// summary.json "mechanics" of a contact solve, also of one that failed: its settings,
    /// iteration counts and residual and face-state histories.
    io::Json
    summarize_contact_iterations(const mechanics::ContactParameters &parameters,
                                 const mechanics::ContactStatistics &statistics);

    /// Reports the dofs of @p problem, solves it and records the solve's wall time in
    /// summary.json; a solve that fails leaves its history there (summarize_contact_iterations)
    /// for the summary written on the way out.
    template <typename Problem>
    void
    solve_contact_problem(Problem                            &problem,
                          const mechanics::ContactParameters &parameters,
                          io::RunContext                     &context)
    {
      context.report << "Mechanics: " << problem.n_dofs() << " dofs ("
                     << problem.n_displacement_dofs() << " displacement, "
                     << problem.n_dofs() - problem.n_displacement_dofs() << " multiplier)"
                     << std::endl;
      context.summary["n_dofs_mechanics"] = problem.n_dofs();
      dealii::Timer clock;
      try
        {
          problem.solve();
        }
      catch (const SolverFailure &)
        {
          context.summary["mechanics"] =
            summarize_contact_iterations(parameters, problem.statistics());
          throw;
        }
      context.summary["contact_solve_time_s"] = clock.wall_time();
    }

    /// summary.json "mechanics": summarize_contact_iterations with the final face states and
    /// the timings.
    template <int dim>
    io::Json
    summarize_contact_solution(const ContactSolution<dim> &solution);

    /// Adds to @p summary the per-iteration history of a contact solve: the three terms of the
    /// stopping test ("residual_terms") and the face states each step was computed with
    /// ("face_states", with the number of faces that changed state).
    void
    add_iteration_history(const mechanics::ContactStatistics &statistics, io::Json &summary);

    /// fractures.csv and, with field output, the fracture VTU.
    template <int dim>
    void
    write_fracture_outputs(const ContactSolution<dim> &solution, io::RunContext &context);
  } // namespace app
} // namespace porofrac

#endif
