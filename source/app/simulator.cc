// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <porofrac/app/contact_mechanics_scene.h>
#include <porofrac/app/mesh_report.h>
#include <porofrac/app/poromechanics_scene.h>
#include <porofrac/app/simulator.h>
#include <porofrac/app/two_phase_flow_scene.h>
#include <porofrac/base/blas_info.h>
#include <porofrac/base/config.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/mpi_tools.h>
#include <porofrac/geometry/distributed_cut_mesh.h>
#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/mesh_output.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/io/output_directory.h>
#include <porofrac/io/output_parameters.h>
#include <porofrac/io/run_context.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>

namespace porofrac
{
  namespace app
  {
    namespace
    {
      /// Whether the scene runs the distributed code on all processes: contact mechanics,
      /// two-phase flow and poromechanics. 'mesh only' runs on rank 0 while the other processes
      /// wait.
      bool
      distributed_scene(dealii::ParameterHandler &prm, const std::string &physics)
      {
        const unsigned int n = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
        return physics != "mesh only" && (n > 1 || prm.get("Distributed") == "always");
      }

      /// Takes the output directory on rank 0 of @p communicator (doc: io::OutputDirectory); the
      /// other processes wait until it exists. A run that resumes in the directory of its
      /// checkpoint keeps the files written so far.
      std::unique_ptr<io::OutputDirectory>
      take_output_directory(const std::string &output_directory,
                            const std::string &restart_directory,
                            const MPI_Comm     communicator)
      {
        std::error_code ec;
        const bool      resume_in_place =
          !restart_directory.empty() &&
          std::filesystem::equivalent(restart_directory, output_directory, ec);
        std::unique_ptr<io::OutputDirectory> lock;
        collectively(communicator, [&]() {
          if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
            lock = std::make_unique<io::OutputDirectory>(output_directory,
                                                         "Output/Directory (or --output-dir)",
                                                         resume_in_place);
        });
        return lock;
      }

      /// summary.json with the status, the wall time and the peak memory: by rank 0 with the
      /// peak of every process of the scene (collective), or, @p alone, by this process with its
      /// own peak and its rank (`failed_on_rank`), for a failure the processes cannot agree on
      /// (an allocation that failed on one of them; main() stops the others afterwards).
      void
      write_summary(const std::string &status,
                    const std::string &reason,
                    const double       wall_time,
                    io::RunContext    &context,
                    const bool         alone = false)
      {
        using namespace dealii;
        Utilities::System::MemoryStats memory;
        Utilities::System::get_memory_stats(memory);
        const double              own  = memory.VmHWM / 1024.;
        const unsigned int        rank = Utilities::MPI::this_mpi_process(context.communicator);
        const std::vector<double> peak =
          alone ? std::vector<double>{own} : Utilities::MPI::gather(context.communicator, own, 0);
        if (!alone && rank != 0)
          return;
        io::Json &summary = context.summary;
        summary["status"] = status;
        if (!reason.empty())
          summary["reason"] = reason;
        summary["wall_time_s"]    = wall_time;
        summary["peak_memory_mb"] = *std::max_element(peak.begin(), peak.end());
        if (alone)
          summary["failed_on_rank"] = rank;
        else
          summary["peak_memory_mb_per_rank"] = peak;
        summary.write_file(context.path("summary.json"));
        context.progress << "*** Wrote " << context.path("summary.json") << std::endl;
      }

      /// Reports the cut mesh (rank 0 of the scene's processes).
      template <int dim>
      void
      report_cut_mesh(const geometry::CutMesh<dim> &mesh, io::RunContext &context)
      {
        using namespace dealii;
        if (Utilities::MPI::this_mpi_process(context.communicator) != 0)
          return;
        report_mesh(mesh, context);
        context.summary["n_cells"]          = mesh.triangulation.n_active_cells();
        context.summary["n_fracture_faces"] = static_cast<unsigned int>(mesh.fracture_faces.size());
        context.summary["n_dofs_mechanics"] = 0;
        context.summary["n_unknowns_flow"]  = 0;
      }

