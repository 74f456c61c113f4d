// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/coupling/analytical.h>
#include <porofrac/coupling/poromechanics.h>
#include <porofrac/coupling/scene.h>
#include <porofrac/flow/model.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/geometry/mesh_output.h>
#include <porofrac/io/text.h>
#include <porofrac/mechanics/contact_output.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>

namespace porofrac
{
  namespace coupling
  {
    using namespace dealii;

    void
    declare_parameters(ParameterHandler &prm)
    {
      CouplingParameters::declare_parameters(prm);
      prm.enter_subsection("Coupling");
      prm.declare_entry("Fracture output times",
                        "",
                        Patterns::Anything(),
                        "Comma-separated times (s) after which fractures.csv rows are written "
                        "(at the first step reaching each); t = 0 and the final time always are.");
      prm.declare_entry("Analytical solution",
                        "none",
                        Patterns::Selection("none|terzaghi"),
                        "terzaghi: at the final time, the relative L2 error of the matrix wetting "
                        "pressure against Terzaghi's consolidation of a laterally confined column, "
                        "drained at the top (largest y) through a Dirichlet condition and loaded "
                        "by a constant pressure (coupling/analytical.h).");
      prm.leave_subsection();
    }

    namespace
    {
      /// Face-state counts (open, stick, slip) of one fracture, or of all with fid = -1.
      template <int dim>
      std::array<unsigned int, 3>
      count_states(const mechanics::ContactProblem<dim> &problem, const int fid)
      {
        std::array<unsigned int, 3> c{{0, 0, 0}};
        for (const auto &face : problem.get_mesh().fracture_faces)
          if (fid < 0 || int(face.fracture_id) == fid)
            ++c[static_cast<unsigned int>(problem.state(face.index))];
        return c;
      }

      template <int dim>
      void
      report_states(std::ostream                         &out,
                    const mechanics::ContactProblem<dim> &problem,
                    const std::string                    &when)
      {
        for (const unsigned int fid : problem.get_mesh().fracture_ids)
          {
            const auto c = count_states(problem, fid);
            out << "Coupling: " << when << ", fracture " << fid << ": open " << c[0] << ", stick "
                << c[1] << ", slip " << c[2] << std::endl;
          }
      }

      template <int dim>
      void
      write_fields(const Poromechanics<dim> &pm,
                   const std::string        &basename,
                   const std::string        &format)
      {
        const auto        &grid   = *pm.flow.grid;
        const auto        &solver = *pm.flow.solver;
        const auto        &mesh   = pm.mechanics.get_mesh();
        const unsigned int n      = grid.n_matrix_cells;
        Vector<double>     pw(n), pnw(n), snw(n), pE(n), phi(n);
        for (unsigned int K = 0; K < n; ++K)
          {
            pw[K]  = solver.pressure(solver.state, K, 0);
            pnw[K] = solver.pressure(solver.state, K, 1);
            snw[K] = solver.saturation(solver.state, K, flow::matrix_rock);
            pE[K]  = pm.equivalent_pressure()[K];
            phi[K] = grid.porosity[K];
          }
        geometry::write_cell_fields(
          mesh,
          basename,
          format,
          {{"p_w", pw}, {"p_nw", pnw}, {"s_nw", snw}, {"p_E", pE}, {"porosity", phi}});
        geometry::FractureFields fields = {{"p_w", {}},
                                           {"p_nw", {}},
                                           {"s_nw", {}},
                                           {"p_E", {}},
                                           {"aperture", {}},
                                           {"jump_n", {}},
                                           {"jump_t", {}},
                                           {"lambda_n", {}},
                                           {"state", {}}};
        for (unsigned int f = 0; f < grid.n_fracture_cells; ++f)
          {
            const unsigned int   i = n + f;
            const Tensor<2, dim> R = pm.mechanics.frame(f);
            const Tensor<1, dim> j = R * pm.mechanics.jump(f);
            const Tensor<1, dim> l = R * pm.mechanics.multiplier(f);
            fields[0].second.push_back(solver.pressure(solver.state, i, 0));
            fields[1].second.push_back(solver.pressure(solver.state, i, 1));
            fields[2].second.push_back(solver.saturation(solver.state, i, flow::fracture_rock));
            fields[3].second.push_back(pm.equivalent_pressure()[i]);
            fields[4].second.push_back(grid.aperture[f]);
            fields[5].second.push_back(j[0]);
            fields[6].second.push_back(j[1]);
            fields[7].second.push_back(l[0]);
            fields[8].second.push_back(static_cast<double>(pm.mechanics.state(f)));
          }
        if (grid.n_fracture_cells > 0)
          geometry::write_fracture_cells(mesh, basename + "_fractures." + format, format, fields);

        DataOut<dim> data_out;
        data_out.attach_dof_handler(pm.mechanics.get_dof_handler());
        std::vector<DataComponentInterpretation::DataComponentInterpretation> interp(
          dim, DataComponentInterpretation::component_is_part_of_vector);
        data_out.add_data_vector(pm.mechanics.displacement(),
                                 std::vector<std::string>(dim, "displacement"),
                                 DataOut<dim>::type_dof_data,
                                 interp);
        data_out.build_patches(mesh.mapping(), 2);
        geometry::write_data_out(data_out, basename + "_displacement." + format, format);
      }

