// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/app/contact_mechanics_scene.h>
#include <porofrac/mechanics/contact_output.h>

#include <fstream>
#include <iomanip>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /// Iterations, face states per fracture, ranges of the face values (local frame).
      template <int dim>
      void
      report_solution(const mechanics::ContactProblem<dim> &problem, io::RunContext &context)
      {
        const auto &prm  = problem.get_parameters();
        const auto &mesh = problem.get_mesh();
        context.report << "Mechanics: solver " << prm.method << ", "
                       << (prm.stick_guess ? "stick" : "open") << " guess, c = " << std::scientific
                       << std::setprecision(1) << prm.c << std::defaultfloat << ": converged in "
                       << problem.statistics().iterations << " iterations" << std::endl;
        if (problem.linear_solver_name() != prm.linear_solver)
          context.report << "Mechanics: Schur complement unavailable (the elasticity block alone "
                            "is singular); the full system was solved"
                         << std::endl;
        const auto counts = mechanics::count_states(problem);
        context.report << "Mechanics: faces open " << counts[0] << ", stick " << counts[1]
                       << ", slip " << counts[2] << std::endl;
        if (mesh.fracture_ids.size() > 1)
          for (const unsigned int id : mesh.fracture_ids)
            {
              const auto c = mechanics::count_states(problem, id);
              context.report << "Mechanics: fracture " << id << ": open " << c[0] << ", stick "
                             << c[1] << ", slip " << c[2] << std::endl;
            }
        if (mesh.fracture_faces.empty())
          return;
        double jn_min = 1e300, jn_max = -1e300, jt_max = 0, ln_min = 1e300, ln_max = -1e300,
               lt_max = 0;
        for (const auto &face : mesh.fracture_faces)
          {
            const auto v = mechanics::contact_face_values(problem, face.index);
            jn_min       = std::min(jn_min, v.jump[0]);
            jn_max       = std::max(jn_max, v.jump[0]);
            ln_min       = std::min(ln_min, v.lambda[0]);
            ln_max       = std::max(ln_max, v.lambda[0]);
            jt_max = std::max(jt_max, mechanics::LocalContactLaw<dim>::tangential(v.jump).norm());
            lt_max = std::max(lt_max, mechanics::LocalContactLaw<dim>::tangential(v.lambda).norm());
          }
        context.report << std::scientific << std::setprecision(3) << "Mechanics: jump_n in ["
                       << jn_min << ", " << jn_max << "], max |jump_t| " << jt_max << "\n"
                       << "Mechanics: lambda_n in [" << ln_min << ", " << ln_max
                       << "], max |lambda_t| " << lt_max << std::defaultfloat << std::endl;
      }

      /// summary.json "mechanics": the solve's settings, iterations, states and timings.
      template <int dim>
      io::Json
      summarize(const mechanics::ContactProblem<dim> &problem)
      {
        const auto                         &prm    = problem.get_parameters();
        const mechanics::ContactStatistics &s      = problem.statistics();
        const auto                          counts = mechanics::count_states(problem);
        io::Json                            m      = io::Json::object();
        m["solver"]                                = prm.method;
        m["initial_guess"]              = std::string(prm.stick_guess ? "stick" : "open");
        m["c"]                          = prm.c;
        m["nonlinear_iterations"]       = s.iterations;
        m["converged"]                  = s.converged;
        m["n_open"]                     = counts[0];
        m["n_stick"]                    = counts[1];
        m["n_slip"]                     = counts[2];
        m["residuals"]                  = s.residual_history;
        m["residuals_initial_relative"] = s.initial_relative_history;
        m["steps"]                      = s.step_history;
        m["line_search_backtracks"]     = s.backtracks;
        m["cycles_detected"]            = s.cycles_detected;
        m["factorizations"]             = s.factorizations;
        m["reused_factorizations"]      = s.reused_factorizations;
        io::Json timing                 = io::Json::object();
        timing["contact_rows_s"]        = s.time_contact_rows;
        timing["factorization_s"]       = s.time_factorization;
        timing["triangular_solves_s"]   = s.time_solves;
        timing["residuals_s"]           = s.time_residuals;
        timing["cholesky_s"]            = s.time_cholesky;
        timing["form_W_s"]              = s.time_form_W;
        m["timing"]                     = timing;
        m["linear_solver"]              = problem.linear_solver_name() == prm.linear_solver ?
                                            prm.linear_solver :
                                            std::string("full system (schur complement unavailable)");
        return m;
      }

      /// fractures.csv, and with field output the fracture VTU and the displacement VTU.
      template <int dim>
      void
      write_outputs(const mechanics::ContactProblem<dim> &problem, io::RunContext &context)
      {
        TimerOutput::Scope t(context.timer, "Output: mechanics");
        std::ofstream      csv(context.path("fractures.csv"));
        mechanics::write_fracture_table_header(csv, dim, false);
        mechanics::write_fracture_table_rows(csv, problem);
        if (context.output_format == "none")
          return;
        if (!problem.get_mesh().fracture_faces.empty())
          {
            geometry::FractureFields fields;
            mechanics::append_contact_fields(problem, fields);
            geometry::write_fracture_cells(problem.get_mesh(),
                                           context.path("fractures." + context.output_format),
                                           context.output_format,
                                           fields);
          }
        mechanics::write_displacement(problem,
                                      context.path("displacement." + context.output_format),
                                      context.output_format);
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
      context.report << "Mechanics: " << problem.n_dofs() << " dofs ("
                     << problem.n_displacement_dofs() << " displacement, "
                     << problem.n_dofs() - problem.n_displacement_dofs() << " multiplier)"
                     << std::endl;
      context.summary["n_dofs_mechanics"] = problem.n_dofs();
      {
        Timer clock;
        problem.solve();
        context.summary["contact_solve_time_s"] = clock.wall_time();
      }
      report_solution(problem, context);
      context.summary["mechanics"] = summarize(problem);
      write_outputs(problem, context);
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
