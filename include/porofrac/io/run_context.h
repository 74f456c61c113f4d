// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_RUN_CONTEXT_H
#define POROFRAC_IO_RUN_CONTEXT_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <porofrac/io/json.h>

#include <ostream>
#include <string>

namespace porofrac
{
  namespace io
  {
    using namespace dealii;

    /// Command-line options of a run that are not deck parameters.
    struct RunOptions
    {
      /// Write a checkpoint after every this many accepted steps (0: never) ...
      unsigned int checkpoint_every_steps = 0;
      /// ... or when this much wall time (s) has passed since the last one (0: never).
      double checkpoint_every_seconds = 0;
      /// Resume from the checkpoint in this directory (empty: start at t = 0).
      std::string restart_directory;
    };

    /**
     * What a scene needs from the application around it: where to write, where to talk, where to
     * time, and the summary.json being built.
     *
     * - `report` always prints: results that tests compare (fixed formats: integers, or
     *   std::scientific with 3-4 digits; never timings, paths or Krylov iteration counts).
     * - `progress` prints at verbosity normal or verbose: per-step and per-iteration progress.
     * - `verbose` prints at verbosity verbose only.
     */
    struct RunContext
    {
      std::string         deck_name;
      std::string         output_directory;
      std::ostream       &report;
      ConditionalOStream &progress;
      ConditionalOStream &verbose;
      TimerOutput        &timer;
      Json               &summary;
      /// "vtu", "vtk" or "none" (Output/Format).
      std::string output_format;
      RunOptions  options;
      /// The processes that run the scene together: MPI_COMM_SELF unless the scene is
      /// distributed (then `report`, `progress` and the files of the run are rank 0's).
      MPI_Comm communicator = MPI_COMM_SELF;

      /// Whether this process writes the run's files (rank 0 of the communicator).
      bool
      writes_files() const
      {
        return Utilities::MPI::this_mpi_process(communicator) == 0;
      }

      /// output_directory + "/" + @p file.
      std::string
      path(const std::string &file) const
      {
        return output_directory + "/" + file;
      }
    };
  } // namespace io
} // namespace porofrac

#endif
