// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <porofrac/app/checkpointing.h>
#include <porofrac/app/linear_solve_report.h>
#include <porofrac/app/poromechanics_scene.h>
#include <porofrac/app/time_loop.h>
#include <porofrac/base/mpi_tools.h>
#include <porofrac/coupling/energy_estimate.h>
#include <porofrac/flow/flow_output.h>
#include <porofrac/io/pvd_writer.h>
#include <porofrac/mechanics/contact_output.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      void
      report_states(std::ostream                         &out,
                    const mechanics::ContactProblem<dim> &problem,
                    const std::string                    &when)
      {
        for (const unsigned int id : problem.get_mesh().fracture_ids)
          {
            const auto c = mechanics::count_states(problem, id);
            out << "Coupling: " << when << ", fracture " << id << ": open " << c[0] << ", stick "
                << c[1] << ", slip " << c[2] << std::endl;
          }
      }

      /**
       * The cell, fracture and displacement files of the current coupled state: every process
       * writes its cells of the cell and displacement files (@p pieces), rank 0 the fracture
       * file. Returns the cell file a .pvd lists.
       */
      template <int dim>
      std::string
      write_fields(const coupling::Poromechanics<dim> &pm,
                   const std::string                  &basename,
                   const std::string                  &format,
                   const geometry::OutputPieces       &pieces)
      {
        const auto          &grid  = *pm.flow.grid;
        const auto          &mesh  = pm.mechanics.get_mesh();
        const unsigned int   n     = grid.n_matrix_cells;
        geometry::CellFields cells = flow::matrix_fields(*pm.flow.solver, grid);
        Vector<double>       p_E(n), porosity(n);
        for (unsigned int K = 0; K < n; ++K)
          {
            p_E[K]      = pm.equivalent_pressure()[K];
            porosity[K] = grid.porosity[K];
          }
        cells.emplace_back("p_E", p_E);
        cells.emplace_back("porosity", porosity);
        const std::string file = geometry::write_cell_fields(mesh, basename, format, cells, pieces);
        mechanics::write_displacement(pm.mechanics, basename + "_displacement", format, pieces);

        if (grid.n_fracture_cells > 0 && pieces.rank == 0)
          {
            geometry::FractureFields faces = flow::fracture_fields(*pm.flow.solver, grid);
            faces.emplace_back("p_E", std::vector<double>());
            for (unsigned int f = 0; f < grid.n_fracture_cells; ++f)
              faces.back().second.push_back(pm.equivalent_pressure()[n + f]);
            mechanics::append_contact_fields(pm.mechanics, faces);
            geometry::write_fracture_cells(mesh, basename + "_fractures." + format, format, faces);
          }
        return file;
      }

      /// Iteration counts summed over a run (every attempt, failed ones included).
      struct RunTotals
      {
        unsigned int flow = 0, mechanics = 0, coupling = 0, maps = 0, gmres = 0;
        unsigned int coupling_max_per_step = 0, cuts = 0;
        double       mass_error_max = 0;

        void
        save(io::CheckpointWriter &w) const
        {
          w.put("iterations",
                std::vector<double>{double(flow),
                                    double(mechanics),
                                    double(coupling),
                                    double(maps),
                                    double(gmres),
                                    double(coupling_max_per_step),
                                    double(cuts),
                                    mass_error_max});
        }

        void
        load(io::CheckpointReader &r)
        {
          std::vector<double> v;
          r.get("iterations", v);
          check_input(v.size() == 8, "--restart", "malformed checkpoint");
          flow                  = v[0];
          mechanics             = v[1];
          coupling              = v[2];
          maps                  = v[3];
          gmres                 = v[4];
          coupling_max_per_step = v[5];
          cuts                  = v[6];
          mass_error_max        = v[7];
        }
      };

      const char *history_header =
        "time,dt,mean_fracture_width,flow_newton_iterations,mechanics_iterations,"
        "coupling_iterations,time_step_cuts,mass_balance_error,map_evaluations,"
        "gmres_iterations,n_open,n_stick,n_slip,energy_capillary_matrix,"
        "energy_capillary_fracture,energy_elastic,energy_storage,flow_dissipation,"
        "friction_work,supplied_work,energy_inequality_violation\n";

      template <int dim>
      void
      write_history_row(std::ostream                       &history,
                        const AdaptiveTimeStepper          &stepper,
                        const coupling::Poromechanics<dim> &pm,
                        const coupling::CoupledStepReport  &r,
                        const coupling::StepEnergy         &e)
      {
        const auto c = mechanics::count_states(pm.mechanics);
        history << stepper.time() << ',' << stepper.last_step_size() << ','
                << pm.mean_fracture_width() << ',' << r.flow_newton_iterations << ','
                << r.mechanics_iterations << ',' << r.coupling_iterations << ','
                << stepper.last_step_cuts() << ',' << std::max(r.mass_defect[0], r.mass_defect[1])
                << ',' << r.map_evaluations << ',' << r.gmres_iterations << ',' << c[0] << ','
                << c[1] << ',' << c[2] << ',' << e.energy.capillary_matrix << ','
                << e.energy.capillary_fracture << ',' << e.energy.elastic << ',' << e.energy.storage
                << ',' << e.dissipation << ',' << e.friction_work << ',' << e.supplied_work << ','
                << e.violation << std::endl;
      }

      template <int dim>
      io::Json
      summarize_mechanics(const coupling::Poromechanics<dim> &pm,
                          const RunTotals                    &totals,
                          const unsigned int                  initial_iterations)
      {
        const auto &prm               = pm.mechanics.get_parameters();
        const auto  c                 = mechanics::count_states(pm.mechanics);
        io::Json    m                 = io::Json::object();
        m["solver"]                   = prm.method;
        m["c"]                        = prm.c;
        m["nonlinear_iterations"]     = totals.mechanics;
        m["initial_state_iterations"] = initial_iterations;
        // LU factorizations of the contact system (reused while no face row changes).
        const auto &linear = pm.contact_linear_totals();
        m["lu_factorizations"] =
          pm.distributed_contact() ? linear[0] : pm.mechanics.n_factorizations();
        if (pm.distributed_contact())
          {
            m["distributed"]                     = true;
            m["linear_solver"]                   = pm.contact_linear_solver();
            m["linear_iterations"]               = linear[1];
            m["linear_direct_fallbacks"]         = linear[2];
            m["linear_direct_workspace_retries"] = linear[3];
            m["linear_fallback_factorizations"]  = linear[4];
          }
        m["converged"] = true;
        m["n_open"]    = c[0];
        m["n_stick"]   = c[1];
        m["n_slip"]    = c[2];
        return m;
      }

      template <int dim>
      void
      report_run(const coupling::Poromechanics<dim>  &pm,
                 const AdaptiveTimeStepper           &stepper,
                 const RunTotals                     &totals,
                 const coupling::EnergyEstimate<dim> &energy,
                 std::ostream                        &report)
      {
        const coupling::EnergyTerms &stored = energy.last_stored_energy();
        // Plane strain: per metre of the out-of-plane direction.
        const char *joules =
          dim == 2 && !pm.mechanics.get_parameters().axisymmetric ? " J/m" : " J";
        report_states(report, pm.mechanics, "final time");
        report << "Coupling: " << stepper.step_number() << " time steps, " << totals.cuts
               << " time-step cuts, final time " << std::scientific << std::setprecision(4)
               << stepper.time() << " s" << std::endl
               << "Coupling: final mean fracture width " << pm.mean_fracture_width() << " m"
               << std::endl
               << "Coupling: final stored energy (19): elastic " << stored.elastic << joules
               << ", total " << stored.total() << joules << std::defaultfloat << std::endl
               << "Coupling: iterations: coupling " << totals.coupling << ", map evaluations "
               << totals.maps << ", flow Newton " << totals.flow << ", mechanics "
               << totals.mechanics << std::endl;
        const auto &linear = pm.contact_linear_totals();
        if (pm.distributed_contact() && linear[2] > 0)
          report << "Coupling: " << linear[2]
                 << " contact linear solves fell back from the Krylov solver to the direct solver ("
                 << linear[4] << " factorizations)" << std::endl;
        report << "Coupling: mass balance error per step below 1e-10: "
               << (totals.mass_error_max <= 1e-10 ? "yes" : "NO") << std::endl
               << "Coupling: energy inequality (19) holds at every step: "
               << (energy.max_violation() <= 1e-6 ? "yes" : "NO") << std::endl;
      }
    } // namespace



    namespace
    {
      /// The flow model of a coupled scene: the deck's flow with tight inner Newton tolerances
      /// (with @p distributed, without the serial Newton matrix: distribute() follows).
      template <int dim>
      flow::FlowModel<dim>
      make_inner_flow_model(const PhysicsParameters      &parameters,
                            const geometry::CutMesh<dim> &mesh,
                            const bool                    distributed)
      {
        const coupling::CouplingParameters &cp = parameters.coupling;
        // Inside coupled iterations the flow Newton must be converged tightly (see
        // CouplingParameters); the deck's tolerances are the upper bounds.
        return flow::make_flow_model<dim>(
          parameters.flow,
          mesh,
          [&](flow::NewtonParameters &n) {
            // At its noise floor (kinks of S and of the upwinding), accept an inner solve that
            // meets the flow deck's own tolerances instead of cutting the step.
            n.stagnation_update_tolerance = n.update_tolerance;
            n.stagnation_mass_tolerance   = 1e-10; // the per-step conservation target
            n.residual_tolerance = std::min(n.residual_tolerance, cp.inner_flow_residual_tolerance);
            n.update_tolerance   = std::min(n.update_tolerance, cp.inner_flow_update_tolerance);
          },
          distributed);
      }



      /**
       * One coupled run: the coupled problem, its time stepper, energy record, field series,
       * text files and checkpoints, and what run_time_loop() calls for each step.
       */
      template <int dim>
      class CoupledRun
      {
      public:
        CoupledRun(const PhysicsParameters                 &parameters,
                   const geometry::CutMesh<dim>            &mesh,
                   io::RunContext                          &context,
                   const std::vector<unsigned int>         &cell_owner,
                   const geometry::DistributedCutMesh<dim> *distributed_mesh);

        /// The state at t = 0 (or the restored one) written, the text files open.
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
        finish(const PhysicsParameters &parameters, const geometry::CutMesh<dim> &mesh);
        /// The run's totals in summary.json (steps, time, iterations, balances, face states),
        /// also for a run that failed or was interrupted.
        void
        summarize_totals();

        AdaptiveTimeStepper stepper;

      private:
        void
        output(const unsigned int step, const double time);
        /// The rows of fractures.csv at @p time: contact state, aperture and p_E per face.
        void
        write_fracture_rows(const double time);
        void
        save(io::CheckpointWriter &w) const;
        void
        load(io::CheckpointReader &r);
        /// The parameters the postprocessors see: with the distributed contact problem the
        /// serial copy has no K, so their linear elasticity solve is left to it.
        PhysicsParameters
        postprocessing_parameters(const PhysicsParameters &physics) const
        {
          return distributed_mech ? without_serial_linear_solve(physics) : physics;
        }

        io::RunContext                    &context;
        const coupling::CouplingParameters parameters;
        flow::FlowModel<dim>               flow;
        mechanics::ContactProblem<dim>     mech;
        /// The contact problem's solver in distributed-contact runs (the state is copied to mech).
        std::unique_ptr<mechanics::DistributedContactProblem<dim>> distributed_mech;
        coupling::Poromechanics<dim>                               pm;
        unsigned int                                               initial_mechanics_iterations = 0;
        std::unique_ptr<coupling::EnergyEstimate<dim>>             energy;
        coupling::CoupledStepReport                                step_report;
        RunTotals                                                  totals;
        io::PvdWriter                                              pvd;
        int last_written = -1; // field files' step
        /// Which cells of the field files this process writes.
        const geometry::OutputPieces pieces;
        Checkpointing                checkpoints;
        std::ofstream               *fractures = nullptr, *history = nullptr;
      };



      template <int dim>
      CoupledRun<dim>::CoupledRun(const PhysicsParameters                 &physics,
                                  const geometry::CutMesh<dim>            &mesh,
                                  io::RunContext                          &context,
                                  const std::vector<unsigned int>         &cell_owner,
                                  const geometry::DistributedCutMesh<dim> *distributed_mesh)
          : stepper(physics.flow.stepping.final_time,
                    physics.flow.stepping.initial_step,
                    physics.flow.stepping.maximum_step,
                    physics.flow.stepping.growth,
                    physics.flow.stepping.maximum_cuts,
                    physics.coupling.output_times)
          , context(context)
          , parameters(physics.coupling)
          , flow(make_inner_flow_model(physics, mesh, context.communicator != MPI_COMM_SELF))
          , mech(mesh, physics.mechanics, context.verbose, context.timer)
          , distributed_mech(
              distributed_mesh ?
                std::make_unique<mechanics::DistributedContactProblem<dim>>(*distributed_mesh,
                                                                            physics.mechanics,
                                                                            context.verbose,
                                                                            context.timer) :
                nullptr)
          , pm(mech,
               flow,
               parameters,
               context.verbose,
               context.timer,
               context.communicator,
               distributed_mech.get())
          , pvd(context.path("poromechanics.pvd"))
          , pieces(geometry::replicated_mesh_pieces(cell_owner, context.communicator))
          , checkpoints(context, "poromechanics", stepper, pvd, {"history.csv", "fractures.csv"})
      {
        // Distributed: the flow's Newton systems are shared, the contact problem is solved by
        // every process or distributed (coupling::Poromechanics).
        if (context.communicator != MPI_COMM_SELF)
          flow.solver->distribute(context.communicator, flow.grid->node_owners(cell_owner));
        context.progress << "*** Poromechanics: contact mechanics set-up" << std::endl;
        // With the distributed contact problem the serial one only holds its state: no K,
        // unless a postprocessor solves with it (Iteration table).
        const bool state_only = distributed_mech && !postprocessors_need_system_matrices<dim>(
                                                      postprocessing_parameters(physics));
        mech.setup(state_only ? mechanics::SystemAssembly::loads :
                                mechanics::SystemAssembly::matrices);
        if (distributed_mech)
          distributed_mech->setup();
        context.summary["n_dofs_mechanics"] = mech.n_dofs();
        context.summary["n_unknowns_flow"]  = flow.solver->n_unknowns();
        context.report << "Coupling: " << mech.n_dofs() << " mechanics dofs, "
                       << flow.solver->n_unknowns() << " flow unknowns, "
                       << flow.grid->n_matrix_cells << " matrix cells, "
                       << flow.grid->n_fracture_cells << " fracture cells" << std::endl;
        context.progress << "*** Poromechanics: initial state" << std::endl;
        pm.initialize();
        initial_mechanics_iterations = pm.contact_statistics().iterations;
        energy                       = std::make_unique<coupling::EnergyEstimate<dim>>(pm);
        report_states(context.report, mech, "t = 0");
        context.report << "Coupling: t = 0, mean fracture width " << std::scientific
                       << std::setprecision(4) << pm.mean_fracture_width() << " m"
                       << std::defaultfloat << std::endl;
      }



      template <int dim>
      void
      CoupledRun<dim>::start()
      {
        if (checkpoints.restarting())
          checkpoints.restore([this](io::CheckpointReader &r) { load(r); });
        else
          output(0, 0.);
        std::ostringstream header;
        mechanics::write_fracture_table_header(header, dim, true);
        fractures = &checkpoints.text_file("fractures.csv", header.str());
        if (!checkpoints.restarting())
          {
            write_fracture_rows(0.);
          }
        history = &checkpoints.text_file("history.csv", history_header);
        *history << std::setprecision(10);
      }



      template <int dim>
      StepOutcome
      CoupledRun<dim>::attempt(const double dt)
      {
        step_report = pm.solve_time_step(dt);
        totals.flow += step_report.flow_newton_iterations;
        totals.mechanics += step_report.mechanics_iterations;
        totals.maps += step_report.map_evaluations;
        totals.gmres += step_report.gmres_iterations;
        return {step_report.converged, step_report.failure};
      }



      template <int dim>
      void
      CoupledRun<dim>::accept()
      {
        const auto        &r    = step_report;
        const unsigned int step = stepper.step_number();
        const double       t    = stepper.time();
        totals.cuts += stepper.last_step_cuts();
        totals.coupling += r.coupling_iterations;
        totals.coupling_max_per_step =
          std::max(totals.coupling_max_per_step, r.coupling_iterations);
        totals.mass_error_max =
          std::max({totals.mass_error_max, r.mass_defect[0], r.mass_defect[1]});
        // (19) compares the new state with the accepted one: record before accepting.
        const coupling::StepEnergy e = energy->record_step();
        pm.accept_time_step();
        write_history_row(*history, stepper, pm, r, e);
        const auto c = mechanics::count_states(mech);
        context.progress << "  Step " << step << ": t = " << t / 3.15576e7
                         << " y, dt = " << stepper.last_step_size() << " s, "
                         << r.coupling_iterations << " coupling, " << r.flow_newton_iterations
                         << " flow, " << r.mechanics_iterations
                         << " mechanics iterations; mean width " << pm.mean_fracture_width()
                         << " m; open/stick/slip " << c[0] << '/' << c[1] << '/' << c[2]
                         << std::endl;
        const bool table = stepper.at_output_time() || stepper.finished();
        if (table)
          write_fracture_rows(t);
        const unsigned int every = flow.stepping.output_every;
        if ((every > 0 && step % every == 0) || table)
          output(step, t);
        checkpoints.after_step([this](io::CheckpointWriter &w) { save(w); });
      }



      template <int dim>
      void
      CoupledRun<dim>::write_accepted_state(const bool restore_first)
      {
        if (restore_first)
          pm.restore_accepted_state();
        if (last_written != int(stepper.step_number()))
          output(stepper.step_number(), stepper.time());
        if (!restore_first)
          checkpoints.write([this](io::CheckpointWriter &w) { save(w); });
      }



      template <int dim>
      void
      CoupledRun<dim>::output(const unsigned int step, const double time)
      {
        if (context.output_format == "none")
          return;
        TimerOutput::Scope timer(context.timer, "Coupling: output");
        const std::string  name = "poromechanics-" + Utilities::int_to_string(step, 5);
        std::string        file;
        collectively(context.communicator, [&]() {
          file = write_fields(pm, context.path(name), context.output_format, pieces);
        });
        // Listed once every piece is written.
        collectively(context.communicator, [&]() {
          if (context.writes_files())
            pvd.add(time, file);
        });
        last_written = step;
      }



      template <int dim>
      void
      CoupledRun<dim>::write_fracture_rows(const double time)
      {
        const mechanics::CoupledFaceColumns columns{
          flow.grid->aperture, pm.equivalent_pressure().data() + flow.grid->n_matrix_cells, time};
        mechanics::write_fracture_table_rows(*fractures, mech, &columns);
      }



      template <int dim>
      void
      CoupledRun<dim>::save(io::CheckpointWriter &w) const
      {
        pm.save(w);
        energy->save(w);
        totals.save(w);
        flow::save_linear_statistics(w, pm.flow.solver->linear_statistics());
        w.put("last written step", static_cast<unsigned int>(last_written + 1));
      }



      template <int dim>
      void
      CoupledRun<dim>::load(io::CheckpointReader &r)
      {
        pm.load(r);
        energy->load(r);
        totals.load(r);
        pm.flow.solver->restore_linear_statistics(flow::load_linear_statistics(r));
        unsigned int written = 0;
        r.get("last written step", written);
        last_written = int(written) - 1;
      }



      template <int dim>
      void
      CoupledRun<dim>::finish(const PhysicsParameters &physics, const geometry::CutMesh<dim> &mesh)
      {
        report_run(pm, stepper, totals, *energy, context.report);
        summarize_totals();
        flow::report_linear_solver(pm.flow.solver->linear_solver_name(),
                                   pm.flow.solver->linear_statistics(),
                                   context.report);
        // A distributed contact problem times its own linear solve; the serial copy has no K.
        if (distributed_mech && physics.mechanics.reports.linear_solve_time)
          report_linear_elasticity_solve(*distributed_mech, context);
        const PhysicsParameters postprocessing = postprocessing_parameters(physics);
        SceneView<dim>          scene{mesh, postprocessing};
        scene.mechanics     = &mech;
        scene.flow          = &flow;
        scene.poromechanics = &pm;
        scene.time          = stepper.time();
        run_postprocessors_on_writer(scene, context);
      }



      template <int dim>
      void
      CoupledRun<dim>::summarize_totals()
      {
        auto &summary        = context.summary;
        summary["mechanics"] = summarize_mechanics(pm, totals, initial_mechanics_iterations);
        io::Json cpl         = io::Json::object();
        cpl["fixed_point"]   = std::string(
          parameters.variable == coupling::CouplingVariable::displacement ? "displacement" :
                                                                            "equivalent pressure");
        cpl["method"]                     = parameters.fixed_point.method;
        cpl["iterations"]                 = totals.coupling;
        cpl["iterations_max_per_step"]    = totals.coupling_max_per_step;
        cpl["map_evaluations"]            = totals.maps;
        cpl["gmres_iterations"]           = totals.gmres;
        summary["coupling"]               = cpl;
        summary["n_time_steps"]           = stepper.step_number();
        summary["final_time"]             = stepper.time();
        summary["time_step_cuts"]         = totals.cuts;
        summary["flow_newton_iterations"] = totals.flow;
        summary["flow_linear_solver"] =
          flow::linear_solver_summary(pm.flow.solver->linear_solver_name(),
                                      pm.flow.solver->linear_statistics());
        summary["mass_balance_error_max"]          = totals.mass_error_max;
        summary["energy_inequality_violation_max"] = energy->max_violation();
        const coupling::EnergyTerms &stored        = energy->last_stored_energy();
        summary["final_elastic_energy"]            = stored.elastic;
        summary["final_stored_energy"]             = stored.total();
        summary["mean_fracture_width"]             = pm.mean_fracture_width();
      }
    } // namespace



    template <int dim>
    void
    run_poromechanics_scene(const PhysicsParameters                 &parameters,
                            const geometry::CutMesh<dim>            &mesh,
                            io::RunContext                          &context,
                            const std::vector<unsigned int>         &cell_owner,
                            const geometry::DistributedCutMesh<dim> *distributed_mesh)
    {
      CoupledRun<dim> run(parameters, mesh, context, cell_owner, distributed_mesh);
      run_time_loop(
        run.stepper,
        "Coupling",
        [&]() { run.start(); },
        [&](const double dt) { return run.attempt(dt); },
        [&]() { run.accept(); },
        [&](const bool restore_first) { run.write_accepted_state(restore_first); },
        context.progress,
        context.communicator,
        [&]() { run.summarize_totals(); });
      run.finish(parameters, mesh);
    }

    template void
    run_poromechanics_scene(const PhysicsParameters &,
                            const geometry::CutMesh<2> &,
                            io::RunContext &,
                            const std::vector<unsigned int> &,
                            const geometry::DistributedCutMesh<2> *);
    template void
    run_poromechanics_scene(const PhysicsParameters &,
                            const geometry::CutMesh<3> &,
                            io::RunContext &,
                            const std::vector<unsigned int> &,
                            const geometry::DistributedCutMesh<3> *);
  } // namespace app
} // namespace porofrac
