// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <porofrac/app/contact_mechanics_scene.h>
#include <porofrac/app/contact_report.h>
#include <porofrac/app/linear_solve_report.h>
#include <porofrac/base/mpi_tools.h>
#include <porofrac/mechanics/distributed_contact_problem.h>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /// The deck's postprocessors, on rank 0, on a serial ContactProblem that holds the
      /// distributed solution (gathered there); its matrices are assembled only for the
      /// postprocessors that need them. Collective.
      template <int dim>
      void
      run_postprocessors_on_rank_0(const PhysicsParameters                         &parameters,
                                   const geometry::DistributedCutMesh<dim>         &mesh,
                                   const mechanics::DistributedContactProblem<dim> &problem,
                                   io::RunContext                                  &context)
      {
        if (!any_postprocessor<dim>(parameters))
          return;
        std::unique_ptr<mechanics::ContactProblem<dim>> serial;
        collectively(context.communicator, [&]() {
          if (mesh.this_rank() != 0)
            return;
          serial = std::make_unique<mechanics::ContactProblem<dim>>(mesh.serial,
                                                                    parameters.mechanics,
                                                                    context.progress,
                                                                    context.timer);
          serial->setup(postprocessors_need_system_matrices<dim>(parameters) ?
                          mechanics::SystemAssembly::matrices :
                          mechanics::SystemAssembly::state);
        });
        const Vector<double> u =
          problem.gather_displacement(serial ? &serial->get_dof_handler() : nullptr);
        const Vector<double> lambda = problem.gather_multipliers();
        collectively(context.communicator, [&]() {
          if (mesh.this_rank() != 0)
            return;
          serial->set_state(u, lambda);
          SceneView<dim> scene{mesh.serial, parameters, serial.get()};
          run_postprocessors(scene, context);
        });
      }
    } // namespace



    template <int dim>
    void
    run_contact_mechanics_scene(const PhysicsParameters                 &parameters,
                                const geometry::DistributedCutMesh<dim> &mesh,
                                io::RunContext                          &context)
    {
      const unsigned int n_processes = Utilities::MPI::n_mpi_processes(context.communicator);
      context.progress << "*** Contact mechanics, distributed over " << n_processes
                       << " MPI process" << (n_processes > 1 ? "es" : "") << std::endl;
      mechanics::DistributedContactProblem<dim> problem(mesh,
                                                        parameters.mechanics,
                                                        context.progress,
                                                        context.timer);
      problem.setup();
      solve_contact_problem(problem, parameters.mechanics, context);
      const auto faces = problem.gather_face_values();
      {
        TimerOutput::Scope         t(context.timer, "Output: mechanics");
        const ContactSolution<dim> solution{parameters.mechanics,
                                            problem.statistics(),
                                            problem.linear_solver_name(),
                                            parameters.mechanics.distributed_linear_solver,
                                            mesh.serial,
                                            faces};
        collectively(context.communicator, [&]() {
          if (mesh.this_rank() == 0)
            {
              report_contact_solution(solution, context);
              context.summary["mechanics"] = summarize_contact_solution(solution);
              write_fracture_outputs(solution, context);
            }
          if (context.output_format != "none")
            mechanics::write_distributed_displacement(problem,
                                                      context.output_directory,
                                                      "displacement",
                                                      context.output_format);
        });
      }
      if (parameters.mechanics.reports.linear_solve_time)
        report_linear_elasticity_solve(problem, context);
      run_postprocessors_on_rank_0(without_serial_linear_solve(parameters), mesh, problem, context);
    }

    template void
    run_contact_mechanics_scene(const PhysicsParameters &,
                                const geometry::DistributedCutMesh<2> &,
                                io::RunContext &);
    template void
    run_contact_mechanics_scene(const PhysicsParameters &,
                                const geometry::DistributedCutMesh<3> &,
                                io::RunContext &);
  } // namespace app
} // namespace porofrac
