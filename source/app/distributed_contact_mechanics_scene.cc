// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <porofrac/app/contact_mechanics_scene.h>
#include <porofrac/app/contact_report.h>
#include <porofrac/base/mpi_tools.h>
#include <porofrac/mechanics/distributed_contact_problem.h>
#include <porofrac/mechanics/linear_elasticity_solve.h>

#include <iomanip>
#include <sstream>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /**
       * Mechanics/Report linear solve time of a distributed run: one linear elasticity solve
       * (every fracture open) by the run's distributed solver on its mesh, against the contact
       * solve's time (summary.json mechanics/linear_solve_time_s, contact_linear_ratio), and how
       * far its displacement lies from the contact solution (zero when every face is open and
       * lambda = 0). Collective.
       */
      template <int dim>
      void
      report_linear_solve(const mechanics::DistributedContactProblem<dim> &problem,
                          const PhysicsParameters                         &parameters,
                          io::RunContext                                  &context)
      {
        const auto result =
          mechanics::solve_linear_elasticity(problem.get_system(), parameters.mechanics);
        auto difference = result.displacement;
        difference -= problem.displacement();
        const double relative = difference.l2_norm() / problem.displacement().l2_norm();
        const double time     = result.set_up_time + result.solve_time;
        if (Utilities::MPI::this_mpi_process(context.communicator) != 0)
          return;
        context.report << "Mechanics: one linear elasticity solve (fractures open, "
                       << result.solver << "): ";
        if (result.solver == "AMG-CG")
          context.report << result.iterations << " iterations, ";
        if (!result.converged)
          context.report << "failed" << std::endl;
        else
          {
            std::ostringstream text;
            text << std::scientific << std::setprecision(1) << relative;
            context.report << "displacement differs from the contact solution by " << text.str()
                           << " (relative l2)" << std::endl;
          }
        context.progress << "    one linear elasticity solve: " << result.set_up_time
                         << " s set-up, " << result.solve_time << " s solve" << std::endl;
        io::Json &m                           = context.summary["mechanics"];
        m["linear_solve_solver"]              = result.solver;
        m["linear_solve_converged"]           = result.converged;
        m["linear_solve_iterations"]          = result.iterations;
        m["linear_solve_set_up_time_s"]       = result.set_up_time;
        m["linear_solve_time_s"]              = time;
        m["linear_solve_relative_difference"] = relative;
        m["contact_linear_ratio"] = context.summary["contact_solve_time_s"].as_number() / time;
      }



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
      // The distributed linear solve replaces the serial postprocessor's UMFPACK one.
      PhysicsParameters on_rank_0 = parameters;
      if (parameters.mechanics.reports.linear_solve_time)
        {
          report_linear_solve(problem, parameters, context);
          on_rank_0.mechanics.reports.linear_solve_time = false;
        }
      run_postprocessors_on_rank_0(on_rank_0, mesh, problem, context);
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
