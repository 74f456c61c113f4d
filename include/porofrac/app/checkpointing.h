// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_CHECKPOINTING_H
#define POROFRAC_APP_CHECKPOINTING_H

#include <deal.II/base/timer.h>

#include <porofrac/base/time_stepper.h>
#include <porofrac/io/checkpoint.h>
#include <porofrac/io/pvd_writer.h>
#include <porofrac/io/run_context.h>

#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace porofrac
{
  namespace app
  {
    /**
     * Checkpoints of a time-dependent scene (`--checkpoint-every`, `--restart`). The scene keeps
     * its text files (history.csv, fractures.csv) here, so that a checkpoint can carry what they
     * held at that step and a resumed run rewrites them exactly; it registers its own state with
     * save() and load() callbacks. The checkpoint is `checkpoint.bin` in the output directory.
     */
    class Checkpointing
    {
    public:
      using Save = std::function<void(io::CheckpointWriter &)>;
      using Load = std::function<void(io::CheckpointReader &)>;

      Checkpointing(io::RunContext                 &context,
                    const std::string              &scene_kind,
                    AdaptiveTimeStepper            &stepper,
                    io::PvdWriter                  &pvd,
                    const std::vector<std::string> &text_files);

      /// Whether the run resumes from a checkpoint.
      bool
      restarting() const
      {
        return !context.options.restart_directory.empty();
      }

      /// The text file @p name, open for appending. Without restart it is created with
      /// @p header; on restart it holds what it held at the checkpoint.
      std::ofstream &
      text_file(const std::string &name, const std::string &header);

      /// On restart: reads the checkpoint (stepper, field series, text files, then @p load).
      void
      restore(const Load &load);

      /// After an accepted step: writes a checkpoint if one is due (steps or wall time).
      void
      after_step(const Save &save);

      /// Writes a checkpoint of the accepted state now (a run stopped by a signal).
      void
      write(const Save &save);

    private:
      io::RunContext                             &context;
      const std::string                           scene_kind;
      AdaptiveTimeStepper                        &stepper;
      io::PvdWriter                              &pvd;
      std::vector<std::string>                    names;
      std::vector<std::unique_ptr<std::ofstream>> files;
      std::vector<std::string>                    restored_text;
      dealii::Timer                               clock;
    };
  } // namespace app
} // namespace porofrac

#endif