      /// Writes the mesh files: whole on one process, else each process the cells of
      /// @p cell_owner that are its own (geometry::write_mesh). Collective.
      template <int dim>
      void
      write_mesh_files(const geometry::CutMesh<dim>    &mesh,
                       const std::vector<unsigned int> &cell_owner,
                       io::RunContext                  &context)
      {
        dealii::TimerOutput::Scope t(context.timer, "Output: mesh");
        const auto pieces = geometry::replicated_mesh_pieces(cell_owner, context.communicator);
        collectively(context.communicator, [&]() {
          geometry::write_mesh(mesh, context.path("mesh"), context.output_format, pieces);
        });
      }

      /// Axisymmetric scenes take the second coordinate as the radius r (Section 5.3): a domain
      /// that reaches r < 0 has no meaning there. Generated domains are checked before meshing.
      template <int dim, typename Points>
      void
      check_radius_non_negative(const Points &points, const std::string &parameter)
      {
        double r_min = std::numeric_limits<double>::max(), r_max = 0;
        for (const auto &v : points)
          {
            r_min = std::min(r_min, v[1]);
            r_max = std::max(r_max, std::abs(v[1]));
          }
        check_input(r_min >= -1e-12 * r_max,
                    parameter,
                    "the axisymmetric mode takes the second coordinate as the radius r, which "
                    "must not be negative, but the domain reaches r = " +
                      io::to_text(r_min) + " (move the domain to r >= 0)");
      }

      /// Where Mechanics/Multiplier stabilization is available (doc/algorithms.md §2.2): the
      /// serial Schur complement solver and the distributed solvers, in contact-mechanics runs.
      void
      check_multiplier_stabilization(const mechanics::ContactParameters &mechanics,
                                     const std::string                  &physics,
                                     const bool                          distributed)
      {
        if (mechanics.multiplier_stabilization == 0)
          return;
        const std::string parameter = "Mechanics/Multiplier stabilization";
        check_input(physics == "contact mechanics",
                    parameter,
                    "is available in contact-mechanics runs only, not in coupled runs (the "
                    "Coulomb conditions of a time step count the slip from the previous step's "
                    "true jumps)");
        check_input(distributed || mechanics.linear_solver == "schur complement",
                    parameter,
                    "needs Mechanics/Linear solver = schur complement on one process (the "
                    "full-system solver has no multiplier-multiplier coupling), or a distributed "
                    "run (Distributed = always)");
      }

