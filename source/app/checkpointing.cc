// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/checkpointing.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/mpi_tools.h>

#include <algorithm>
#include <sstream>

namespace porofrac
{
  namespace app
  {
    namespace
    {
      const std::string checkpoint_name = "checkpoint.bin";

      void
      put_stepper(io::CheckpointWriter &w, const AdaptiveTimeStepper::State &s)
      {
        w.put("time", s.t);
        w.put("regular step", s.regular);
        w.put("attempted step", s.attempt);
        w.put("last step", s.last_step);
        w.put("next output time", s.next_output);
        w.put("steps", s.n_steps);
        w.put("cuts", s.n_cuts);
        w.put("last step cuts", s.last_cuts);
        w.put("landed on output", static_cast<unsigned int>(s.landed_on_output));
        w.put("attempt lands", static_cast<unsigned int>(s.attempt_lands));
      }

      AdaptiveTimeStepper::State
      get_stepper(io::CheckpointReader &r)
      {
        AdaptiveTimeStepper::State s;
        unsigned int               landed = 0, lands = 0;
        r.get("time", s.t);
        r.get("regular step", s.regular);
        r.get("attempted step", s.attempt);
        r.get("last step", s.last_step);
        r.get("next output time", s.next_output);
        r.get("steps", s.n_steps);
        r.get("cuts", s.n_cuts);
        r.get("last step cuts", s.last_cuts);
        r.get("landed on output", landed);
        r.get("attempt lands", lands);
        s.landed_on_output = landed;
        s.attempt_lands    = lands;
        return s;
      }
    } // namespace



    Checkpointing::Checkpointing(io::RunContext                 &context,
                                 const std::string              &scene_kind,
                                 AdaptiveTimeStepper            &stepper,
                                 io::PvdWriter                  &pvd,
                                 const std::vector<std::string> &text_files)
        : context(context)
        , scene_kind(scene_kind)
        , stepper(stepper)
        , pvd(pvd)
        , names(text_files)
        , files(text_files.size())
        , restored_text(text_files.size())
    {
    }



    std::ofstream &
    Checkpointing::text_file(const std::string &name, const std::string &header)
    {
      const std::size_t i = std::find(names.begin(), names.end(), name) - names.begin();
      Assert(i < names.size(), dealii::ExcInternalError());
      // Only rank 0 of a distributed run writes; the other processes write into a closed
      // stream, which discards the text.
      files[i] = std::make_unique<std::ofstream>();
      if (!context.writes_files())
        return *files[i];
      files[i]->open(context.path(name));
      check_input(bool(*files[i]), "Output/Directory", "cannot write '" + context.path(name) + "'");
      *files[i] << (restarting() ? restored_text[i] : header);
      files[i]->flush();
      return *files[i];
    }



    void
    Checkpointing::restore(const Load &load)
    {
      io::CheckpointReader r(context.options.restart_directory + "/" + checkpoint_name);
      r.expect("scene kind", scene_kind);
      stepper.restore(get_stepper(r));
      std::vector<std::pair<double, std::string>> entries;
      r.get("field files", entries);
      pvd.set_entries(entries);
      for (unsigned int i = 0; i < names.size(); ++i)
        r.get(names[i], restored_text[i]);
      load(r);
      context.progress << "*** Resumed from " << context.options.restart_directory << "/"
                       << checkpoint_name << " at step " << stepper.step_number()
                       << ", t = " << stepper.time() << " s" << std::endl;
    }



    void
    Checkpointing::after_step(const Save &save)
    {
      // A text file that stopped taking rows (a full disk) stops the run like any output that
      // cannot be written: rank 0 writes the rows, every process stops.
      collectively(context.communicator, [&]() {
        if (context.writes_files())
          for (unsigned int i = 0; i < names.size(); ++i)
            check_input(bool(*files[i]),
                        "Output/Directory",
                        "cannot write '" + context.path(names[i]) + "'");
      });
      const auto &o = context.options;
      const bool  due_here =
        (o.checkpoint_every_steps > 0 && stepper.step_number() % o.checkpoint_every_steps == 0) ||
        (o.checkpoint_every_seconds > 0 && clock.wall_time() >= o.checkpoint_every_seconds);
      // The processes' clocks differ: all take part when the checkpoint is due on any of them.
      const bool due = dealii::Utilities::MPI::max(int(due_here), context.communicator) > 0;
      if (due && !stepper.finished())
        write(save);
    }



    void
    Checkpointing::write(const Save &save)
    {
      dealii::TimerOutput::Scope t(context.timer, "Output: checkpoints");
      // Rank 0 writes; a checkpoint that cannot be written stops every process.
      collectively(context.communicator, [&]() {
        if (!context.writes_files())
          return;
        io::CheckpointWriter w;
        w.put("scene kind", scene_kind);
        put_stepper(w, stepper.state());
        w.put("field files", pvd.get_entries());
        for (unsigned int i = 0; i < names.size(); ++i)
          {
            files[i]->flush();
            std::ifstream      in(context.path(names[i]));
            std::ostringstream text;
            text << in.rdbuf();
            w.put(names[i], text.str());
          }
        save(w);
        w.write(context.path(checkpoint_name));
      });
      clock.restart();
    }
  } // namespace app
} // namespace porofrac