      /// Relative L2 error (cell-measure weighted) of the matrix wetting pressure at time t.
      template <int dim>
      void
      report_terzaghi_error(const flow::FlowParameters         &flow_parameters,
                            const Poromechanics<dim>           &pm,
                            const mechanics::ContactParameters &mp,
                            const CouplingParameters           &cp,
                            const double                        t,
                            io::RunContext                     &context)
      {
        const auto &grid   = *pm.flow.grid;
        const auto &solver = *pm.flow.solver;
        const auto &tria   = pm.mechanics.get_mesh().triangulation;
        double      y_min = 1e300, y_max = -1e300;
        for (const auto &v : tria.get_vertices())
          {
            y_min = std::min(y_min, v[1]);
            y_max = std::max(y_max, v[1]);
          }
        Terzaghi exact;
        exact.height           = y_max - y_min;
        exact.initial_pressure = flow_parameters.initial_pressure[flow::matrix_rock][0];
        exact.drained_pressure =
          solver.matrix_dirichlet.empty() ? 0. : solver.matrix_dirichlet.begin()->second[0];
        exact.consolidation = Terzaghi::coefficient(pm.flow.initial_permeability,
                                                    pm.flow.rocks[0].viscosity[0],
                                                    mp.young_modulus,
                                                    mp.poisson_ratio,
                                                    cp.biot_coefficient,
                                                    cp.biot_modulus);
        double e2 = 0, n2 = 0;
        for (unsigned int K = 0; K < grid.n_matrix_cells; ++K)
          {
            const double z  = y_max - grid.nodes[K].centre[1];
            const double pe = exact.pressure(z, t);
            const double w  = grid.nodes[K].measure;
            e2 += w * std::pow(solver.pressure(solver.state, K, 0) - pe, 2);
            n2 += w * std::pow(pe - exact.drained_pressure, 2);
          }
        const double error = std::sqrt(e2 / n2);
        context.report << "Coupling: Terzaghi, c_v t / H^2 = " << std::setprecision(4)
                       << exact.consolidation * t / (exact.height * exact.height)
                       << ", relative L2 error of the excess pressure " << std::scientific
                       << std::setprecision(3) << error << std::defaultfloat << std::endl;
        io::Json e                = io::Json::object();
        e["pressure_rel_l2"]      = error;
        context.summary["errors"] = e;
      }
    } // namespace