      /// Builds and reports the cut mesh, then runs the physics the deck asks for.
      template <int dim>
      void
      build_and_run(dealii::ParameterHandler    &prm,
                    const std::filesystem::path &deck,
                    const std::string           &physics,
                    io::RunContext              &context)
      {
        using namespace dealii;
        geometry::GeometryParameters geometry_parameters;
        geometry_parameters.parse_parameters(prm, deck.parent_path().string());
        geometry_parameters.resolve_delaunay_flips(physics, dim);
        // Every physics parameter set the scene uses is parsed (and validated) once, here,
        // before the mesh is made.
        PhysicsParameters physics_parameters;
        if (physics == "contact mechanics" || physics == "poromechanics")
          physics_parameters.mechanics.parse_parameters(prm, dim);
        if (physics == "two-phase flow" || physics == "poromechanics")
          physics_parameters.flow.parse_parameters(prm);
        if (physics == "poromechanics")
          {
            physics_parameters.coupling.parse_parameters(prm);
            check_input(physics_parameters.flow.permeability_expression.empty(),
                        "Flow/Matrix/Permeability expression",
                        "is for two-phase flow scenes; poromechanics starts its Kozeny-Carman "
                        "law from the uniform Flow/Matrix/Permeability");
            check_input(physics_parameters.flow.sample_lines.empty(),
                        "Flow/Sample lines",
                        "are written by two-phase flow scenes only");
          }
        check_multiplier_stabilization(physics_parameters.mechanics,
                                       physics,
                                       context.communicator != MPI_COMM_SELF);
        const std::string axisymmetric =
          (physics_parameters.mechanics.axisymmetric && physics != "two-phase flow") ?
            "Mechanics/Axisymmetric" :
          (physics_parameters.flow.axisymmetric && physics != "contact mechanics") ?
            "Flow/Axisymmetric" :
            "";
        if constexpr (dim == 2)
          if (!axisymmetric.empty() && geometry_parameters.domain != "mesh file")
            check_radius_non_negative<dim>(
              geometry::network_from_parameters(geometry_parameters).domain.corners, axisymmetric);
        context.progress << "*** Building the cut mesh" << std::endl;
        // Every process of a distributed scene builds the same serial cut mesh
        // (doc/parallel.md).
        std::unique_ptr<geometry::CutMesh<dim>> mesh;
        {
          TimerOutput::Scope t(context.timer, "Geometry: mesh generation and cut");
          mesh = geometry::make_cut_mesh<dim>(geometry_parameters);
        }
        if (!axisymmetric.empty())
          check_radius_non_negative<dim>(mesh->triangulation.get_vertices(), axisymmetric);
        collectively(context.communicator, [&]() { report_cut_mesh(*mesh, context); });

        if (physics == "contact mechanics" && context.communicator != MPI_COMM_SELF)
          {
            std::unique_ptr<geometry::DistributedCutMesh<dim>> distributed;
            {
              TimerOutput::Scope t(context.timer, "Geometry: partition and distribution");
              distributed =
                std::make_unique<geometry::DistributedCutMesh<dim>>(*mesh, context.communicator);
            }
            write_mesh_files(*mesh, distributed->cell_owners(), context);
            run_contact_mechanics_scene(physics_parameters, *distributed, context);
          }
        else if (physics == "contact mechanics")
          {
            write_mesh_files(*mesh, {}, context);
            run_contact_mechanics_scene(physics_parameters, *mesh, context);
          }
        else if (physics == "two-phase flow" || physics == "poromechanics")
          {
            std::vector<unsigned int>                          cell_owner;
            std::unique_ptr<geometry::DistributedCutMesh<dim>> distributed;
            if (context.communicator != MPI_COMM_SELF)
              {
                TimerOutput::Scope t(context.timer, "Geometry: partition and distribution");
                if (physics == "poromechanics" && physics_parameters.coupling.distributed_contact)
                  {
                    distributed =
                      std::make_unique<geometry::DistributedCutMesh<dim>>(*mesh,
                                                                          context.communicator);
                    cell_owner = distributed->cell_owners();
                  }
                else
                  cell_owner = geometry::partition_cells(*mesh, context.communicator);
              }
            write_mesh_files(*mesh, cell_owner, context);
            if (physics == "two-phase flow")
              run_two_phase_flow_scene(physics_parameters, *mesh, context, cell_owner);
            else
              run_poromechanics_scene(
                physics_parameters, *mesh, context, cell_owner, distributed.get());
          }
        else // mesh only
          write_mesh_files(*mesh, {}, context);
      }
    } // namespace



