// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_CONTACT_REPORT_H
#define POROFRAC_APP_CONTACT_REPORT_H

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

    /// summary.json "mechanics": the solve's settings, iterations, states and timings.
    template <int dim>
    io::Json
    summarize_contact_solution(const ContactSolution<dim> &solution);

    /// fractures.csv and, with field output, the fracture VTU.
    template <int dim>
    void
    write_fracture_outputs(const ContactSolution<dim> &solution, io::RunContext &context);
  } // namespace app
} // namespace porofrac

#endif
