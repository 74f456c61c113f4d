// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/numerics/data_out.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/flow/model.h>
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
      void
      declare_rock(ParameterHandler  &prm,
                   const std::string &name,
                   const std::string &R,
                   const std::string &kr,
                   const std::string &p0)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Saturation law",
                          "corey",
                          Patterns::Selection("corey|van genuchten"),
                          "S^nw(p_c): corey = max(1 - exp(-p_c/R), 0) (paper 5.3); van genuchten "
                          "= 1 - (1 + (p_c/P_r)^n)^(1/n - 1) for p_c > 0.");
        prm.declare_entry("Corey R", R, Patterns::Double(), "Corey pressure scale R (Pa).");
        prm.declare_entry("van Genuchten P_r",
                          "1e6",
                          Patterns::Double(),
                          "van Genuchten pressure scale P_r (Pa).");
        prm.declare_entry("van Genuchten n",
                          "2",
                          Patterns::Double(),
                          "van Genuchten exponent n > 1 (-).");
        prm.declare_entry("Relative permeability",
                          kr,
                          Patterns::Selection("linear|van genuchten-mualem"),
                          "linear: k_r^alpha = s^alpha; van genuchten-mualem: with q, S_lr, S_gr "
                          "(specs.md 1.1).");
        prm.declare_entry("Mualem q",
                          "0.328",
                          Patterns::Double(),
                          "Mualem exponent q in (0,1) (-).");
        prm.declare_entry("S_lr", "0.35", Patterns::Double(), "Residual liquid saturation (-).");
        prm.declare_entry("S_gr", "0", Patterns::Double(), "Residual gas saturation (-).");
        prm.declare_entry("Mobility floor",
                          "0",
                          Patterns::Double(),
                          "Added to k_r in the mobilities so that an absent phase keeps a "
                          "well-posed pressure (-); 0 = exact laws.");
        prm.declare_entry("Mobility floor nw",
                          "-1",
                          Patterns::Double(),
                          "Floor of the non-wetting phase alone (-); negative: Mobility floor. "
                          "With Capillary pressure bound the non-wetting floor should be 0.");
        prm.declare_entry("Initial pressure w",
                          p0,
                          Patterns::Double(),
                          "Initial wetting pressure (Pa).");
        prm.declare_entry("Initial pressure nw",
                          p0,
                          Patterns::Double(),
                          "Initial non-wetting pressure (Pa).");
        prm.leave_subsection();
      }

      double
      get_double(const ParameterHandler         &prm,
                 const std::vector<std::string> &path,
                 const std::string              &name)
      {
        return Utilities::string_to_double(prm.get(path, name));
      }
    } // namespace

    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Flow");
      prm.declare_entry("Axisymmetric",
                        "false",
                        Patterns::Bool(),
                        "Weight volumes and face measures by 2 pi r, r = second coordinate "
                        "(specs.md 1.4).");
      prm.declare_entry("Viscosity w",
                        "1e-3",
                        Patterns::Double(),
                        "Wetting viscosity mu_w (Pa s).");
      prm.declare_entry("Viscosity nw",
                        "1.851e-5",
                        Patterns::Double(),
                        "Non-wetting viscosity mu_nw (Pa s).");
      prm.declare_entry("Final time", "1", Patterns::Double(), "End of the simulation (s).");
      prm.declare_entry("Initial time step", "0.01", Patterns::Double(), "First time step (s).");
      prm.declare_entry("Maximum time step",
                        "1e100",
                        Patterns::Double(),
                        "Delta t_max in dt_{k+1/2} = min(rho dt_{k-1/2}, Delta t_max) (s).");
      prm.declare_entry("Time step growth", "1.1", Patterns::Double(), "rho (-).");
      prm.declare_entry("Maximum time step cuts",
                        "20",
                        Patterns::Integer(0),
                        "Halvings of one step allowed before giving up.");
      prm.declare_entry("Maximum Newton iterations",
                        "50",
                        Patterns::Integer(1),
                        "Newton iterations before the step is halved.");
      prm.declare_entry("Residual tolerance",
                        "1e-5",
                        Patterns::Double(),
                        "Stop Newton when |R|/|R_0| is below this ...");
      prm.declare_entry("Update tolerance",
                        "1e-4",
                        Patterns::Double(),
                        "... or when max |dp| / max |p| is below this ...");
      prm.declare_entry("Mass balance tolerance",
                        "1e-11",
                        Patterns::Double(),
                        "... and each phase's relative mass defect is below this.");
      prm.declare_entry("Capillary chop",
                        "1",
                        Patterns::Double(0),
                        "Newton: largest change of a node's capillary pressure per iteration, in "
                        "units of the Corey R or van Genuchten P_r of its rock (0: no limit).");
      prm.declare_entry("Entry slope iterations",
                        "1000",
                        Patterns::Integer(0),
                        "Newton: number of iterations per time step that use the entry slope "
                        "(see Entry slope in Jacobian); later iterations use the exact Jacobian.");
      prm.declare_entry("Stagnation iterations",
                        "10",
                        Patterns::Integer(0),
                        "Newton: give up (and cut the time step) after this many iterations in "
                        "which neither the residual nor the mass defect halved (0: never).");
      prm.declare_entry("Saturation chop",
                        "0",
                        Patterns::Double(0),
                        "Newton: largest change of a node's non-wetting saturation per "
                        "iteration (Appleyard chop; 0: no limit). Interface nodes are limited "
                        "under both the matrix and the fracture law.");
      prm.declare_entry("Reference pressure",
                        "0",
                        Patterns::Double(),
                        "Pressures are stored relative to this value (Pa); the results do not "
                        "depend on it. Set it to the pressure of the best-conducting region (the "
                        "fractures' boundary pressure): one ulp of a stored 1e5 Pa there can "
                        "exceed the mass balance tolerance (doc/benchmarks/flow.md).");
      prm.declare_entry("Line search",
                        "false",
                        Patterns::Bool(),
                        "Newton: halve the update (up to 4 times) while it increases the "
                        "residual norm (breaks the two-cycles of van Genuchten-Mualem k_r^w, "
                        "whose slope is unbounded at S^nw = 0).");
      prm.declare_entry("Capillary pressure bound",
                        "false",
                        Patterns::Bool(),
                        "Newton: keep p_c >= 0 at every node (the non-wetting pressure of a "
                        "saturated node is projected onto the wetting one; the Jacobian uses "
                        "S'(0+) there). The saturation laws vanish for p_c <= 0, so this removes "
                        "a pressure that no equation fixes; use it with Mobility floor nw = 0.");
      prm.declare_entry("Entry slope in Jacobian",
                        "true",
                        Patterns::Bool(),
                        "Newton: use S'(0+) instead of 0 in the Jacobian where p_c <= 0 (false: "
                        "exact Jacobian).");
      prm.declare_entry("Output every",
                        "1",
                        Patterns::Integer(0),
                        "Write fields every n accepted steps (0: only the last).");
      declare_rock(prm, "Matrix", "2e8", "van genuchten-mualem", "4e6");
      prm.enter_subsection("Matrix");
      prm.declare_entry("Porosity", "0.15", Patterns::Double(), "Initial porosity phi_0 (-).");
      prm.declare_entry("Permeability",
                        "5e-20",
                        Patterns::Double(),
                        "K_0 of the Kozeny-Carman law, K at phi_0 (m^2).");
      prm.declare_entry("Source w",
                        "0",
                        Patterns::Anything(),
                        "Wetting-phase source h^w of scheme (11a): volume of phase per bulk "
                        "volume and second (1/s), muparser in x, y (, z); negative = sink.");
      prm.declare_entry("Source nw",
                        "0",
                        Patterns::Anything(),
                        "Non-wetting-phase source h^nw (1/s), as Source w.");
      prm.leave_subsection();
      declare_rock(prm, "Fracture", "1e2", "linear", "1e5");
      prm.enter_subsection("Fracture");
      prm.declare_entry("Aperture", "1e-3", Patterns::Double(), "Initial aperture d_f (m).");
      prm.declare_entry("Normal transmissibility",
                        "1e-9",
                        Patterns::Double(),
                        "Lambda_f of eq. (3) (m).");
      prm.declare_entry("Damaged layer thickness",
                        "0",
                        Patterns::Double(),
                        "d_a: thickness of the damaged layer on each side of a fracture, the pore "
                        "space of the matrix-fracture interface unknowns (m; 0: massless "
                        "interfaces). The layer uses the fracture's laws.");
      prm.declare_entry("Damaged layer porosity",
                        "0",
                        Patterns::Double(),
                        "phi_a: porosity of the damaged layer (-).");
      prm.leave_subsection();
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Matrix",
                        "",
                        Patterns::Anything(),
                        "Dirichlet conditions on matrix boundary faces: 'id: p_w = v, p_nw = v; "
                        "id: s_nw = v, p_nw = v' (two of p_w, p_nw, s_nw, s_w per id; Pa, -). "
                        "Other boundaries: no flux.");
      prm.declare_entry("Fracture",
                        "",
                        Patterns::Anything(),
                        "Dirichlet conditions on fracture nodes on the outer boundary, same "
                        "syntax (matrix boundary ids).");
      prm.leave_subsection();
      prm.leave_subsection();
    }

    RockType
    parse_rock(const ParameterHandler &prm,
               const std::string      &name,
               const double            mu_w,
               const double            mu_nw)
    {
      const std::vector<std::string> path   = {"Flow", name};
      const std::string              prefix = "Flow/" + name;
      RockType                       rock;
      if (prm.get(path, "Saturation law") == "corey")
        rock.saturation =
          SaturationLaw::corey(get_double(prm, path, "Corey R"), prefix + "/Corey R");
      else
        rock.saturation = SaturationLaw::van_genuchten(get_double(prm, path, "van Genuchten P_r"),
                                                       get_double(prm, path, "van Genuchten n"),
                                                       prefix + "/van Genuchten");
      if (prm.get(path, "Relative permeability") == "linear")
        rock.relative_permeability = RelativePermeability::linear();
      else
        rock.relative_permeability =
          RelativePermeability::van_genuchten_mualem(get_double(prm, path, "Mualem q"),
                                                     get_double(prm, path, "S_lr"),
                                                     get_double(prm, path, "S_gr"),
                                                     prefix);
      rock.viscosity[0]      = mu_w;
      rock.viscosity[1]      = mu_nw;
      rock.mobility_floor    = get_double(prm, path, "Mobility floor");
      rock.mobility_floor_nw = get_double(prm, path, "Mobility floor nw");
      rock.validate("Flow");
      return rock;
    }

    std::map<types::boundary_id, std::array<double, 2>>
    parse_dirichlet(const std::string &text, const RockType &rock, const std::string &parameter)
    {
      std::map<types::boundary_id, std::array<double, 2>> result;
      for (const std::string &entry : Utilities::split_string_list(text, ';'))
        {
          if (entry.empty())
            continue;
          const auto colon = entry.find(':');
          check_input(colon != std::string::npos,
                      parameter,
                      "expected 'id: name = value, name = value', got '" + entry + "'");
          int id = -1;
          try
            {
              id = Utilities::string_to_int(Utilities::trim(entry.substr(0, colon)));
            }
          catch (...)
            {
            }
          check_input(id >= 0 && id < int(geometry::first_fracture_boundary_id),
                      parameter,
                      "bad boundary id in '" + entry + "'");
          std::map<std::string, double> values;
          for (const std::string &item : Utilities::split_string_list(entry.substr(colon + 1), ','))
            {
              const auto eq = item.find('=');
              check_input(eq != std::string::npos,
                          parameter,
                          "expected 'name = value' in '" + entry + "'");
              const std::string key = Utilities::trim(item.substr(0, eq));
              check_input(key == "p_w" || key == "p_nw" || key == "s_nw" || key == "s_w",
                          parameter,
                          "unknown quantity '" + key + "' (p_w, p_nw, s_nw, s_w)");
              double v = 0;
              try
                {
                  v = Utilities::string_to_double(Utilities::trim(item.substr(eq + 1)));
                }
              catch (...)
                {
                  throw InputError(parameter, "bad number in '" + item + "'");
                }
              values[key] = v;
            }
          check_input(values.size() == 2,
                      parameter,
                      "give exactly two of p_w, p_nw, s_nw, s_w for boundary id " +
                        std::to_string(id));
          if (values.count("s_w"))
            {
              check_input(values["s_w"] >= 0 && values["s_w"] <= 1,
                          parameter,
                          "saturation s_w outside [0, 1] for boundary id " + std::to_string(id));
              values["s_nw"] = 1. - values["s_w"];
            }
          if (values.count("s_nw"))
            check_input(values["s_nw"] >= 0 && values["s_nw"] <= 1,
                        parameter,
                        "saturation s_nw outside [0, 1] for boundary id " + std::to_string(id));
          std::array<double, 2> p;
          if (values.count("p_w") && values.count("p_nw"))
            p = {{values["p_w"], values["p_nw"]}};
          else
            {
              check_input(values.count("s_nw"),
                          parameter,
                          "give a saturation and one pressure, or both pressures, for id " +
                            std::to_string(id));
              const double pc = rock.saturation.inverse(values["s_nw"], parameter);
              if (values.count("p_w"))
                p = {{values["p_w"], values["p_w"] + pc}};
              else
                p = {{values["p_nw"] - pc, values["p_nw"]}};
            }
          result[id] = p;
        }
      return result;
    }

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
      FlowModel<dim>       model  = make_flow_model<dim>(prm, mesh);
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
          // dt_{k+1/2} = min(rho dt_{k-1/2}, dt_max) (specs.md 1.1)
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