    template <int dim>
    void
    run_scene(dealii::ParameterHandler &prm,
              const std::string        &deck_path,
              const std::string        &output_directory,
              std::ostream             &report,
              const io::RunOptions     &options)
    {
      using namespace dealii;
      Timer                       wall_clock;
      const std::filesystem::path deck(deck_path);
      const std::string           physics = prm.get("Physics");
      std::string                 scene   = prm.get("Scene name");
      if (scene.empty())
        scene = deck.stem().string();

      io::OutputParameters output;
      output.parse_parameters(prm);
      const std::string format       = output.format;
      const std::string verbosity    = output.verbosity;
      const bool        print_timers = output.timer_summary && verbosity != "quiet";

      const bool time_dependent = physics == "two-phase flow" || physics == "poromechanics";
      check_input(time_dependent || options.restart_directory.empty(),
                  "--restart",
                  "only time-dependent scenes (two-phase flow, poromechanics) can be resumed");
      check_input(time_dependent ||
                    (options.checkpoint_every_steps == 0 && options.checkpoint_every_seconds == 0),
                  "--checkpoint-every",
                  "only time-dependent scenes (two-phase flow, poromechanics) write checkpoints");
      // A scene that is not distributed runs on rank 0; the other processes wait in main().
      const MPI_Comm communicator =
        distributed_scene(prm, physics) ? MPI_COMM_WORLD : MPI_COMM_SELF;
      const bool rank_0 = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      if (!rank_0 && communicator == MPI_COMM_SELF)
        return;
      const auto directory_lock =
        take_output_directory(output_directory, options.restart_directory, communicator);

      ConditionalOStream progress(std::cout, verbosity != "quiet" && rank_0);
      ConditionalOStream verbose(std::cout, verbosity == "verbose" && rank_0);
      TimerOutput        timer(progress, TimerOutput::never, TimerOutput::wall_times);
      io::Json           summary  = io::Json::object();
      summary["scene"]            = scene;
      summary["physics"]          = physics;
      summary["dim"]              = dim;
      summary["porofrac_version"] = version;
      summary["blas"]             = blas_description();
      summary["n_mpi_ranks"]      = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      summary["distributed"]      = communicator != MPI_COMM_SELF;
      io::RunContext context{deck.filename().string(),
                             output_directory,
                             report,
                             progress,
                             verbose,
                             timer,
                             summary,
                             format,
                             options,
                             communicator};

      // summary.json is written whatever happens after this point: a failed or interrupted
      // run says so (status and reason) next to the last accepted state its scene wrote.
      const auto finish = [&](const std::string &status, const std::string &reason) {
        write_summary(status, reason, wall_clock.wall_time(), context);
      };
      try
        {
          reserve_blas_workspace();
          build_and_run<dim>(prm, deck, physics, context);
        }
      catch (const SolverFailure &e)
        {
          finish("failed", e.what());
          throw;
        }
      catch (const InputError &e)
        {
          // Input found bad once the scene has started (a parameter checked against the mesh,
          // an output file that cannot be written): the run stops with this error, and
          // summary.json says why where it can still be written.
          try
            {
              finish("failed", e.what());
            }
          catch (const InputError &)
            {
            }
          throw;
        }
      catch (const Interrupted &e)
        {
          finish("interrupted", e.what());
          throw;
        }
      catch (const std::bad_alloc &)
        {
          // The memory of the failed stage is freed by now. On one process the run stops as
          // for any lack of memory; with several, this one cannot join the others' collective
          // calls, so it reports alone and main() stops them all.
          const std::string reason =
            std::string(out_of_memory_reason) +
            (Utilities::MPI::n_mpi_processes(communicator) > 1 ?
               " on process " + std::to_string(Utilities::MPI::this_mpi_process(communicator)) +
                 " of " + std::to_string(Utilities::MPI::n_mpi_processes(communicator)) :
               std::string());
          try
            {
              if (Utilities::MPI::n_mpi_processes(communicator) > 1)
                write_summary("failed", reason, wall_clock.wall_time(), context, true);
              else
                finish("failed", reason);
            }
          catch (const std::exception &)
            {
              // Not even summary.json could be written; the message still says why.
            }
          if (Utilities::MPI::n_mpi_processes(communicator) > 1)
            throw;
          throw InsufficientMemory(reason);
        }
      finish("converged", "");
      if (print_timers)
        timer.print_summary();
    }



    template void
    run_scene<2>(dealii::ParameterHandler &,
                 const std::string &,
                 const std::string &,
                 std::ostream &,
                 const io::RunOptions &);
    template void
    run_scene<3>(dealii::ParameterHandler &,
                 const std::string &,
                 const std::string &,
                 std::ostream &,
                 const io::RunOptions &);
  } // namespace app
} // namespace porofrac
