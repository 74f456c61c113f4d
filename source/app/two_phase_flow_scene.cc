// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <porofrac/app/checkpointing.h>
#include <porofrac/app/time_loop.h>
#include <porofrac/app/two_phase_flow_scene.h>
#include <porofrac/base/mpi_tools.h>
#include <porofrac/flow/boundary_fluxes.h>
#include <porofrac/flow/flow_output.h>
#include <porofrac/flow/line_samples.h>
#include <porofrac/flow/model.h>
#include <porofrac/geometry/mesh_output.h>
#include <porofrac/io/output_directory.h>
#include <porofrac/io/output_file.h>
#include <porofrac/io/pvd_writer.h>

#include <algorithm>
#include <fstream>
#include <iomanip>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /// What a flow run sums over its steps (every attempt's Newton iterations included).
      struct FlowTotals
      {
        unsigned int          newton = 0, max_step_newton = 0, cuts = 0;
        double                mass_error_max = 0;
        std::array<double, 2> initial_volumes{{0., 0.}};

        void
        save(io::CheckpointWriter &w) const
        {
          w.put("Newton iterations", newton);
          w.put("Newton iterations per step", max_step_newton);
          w.put("time-step cuts", cuts);
          w.put("mass balance error", mass_error_max);
          w.put("initial phase volumes",
                std::vector<double>(initial_volumes.begin(), initial_volumes.end()));
        }

        void
        load(io::CheckpointReader &r)
        {
          std::vector<double> volumes;
          r.get("Newton iterations", newton);
          r.get("Newton iterations per step", max_step_newton);
          r.get("time-step cuts", cuts);
          r.get("mass balance error", mass_error_max);
          r.get("initial phase volumes", volumes);
          check_input(volumes.size() == 2, "--restart", "malformed checkpoint");
          initial_volumes = {{volumes[0], volumes[1]}};
        }
      };

      /// Ranges of s_nw over the matrix cells and over the fracture cells.
      template <int dim>
      void
      report_saturation_ranges(const flow::FlowModel<dim> &model, std::ostream &report)
      {
        const auto &grid        = *model.grid;
        const auto &solver      = *model.solver;
        double      range[2][2] = {{1, 0}, {1, 0}};
        for (unsigned int i = 0; i < grid.n_matrix_cells + grid.n_fracture_cells; ++i)
          {
            const bool   fracture = i >= grid.n_matrix_cells;
            const double s        = solver.saturation(solver.state,
                                               i,
                                               fracture ? flow::fracture_rock : flow::matrix_rock);
            range[fracture][0]    = std::min(range[fracture][0], s);
            range[fracture][1]    = std::max(range[fracture][1], s);
          }
        report << std::scientific << std::setprecision(4) << "Flow: matrix s_nw in [" << range[0][0]
               << ", " << range[0][1] << "], fracture s_nw in [" << range[1][0] << ", "
               << range[1][1] << "]" << std::defaultfloat << std::endl;
      }
    } // namespace



    namespace
    {
      /**
       * One flow-only run: the flow model, its time stepper, field series, history.csv and
       * checkpoints, and what run_time_loop() calls for each step.
       */
      template <int dim>
      class FlowRun
      {
      public:
        FlowRun(const PhysicsParameters         &parameters,
                const geometry::CutMesh<dim>    &mesh,
                io::RunContext                  &context,
                const std::vector<unsigned int> &cell_owner);

        /// The state at t = 0 (or the restored one) written, history.csv open.
        void
        start();
        StepOutcome
        attempt(const double dt);
        void
        accept();
        void
        write_accepted_state(const bool restore_first);
        /// Report and summary.json entries of the finished run; its postprocessors.
        void
        finish(const PhysicsParameters &parameters);
        /// The run's totals in summary.json (steps, time, iterations, mass balance), also for a
        /// run that failed or was interrupted.
        void
        summarize_totals();

        AdaptiveTimeStepper stepper;

      private:
        void
        output(const unsigned int step, const double time);
        void
        save(io::CheckpointWriter &w) const;
        void
        load(io::CheckpointReader &r);

        const geometry::CutMesh<dim> &mesh;
        io::RunContext               &context;
        /// Whether this process writes the files (rank 0 of the run's processes).
        const bool writer;
        /// Which cells of the field files this process writes.
        const geometry::OutputPieces       pieces;
        flow::FlowModel<dim>               model;
        flow::TpfaGrid<dim>               &grid;
        flow::TwoPhaseSolver<dim>         &solver;
        FlowTotals                         totals;
        flow::StepResult                   result;
        io::PvdWriter                      pvd;
        int                                last_written = -1; // step of the last field files
        Checkpointing                      checkpoints;
        std::ofstream                     *history = nullptr;
        std::vector<flow::SampleLine<dim>> sample_lines;
        const bool                         axisymmetric;

        /// line_<name>.csv of every sample line: s, x, y[, z], p_w of the final state.
        void
        write_sample_lines() const;
      };



      /// The flow grid's counts and its TPFA admissibility, to the report and summary.json.
      template <int dim>
      void
      report_flow_grid(const flow::TpfaGrid<dim>       &grid,
                       const flow::TwoPhaseSolver<dim> &solver,
                       io::RunContext                  &context)
      {
        const bool circumcentres = grid.centres == flow::TpfaGrid<dim>::Centres::circumcentre;
        context.report << "Flow: " << grid.n_matrix_cells << " matrix cells, "
                       << grid.n_fracture_cells << " fracture cells, " << grid.n_interfaces
                       << " interface nodes, " << grid.n_intersections << " intersection nodes, "
                       << solver.n_unknowns() << " unknowns" << std::endl
                       << "Flow: " << grid.n_non_admissible << " cell faces with the "
                       << (circumcentres ? "circumcentre" : "centroid") << " on the wrong side, "
                       << grid.n_fallback
                       << (dim == 2 ? " connections of cocircular cells (centres merged)" :
                                      " connections of cocircular cells or centres out of order "
                                      "(merged or unsigned distances)")
                       << std::endl;
        if (dim == 3 && grid.n_fracture_cells > 0)
          context.report << "Flow: " << grid.n_non_admissible_fracture
                         << " fracture connections of cocircular triangles or with a centre on or "
                            "beyond the edge (merged or unsigned distances)"
                         << std::endl;
        context.summary["n_unknowns_flow"] = solver.n_unknowns();
        context.summary["n_nonzeros_flow"] = solver.n_nonzeros();
        io::Json &admissibility            = context.summary["flow_mesh"];
        admissibility["cell_centres"]      = circumcentres ? "circumcentre" : "centroid";
        admissibility["n_non_admissible_matrix_faces"]         = grid.n_non_admissible;
        admissibility["n_matrix_fallback_connections"]         = grid.n_fallback;
        admissibility["n_non_admissible_fracture_connections"] = grid.n_non_admissible_fracture;
        admissibility["n_intersection_nodes"]                  = grid.n_intersections;
      }



      template <int dim>
      FlowRun<dim>::FlowRun(const PhysicsParameters         &parameters,
                            const geometry::CutMesh<dim>    &mesh,
                            io::RunContext                  &context,
                            const std::vector<unsigned int> &cell_owner)
          : stepper(parameters.flow.stepping.final_time,
                    parameters.flow.stepping.initial_step,
                    parameters.flow.stepping.maximum_step,
                    parameters.flow.stepping.growth,
                    parameters.flow.stepping.maximum_cuts)
          , mesh(mesh)
          , context(context)
          , writer(context.writes_files())
          , pieces(geometry::replicated_mesh_pieces(cell_owner, context.communicator))
          , model([&] {
            TimerOutput::Scope t(context.timer, "Flow: grid and solver set-up");
            return flow::make_flow_model<dim>(parameters.flow,
                                              mesh,
                                              {},
                                              context.communicator != MPI_COMM_SELF);
          }())
          , grid(*model.grid)
          , solver(*model.solver)
          , pvd(context.path("flow.pvd"))
          , checkpoints(context, "two-phase flow", stepper, pvd, {"history.csv"})
          , sample_lines(
              flow::parse_sample_lines<dim>(parameters.flow.sample_lines, "Flow/Sample lines"))
          , axisymmetric(parameters.flow.axisymmetric)
      {
        solver.timer = &context.timer;
        if (context.communicator != MPI_COMM_SELF)
          {
            TimerOutput::Scope t(context.timer, "Flow: distribution");
            solver.distribute(context.communicator, grid.node_owners(cell_owner));
          }
        report_flow_grid(grid, solver, context);
        totals.initial_volumes = solver.phase_volumes(solver.state);
      }



      template <int dim>
      void
      FlowRun<dim>::start()
      {
        if (checkpoints.restarting())
          checkpoints.restore([this](io::CheckpointReader &r) { load(r); });
        else
          output(0, 0.);
        history = &checkpoints.text_file(
          "history.csv",
          "time,dt,mean_fracture_width,flow_newton_iterations,mechanics_iterations,"
          "coupling_iterations,time_step_cuts,mass_balance_error\n");
        *history << std::setprecision(10);
      }



      template <int dim>
      StepOutcome
      FlowRun<dim>::attempt(const double dt)
      {
        solver.state = solver.old_state;
        result       = solver.solve_time_step(dt, context.verbose);
        totals.newton += result.iterations;
        return {result.converged, result.failure};
      }



      template <int dim>
      void
      FlowRun<dim>::accept()
      {
        const unsigned int step       = stepper.step_number();
        const double       t          = stepper.time();
        const double       mass_error = std::max(result.mass_defect[0], result.mass_defect[1]);
        totals.mass_error_max         = std::max(totals.mass_error_max, mass_error);
        totals.max_step_newton        = std::max(totals.max_step_newton, result.iterations);
        totals.cuts += stepper.last_step_cuts();
        solver.begin_time_step();
        *history << t << ',' << stepper.last_step_size() << ',' << flow::mean_aperture(mesh, grid)
                 << ',' << result.iterations << ",0,0," << stepper.last_step_cuts() << ','
                 << mass_error << std::endl;
        context.progress << "  Flow step " << step << ": t = " << t
                         << " s, dt = " << stepper.last_step_size() << " s, " << result.iterations
                         << " Newton iterations, mass defect " << mass_error << std::endl;
        const unsigned int every = model.stepping.output_every;
        if ((every > 0 && step % every == 0) || stepper.finished())
          output(step, t);
        checkpoints.after_step([this](io::CheckpointWriter &w) { save(w); });
      }



      template <int dim>
      void
      FlowRun<dim>::write_accepted_state(const bool restore_first)
      {
        if (restore_first)
          solver.state = solver.old_state;
        if (last_written != int(stepper.step_number()))
          output(stepper.step_number(), stepper.time());
        if (!restore_first)
          checkpoints.write([this](io::CheckpointWriter &w) { save(w); });
      }



      template <int dim>
      void
      FlowRun<dim>::output(const unsigned int step, const double t)
      {
        if (context.output_format == "none")
          return;
        // Every process writes its cells (one piece each, or rank 0 all of them); a file that
        // cannot be written stops every process.
        TimerOutput::Scope timer(context.timer, "Flow: output");
        const std::string  name   = "flow-" + Utilities::int_to_string(step, 5);
        const std::string &format = context.output_format;
        std::string        file;
        collectively(context.communicator, [&]() {
          file = geometry::write_cell_fields(
            mesh, context.path(name), format, flow::matrix_fields(solver, grid), pieces);
          if (writer && grid.n_fracture_cells > 0)
            geometry::write_fracture_cells(mesh,
                                           context.path(name + "_fractures." + format),
                                           format,
                                           flow::fracture_fields(solver, grid));
        });
        // Listed once every piece is written.
        collectively(context.communicator, [&]() {
          if (writer)
            pvd.add(t, file);
        });
        last_written = step;
      }



      template <int dim>
      void
      FlowRun<dim>::write_sample_lines() const
      {
        for (const auto &line : sample_lines)
          {
            const auto     cells = flow::cells_along_line(mesh, line);
            io::OutputFile file(context.path("line_" + line.name + ".csv"));
            std::ostream  &out = file.stream();
            out << io::sample_line_header(dim) << '\n' << std::setprecision(10);
            unsigned int outside = 0;
            for (unsigned int k = 0; k < cells.size(); ++k)
              {
                const double     t = double(k) / (cells.size() - 1);
                const Point<dim> p = line.start + t * (line.end - line.start);
                if (cells[k] == numbers::invalid_unsigned_int)
                  {
                    ++outside;
                    continue;
                  }
                out << t * line.start.distance(line.end);
                for (unsigned int d = 0; d < dim; ++d)
                  out << ',' << p[d];
                out << ',' << solver.pressure(solver.state, cells[k], 0) << '\n';
              }
            file.close();
            if (outside > 0)
              context.report << "Flow: sample line " << line.name << ": " << outside
                             << " points outside the mesh (not written)" << std::endl;
          }
      }



      template <int dim>
      void
      FlowRun<dim>::save(io::CheckpointWriter &w) const
      {
        w.put("flow unknowns", solver.n_unknowns());
        w.put("flow state", solver.state);
        totals.save(w);
        flow::save_linear_statistics(w, solver.linear_statistics());
        w.put("last written step", static_cast<unsigned int>(last_written + 1));
      }



      template <int dim>
      void
      FlowRun<dim>::load(io::CheckpointReader &r)
      {
        r.expect("flow unknowns", solver.n_unknowns());
        r.get("flow state", solver.state);
        totals.load(r);
        solver.restore_linear_statistics(flow::load_linear_statistics(r));
        unsigned int written = 0;
        r.get("last written step", written);
        last_written = int(written) - 1;
        solver.begin_time_step();
      }



      template <int dim>
      void
      FlowRun<dim>::summarize_totals()
      {
        auto &summary                                  = context.summary;
        summary["n_time_steps"]                        = stepper.step_number();
        summary["final_time"]                          = stepper.time();
        summary["mass_balance_error_max"]              = totals.mass_error_max;
        summary["flow_newton_iterations"]              = totals.newton;
        summary["flow_newton_iterations_max_per_step"] = totals.max_step_newton;
        summary["time_step_cuts"]                      = totals.cuts;
        summary["flow_linear_solver"] =
          flow::linear_solver_summary(solver.linear_solver_name(), solver.linear_statistics());
      }



      template <int dim>
      void
      FlowRun<dim>::finish(const PhysicsParameters &parameters)
      {
        const auto  volumes         = solver.phase_volumes(solver.state);
        const auto &initial_volumes = totals.initial_volumes;
        context.report << "Flow: " << stepper.step_number() << " time steps, " << totals.cuts
                       << " time-step cuts" << std::endl
                       << std::scientific << std::setprecision(4) << "Flow: final time "
                       << stepper.time() << " s" << std::endl
                       << "Flow: pore volume of w " << initial_volumes[0] << " -> " << volumes[0]
                       << ", of nw " << initial_volumes[1] << " -> " << volumes[1]
                       << std::defaultfloat << std::endl;
        report_saturation_ranges(model, context.report);
        context.report << "Flow: mass balance error per step below 1e-10: "
                       << (totals.mass_error_max <= 1e-10 ? "yes" : "NO") << std::endl;
        summarize_totals();
        auto &summary = context.summary;
        flow::report_linear_solver(solver.linear_solver_name(),
                                   solver.linear_statistics(),
                                   context.report);

        const auto balances =
          flow::boundary_balances(mesh, solver, model.matrix_flux, axisymmetric);
        flow::report_boundary_balances(balances, dim == 2 && !axisymmetric, context.report);
        summary["boundary_fluxes"] = flow::to_json(balances);
        // Rank 0 writes them; a file that cannot be written stops every process.
        collectively(context.communicator, [&]() {
          if (writer)
            write_sample_lines();
        });

        SceneView<dim> scene{mesh, parameters};
        scene.flow = &model;
        scene.time = stepper.time();
        run_postprocessors_on_writer(scene, context);
      }
    } // namespace



    template <int dim>
    void
    run_two_phase_flow_scene(const PhysicsParameters         &parameters,
                             const geometry::CutMesh<dim>    &mesh,
                             io::RunContext                  &context,
                             const std::vector<unsigned int> &cell_owner)
    {
      FlowRun<dim> run(parameters, mesh, context, cell_owner);
      run_time_loop(
        run.stepper,
        "Flow",
        [&]() { run.start(); },
        [&](const double dt) { return run.attempt(dt); },
        [&]() { run.accept(); },
        [&](const bool restore_first) { run.write_accepted_state(restore_first); },
        context.progress,
        context.communicator,
        [&]() { run.summarize_totals(); });
      run.finish(parameters);
    }

    template void
    run_two_phase_flow_scene(const PhysicsParameters &,
                             const geometry::CutMesh<2> &,
                             io::RunContext &,
                             const std::vector<unsigned int> &);
    template void
    run_two_phase_flow_scene(const PhysicsParameters &,
                             const geometry::CutMesh<3> &,
                             io::RunContext &,
                             const std::vector<unsigned int> &);
  } // namespace app
} // namespace porofrac
