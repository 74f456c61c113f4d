// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/app/contact_mechanics_scene.h>
#include <porofrac/app/contact_report.h>
#include <porofrac/mechanics/contact_output.h>


namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /// fractures.csv and, with field output, the fracture VTU and the displacement VTU.
      template <int dim>
      void
      write_outputs(const mechanics::ContactProblem<dim> &problem,
                    const ContactSolution<dim>           &solution,
                    io::RunContext                       &context)
      {
        TimerOutput::Scope t(context.timer, "Output: mechanics");
        write_fracture_outputs(solution, context);
        if (context.output_format == "none")
          return;
        mechanics::write_displacement(problem, context.path("displacement"), context.output_format);
      }
    } // namespace



    template <int dim>
    void
    run_contact_mechanics_scene(const PhysicsParameters      &parameters,
                                const geometry::CutMesh<dim> &mesh,
                                io::RunContext               &context)
    {
      context.progress << "*** Contact mechanics" << std::endl;
      mechanics::ContactProblem<dim> problem(mesh,
                                             parameters.mechanics,
                                             context.progress,
                                             context.timer);
      problem.setup();
      solve_contact_problem(problem, parameters.mechanics, context);
      const auto                 faces = mechanics::contact_face_values(problem);
      const ContactSolution<dim> solution{parameters.mechanics,
                                          problem.statistics(),
                                          problem.linear_solver_name(),
                                          parameters.mechanics.linear_solver,
                                          mesh,
                                          faces};
      report_contact_solution(solution, context);
      context.summary["mechanics"] = summarize_contact_solution(solution);
      write_outputs(problem, solution, context);
      SceneView<dim> scene{mesh, parameters, &problem};
      run_postprocessors(scene, context);
    }

    template void
    run_contact_mechanics_scene(const PhysicsParameters &,
                                const geometry::CutMesh<2> &,
                                io::RunContext &);
    template void
    run_contact_mechanics_scene(const PhysicsParameters &,
                                const geometry::CutMesh<3> &,
                                io::RunContext &);
  } // namespace app
} // namespace porofrac