    template <int dim>
    void
    run_scene(ParameterHandler &prm, const geometry::CutMesh<dim> &mesh, io::RunContext &context)
    {
      mechanics::ContactParameters mechanics_parameters;
      mechanics_parameters.parse_parameters(prm, dim);
      CouplingParameters parameters;
      parameters.parse_parameters(prm);
      std::vector<double> output_times;
      for (const std::string &s :
           Utilities::split_string_list(prm.get({"Coupling"}, "Fracture output times"), ','))
        {
          try
            {
              output_times.push_back(Utilities::string_to_double(s));
            }
          catch (...)
            {
              throw InputError("Coupling/Fracture output times", "'" + s + "' is not a number");
            }
        }
      std::sort(output_times.begin(), output_times.end());

      // Inside coupled iterations the flow Newton must be converged tightly (see
      // CouplingParameters); the deck's tolerances are the upper bounds.
      flow::FlowParameters flow_parameters;
      flow_parameters.parse_parameters(prm);
      flow::FlowModel<dim> flow =
        flow::make_flow_model<dim>(flow_parameters, mesh, [&](flow::NewtonParameters &n) {
          // At its noise floor (kinks of S and of the upwinding), accept an inner solve that meets
          // the flow deck's own tolerances instead of cutting the step.
          n.stagnation_update_tolerance = n.update_tolerance;
          n.stagnation_mass_tolerance   = 1e-10; // the per-step conservation target

          n.residual_tolerance =
            std::min(n.residual_tolerance, parameters.inner_flow_residual_tolerance);
          n.update_tolerance = std::min(n.update_tolerance, parameters.inner_flow_update_tolerance);
        });
      const flow::TimeStepping &stepping = flow.stepping;
      double t_reachable = 0, dt_probe = std::min(stepping.initial_step, stepping.maximum_step);
      // A configuration that cannot reach the final time in a sane number of steps is bad input.
      for (unsigned int k = 0; k < 1000000 && t_reachable < stepping.final_time; ++k)
        {
          t_reachable += dt_probe;
          dt_probe = std::min(stepping.growth * dt_probe, stepping.maximum_step);
        }
      check_input(
        t_reachable >= stepping.final_time,
        "Flow/Maximum time step",
        "the final time " + io::to_text(stepping.final_time) +
          " s is not reached in 10^6 steps with this initial step, growth and maximum step");

      context.progress << "*** Poromechanics: contact mechanics set-up" << std::endl;
      mechanics::ContactProblem<dim> mech(mesh,
                                          mechanics_parameters,
                                          context.verbose,
                                          context.timer);
      mech.setup();
      context.summary["n_dofs_mechanics"] = mech.n_dofs();
      context.summary["n_unknowns_flow"]  = flow.solver->n_unknowns();
      context.report << "Coupling: " << mech.n_dofs() << " mechanics dofs, "
                     << flow.solver->n_unknowns() << " flow unknowns, " << flow.grid->n_matrix_cells
                     << " matrix cells, " << flow.grid->n_fracture_cells << " fracture cells"
                     << std::endl;

      Poromechanics<dim> pm(mech, flow, parameters, context.verbose, context.timer);
      context.progress << "*** Poromechanics: initial state" << std::endl;
      pm.initialize();
      const unsigned int initial_mechanics_iterations = mech.statistics().iterations;
      report_states(context.report, mech, "t = 0");
      context.report << "Coupling: t = 0, mean fracture width " << std::scientific
                     << std::setprecision(4) << pm.mean_fracture_width() << " m"
                     << std::defaultfloat << std::endl;

      std::ofstream fractures(context.path("fractures.csv"));
      check_input(bool(fractures), "--output-dir", "cannot write fractures.csv");
      mechanics::write_fracture_table_header(fractures, dim, true);
      double t = 0;
      mechanics::write_fracture_table_rows(fractures, mech, &flow.grid->aperture, &t);

      std::ofstream history(context.path("history.csv"));
      check_input(bool(history), "--output-dir", "cannot write history.csv");
      history << "time,dt,mean_fracture_width,flow_newton_iterations,mechanics_iterations,"
                 "coupling_iterations,time_step_cuts,mass_balance_error,map_evaluations,"
                 "gmres_iterations,n_open,n_stick,n_slip,energy_capillary_matrix,"
                 "energy_capillary_fracture,energy_elastic,energy_storage,flow_dissipation,"
                 "friction_work,supplied_work,energy_inequality_violation\n"
              << std::setprecision(10);

      const bool                                  write = context.output_format != "none";
      std::vector<std::pair<double, std::string>> pvd_entries;
      const auto output = [&](const unsigned int step, const double time) {
        if (!write)
          return;
        TimerOutput::Scope timer(context.timer, "Coupling: output");
        const std::string  name = "poromechanics-" + Utilities::int_to_string(step, 5);
        write_fields(pm, context.path(name), context.output_format);
        pvd_entries.emplace_back(time, name + "." + context.output_format);
        std::ofstream pvd(context.path("poromechanics.pvd"));
        pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
               "<Collection>\n";
        for (const auto &e : pvd_entries)
          pvd << "<DataSet timestep=\"" << e.first << "\" file=\"" << e.second << "\"/>\n";
        pvd << "</Collection>\n</VTKFile>\n";
      };
      output(0, 0.);

      EnergyTerms  energy_old = pm.energy();
      double       dt         = std::min(stepping.initial_step, stepping.maximum_step);
      unsigned int step = 0, next_output = 0, total_cuts = 0;
      unsigned int total_flow = 0, total_mechanics = 0, total_coupling = 0, total_maps = 0,
                   total_gmres = 0, max_coupling = 0;
      double mass_error_max = 0, violation_max = 0;
      while (next_output < output_times.size() && output_times[next_output] <= 0)
        ++next_output;
      const double T = stepping.final_time;
      while (t < T * (1 - 1e-12))
        {
          double            dt_step = (t + dt >= T * (1 - 1e-12)) ? T - t : dt;
          unsigned int      cuts    = 0;
          CoupledStepReport r;
          while (true)
            {
              r = pm.solve_time_step(dt_step);
              total_flow += r.flow_newton_iterations;
              total_mechanics += r.mechanics_iterations;
              total_maps += r.map_evaluations;
              total_gmres += r.gmres_iterations;
              if (r.converged)
                break;
              ++cuts;
              context.progress << "    Coupling: step failed at t = " << t << " s (" << r.failure
                               << "), halving dt to " << dt_step / 2 << " s" << std::endl;
              if (cuts > stepping.maximum_cuts)
                {
                  // Keep the last good state on disk before stopping.
                  output(step + 1, t);
                  throw SolverFailure("Coupling: no convergence at t = " + io::to_text(t) +
                                      " s after " + std::to_string(stepping.maximum_cuts) +
                                      " time-step cuts; last failure: " + r.failure +
                                      ". The last good state is written.");
                }
              dt_step /= 2;
            }
          ++step;
          t += dt_step;
          total_cuts += cuts;
          total_coupling += r.coupling_iterations;
          max_coupling = std::max(max_coupling, r.coupling_iterations);

          // Energy estimate (19), discrete form of one step (see EnergyTerms).
          const EnergyTerms energy = pm.energy();
          const double      change = energy.total() - energy_old.total();
          const double lhs = change + pm.last_step_dissipation() + pm.last_step_friction_work();
          const double supplied = pm.last_step_supplied_work();
          const double scale    = std::abs(change) + pm.last_step_dissipation() +
                               std::abs(pm.last_step_friction_work()) + std::abs(supplied);
          const double violation  = scale > 0 ? std::max(0., lhs - supplied) / scale : 0.;
          violation_max           = std::max(violation_max, violation);
          energy_old              = energy;
          const double mass_error = std::max(r.mass_defect[0], r.mass_defect[1]);
          mass_error_max          = std::max(mass_error_max, mass_error);
          pm.accept_time_step();

          const auto c = count_states(mech, -1);
          history << t << ',' << dt_step << ',' << pm.mean_fracture_width() << ','
                  << r.flow_newton_iterations << ',' << r.mechanics_iterations << ','
                  << r.coupling_iterations << ',' << cuts << ',' << mass_error << ','
                  << r.map_evaluations << ',' << r.gmres_iterations << ',' << c[0] << ',' << c[1]
                  << ',' << c[2] << ',' << energy.capillary_matrix << ','
                  << energy.capillary_fracture << ',' << energy.elastic << ',' << energy.storage
                  << ',' << pm.last_step_dissipation() << ',' << pm.last_step_friction_work() << ','
                  << supplied << ',' << violation << std::endl;
          context.progress << "  Step " << step << ": t = " << t / 3.15576e7
                           << " y, dt = " << dt_step << " s, " << r.coupling_iterations
                           << " coupling, " << r.flow_newton_iterations << " flow, "
                           << r.mechanics_iterations << " mechanics iterations; mean width "
                           << pm.mean_fracture_width() << " m; open/stick/slip " << c[0] << '/'
                           << c[1] << '/' << c[2] << std::endl;

          const bool done  = t >= T * (1 - 1e-12);
          bool       table = done;
          while (next_output < output_times.size() && output_times[next_output] <= t * (1 + 1e-12))
            {
              table = true;
              ++next_output;
            }
          if (table)
            mechanics::write_fracture_table_rows(fractures, mech, &flow.grid->aperture, &t);
          if ((stepping.output_every > 0 && step % stepping.output_every == 0) || done || table)
            output(step, t);
          // dt_{k+1/2} = min(rho dt_{k-1/2}, dt_max)
          dt = std::min(stepping.growth * dt_step, stepping.maximum_step);
        }

      report_states(context.report, mech, "final time");
      context.report << "Coupling: " << step << " time steps, " << total_cuts
                     << " time-step cuts, final time " << std::scientific << std::setprecision(4)
                     << t << " s" << std::endl
                     << "Coupling: final mean fracture width " << pm.mean_fracture_width() << " m"
                     << std::defaultfloat << std::endl
                     << "Coupling: iterations: coupling " << total_coupling << ", map evaluations "
                     << total_maps << ", flow Newton " << total_flow << ", mechanics "
                     << total_mechanics << std::endl
                     << "Coupling: mass balance error per step below 1e-10: "
                     << (mass_error_max <= 1e-10 ? "yes" : "NO") << std::endl
                     << "Coupling: energy inequality (19) holds at every step: "
                     << (violation_max <= 1e-6 ? "yes" : "NO") << std::endl;

      if (prm.get({"Coupling"}, "Analytical solution") == "terzaghi")
        report_terzaghi_error(flow_parameters, pm, mechanics_parameters, parameters, t, context);

      io::Json m                    = io::Json::object();
      m["solver"]                   = prm.get({"Mechanics"}, "Solver");
      m["c"]                        = mechanics_parameters.c;
      m["nonlinear_iterations"]     = total_mechanics;
      m["initial_state_iterations"] = initial_mechanics_iterations;
      // LU factorizations of the contact system (reused while no face row changes).
      m["lu_factorizations"]                             = mech.n_factorizations();
      m["converged"]                                     = true;
      const auto c                                       = count_states(mech, -1);
      m["n_open"]                                        = c[0];
      m["n_stick"]                                       = c[1];
      m["n_slip"]                                        = c[2];
      context.summary["mechanics"]                       = m;
      io::Json cpl                                       = io::Json::object();
      cpl["fixed_point"]                                 = prm.get({"Coupling"}, "Fixed point");
      cpl["method"]                                      = parameters.fixed_point.method;
      cpl["iterations"]                                  = total_coupling;
      cpl["iterations_max_per_step"]                     = max_coupling;
      cpl["map_evaluations"]                             = total_maps;
      cpl["gmres_iterations"]                            = total_gmres;
      context.summary["coupling"]                        = cpl;
      context.summary["n_time_steps"]                    = step;
      context.summary["final_time"]                      = t;
      context.summary["time_step_cuts"]                  = total_cuts;
      context.summary["flow_newton_iterations"]          = total_flow;
      context.summary["mass_balance_error_max"]          = mass_error_max;
      context.summary["energy_inequality_violation_max"] = violation_max;
      context.summary["mean_fracture_width"]             = pm.mean_fracture_width();
    }

    template void
    run_scene<2>(ParameterHandler &, const geometry::CutMesh<2> &, io::RunContext &);
    template void
    run_scene<3>(ParameterHandler &, const geometry::CutMesh<3> &, io::RunContext &);
  } // namespace coupling
} // namespace porofrac
