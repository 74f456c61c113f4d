// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/numerics/data_out.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/flow/model.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/flow/scene.h>
#include <porofrac/flow/tpfa_grid.h>
#include <porofrac/flow/two_phase_solver.h>
#include <porofrac/geometry/mesh_output.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace porofrac
{
  namespace flow
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      void
      write_fields(const geometry::CutMesh<dim> &mesh,
                   const TpfaGrid<dim>          &grid,
                   const TwoPhaseSolver<dim>    &solver,
                   const std::string            &basename,
                   const std::string            &format)
      {
        const unsigned n = grid.n_matrix_cells;
        Vector<double> pw(n), pnw(n), pc(n), snw(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            pw[i]  = solver.pressure(solver.state, i, 0);
            pnw[i] = solver.pressure(solver.state, i, 1);
            pc[i]  = pnw[i] - pw[i];
            snw[i] = solver.saturation(solver.state, i, matrix_rock);
          }
        geometry::write_cell_fields(mesh,
                                    basename,
                                    format,
                                    {{"p_w", pw}, {"p_nw", pnw}, {"p_c", pc}, {"s_nw", snw}});

        geometry::FractureFields fields = {
          {"p_w", {}}, {"p_nw", {}}, {"p_c", {}}, {"s_nw", {}}, {"aperture", {}}};
        for (unsigned int s = 0; s < grid.n_fracture_cells; ++s)
          {
            const unsigned int i = n + s;
            fields[0].second.push_back(solver.pressure(solver.state, i, 0));
            fields[1].second.push_back(solver.pressure(solver.state, i, 1));
            fields[2].second.push_back(solver.state[i][1] - solver.state[i][0]);
            fields[3].second.push_back(solver.saturation(solver.state, i, fracture_rock));
            fields[4].second.push_back(grid.aperture[s]);
          }
        if (grid.n_fracture_cells > 0)
          geometry::write_fracture_cells(mesh, basename + "_fractures." + format, format, fields);
      }
    } // namespace

    template <int dim>
    void
    run_scene(const ParameterHandler       &prm,
              const geometry::CutMesh<dim> &mesh,
              io::RunContext               &context)
    {
      FlowParameters parameters;
      parameters.parse_parameters(prm);
      FlowModel<dim>       model  = make_flow_model<dim>(parameters, mesh);
      TpfaGrid<dim>       &grid   = *model.grid;
      TwoPhaseSolver<dim> &solver = *model.solver;
      const TimeStepping  &ts     = model.stepping;
      const double T_final = ts.final_time, dt_0 = ts.initial_step, dt_max = ts.maximum_step,
                   rho           = ts.growth;
      const unsigned int max_cut = ts.maximum_cuts, output_every = ts.output_every;
      solver.timer = &context.timer;

      context.report << "Flow: " << grid.n_matrix_cells << " matrix cells, "
                     << grid.n_fracture_cells << " fracture cells, " << grid.n_interfaces
                     << " interface nodes, " << grid.n_intersections << " intersection nodes, "
                     << solver.n_unknowns() << " unknowns" << std::endl
                     << "Flow: " << grid.n_non_admissible
                     << " cell faces with the circumcentre on the wrong side, " << grid.n_fallback
                     << " non-Delaunay connections (unsigned distances)" << std::endl;
      context.summary["n_unknowns_flow"] = solver.n_unknowns();

      const auto mean_width = [&]() {
        double num = 0, den = 0;
        for (unsigned int s = 0; s < grid.n_fracture_cells; ++s)
          {
            num += mesh.fracture_faces[s].measure * grid.aperture[s];
            den += mesh.fracture_faces[s].measure;
          }
        return den > 0 ? num / den : 0.;
      };

      std::ofstream history(context.path("history.csv"));
      check_input(bool(history), "--output-dir", "cannot write history.csv");
      history << "time,dt,mean_fracture_width,flow_newton_iterations,mechanics_iterations,"
                 "coupling_iterations,time_step_cuts,mass_balance_error\n"
              << std::setprecision(10);
      std::ofstream                               pvd;
      const bool                                  write = context.output_format != "none";
      std::vector<std::pair<double, std::string>> pvd_entries;
      const auto output = [&](const unsigned int step, const double t) {
        if (!write)
          return;
        TimerOutput::Scope timer(context.timer, "Flow: output");
        const std::string  name = "flow-" + Utilities::int_to_string(step, 5);
        write_fields(mesh, grid, solver, context.path(name), context.output_format);
        pvd_entries.emplace_back(t, name + "." + context.output_format);
        std::ofstream pvd_file(context.path("flow.pvd"));
        pvd_file << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
                    "<Collection>\n";
        for (const auto &e : pvd_entries)
          pvd_file << "<DataSet timestep=\"" << e.first << "\" file=\"" << e.second << "\"/>\n";
        pvd_file << "</Collection>\n</VTKFile>\n";
      };
      output(0, 0.);

      const auto   initial_volumes = solver.phase_volumes(solver.state);
      double       t = 0, dt = std::min(dt_0, dt_max);
      unsigned int step = 0, total_newton = 0, total_cuts = 0, max_step_newton = 0;
      double       mass_error_max = 0;
      while (t < T_final * (1 - 1e-12))
        {
          const bool   last    = t + dt >= T_final * (1 - 1e-12);
          double       dt_step = last ? T_final - t : dt;
          unsigned int cuts    = 0;
          StepResult   result;
          solver.begin_time_step();
          while (true)
            {
              solver.state = solver.old_state;
              result       = solver.solve_time_step(dt_step, context.verbose);
              if (result.converged)
                break;
              ++cuts;
              if (cuts > max_cut)
                throw SolverFailure("Flow: Newton did not converge at t = " + std::to_string(t) +
                                    " s after " + std::to_string(max_cut) + " time-step cuts");
              dt_step /= 2;
              context.progress << "    Flow: Newton failed (" << result.failure
                               << "), halving the time step to " << dt_step << " s" << std::endl;
            }
          ++step;
          t += dt_step;
          total_newton += result.iterations;
          total_cuts += cuts;
          max_step_newton         = std::max(max_step_newton, result.iterations);
          const double mass_error = std::max(result.mass_defect[0], result.mass_defect[1]);
          mass_error_max          = std::max(mass_error_max, mass_error);
          history << t << ',' << dt_step << ',' << mean_width() << ',' << result.iterations
                  << ",0,0," << cuts << ',' << mass_error << '\n';
          context.progress << "  Flow step " << step << ": t = " << t << " s, dt = " << dt_step
                           << " s, " << result.iterations << " Newton iterations, mass defect "
                           << mass_error << std::endl;
          // dt_{k+1/2} = min(rho dt_{k-1/2}, dt_max)
          dt              = std::min(rho * dt_step, dt_max);
          const bool done = t >= T_final * (1 - 1e-12);
          if ((output_every > 0 && step % output_every == 0) || done)
            output(step, t);
        }

      const auto volumes = solver.phase_volumes(solver.state);
      double     s_min = 1, s_max = 0, sf_min = 1, sf_max = 0;
      for (unsigned int i = 0; i < grid.n_matrix_cells; ++i)
        {
          const double s = solver.saturation(solver.state, i, matrix_rock);
          s_min          = std::min(s_min, s);
          s_max          = std::max(s_max, s);
        }
      for (unsigned int i = grid.n_matrix_cells; i < grid.n_matrix_cells + grid.n_fracture_cells;
           ++i)
        {
          const double s = solver.saturation(solver.state, i, fracture_rock);
          sf_min         = std::min(sf_min, s);
          sf_max         = std::max(sf_max, s);
        }
      context.report << "Flow: " << step << " time steps, " << total_cuts << " time-step cuts"
                     << std::endl
                     << std::scientific << std::setprecision(4) << "Flow: final time " << t << " s"
                     << std::endl
                     << "Flow: pore volume of w " << initial_volumes[0] << " -> " << volumes[0]
                     << ", of nw " << initial_volumes[1] << " -> " << volumes[1] << std::endl
                     << "Flow: matrix s_nw in [" << s_min << ", " << s_max
                     << "], fracture s_nw in [" << sf_min << ", " << sf_max << "]" << std::endl
                     << std::defaultfloat << "Flow: mass balance error per step below 1e-10: "
                     << (mass_error_max <= 1e-10 ? "yes" : "NO") << std::endl;
      context.summary["n_time_steps"]                        = step;
      context.summary["final_time"]                          = t;
      context.summary["mass_balance_error_max"]              = mass_error_max;
      context.summary["flow_newton_iterations"]              = total_newton;
      context.summary["flow_newton_iterations_max_per_step"] = max_step_newton;
      context.summary["time_step_cuts"]                      = total_cuts;
    }

    template void
    run_scene<2>(const ParameterHandler &, const geometry::CutMesh<2> &, io::RunContext &);
    template void
    run_scene<3>(const ParameterHandler &, const geometry::CutMesh<3> &, io::RunContext &);
  } // namespace flow
} // namespace porofrac
