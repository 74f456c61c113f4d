// SPDX-License-Identifier: LGPL-2.1-or-later
// Checkpoints and restart: a flow run (the short fractured-square drainage) and a coupled run
// (energy_drainage.prm) each write a checkpoint every 4 accepted steps; a copy of the output
// directory is then resumed from its last checkpoint. Checked: the resumed run ends with the
// same history.csv, fractures.csv and flow/poromechanics.pvd, byte for byte, as the
// uninterrupted one, and the same summary totals. Then the coupled run gets a SIGINT while it
// prints step 5: it stops after that step with the Interrupted exception, "status":
// "interrupted", the totals of its 5 steps in summary.json and a checkpoint, from which a restart
// again ends as the uninterrupted run.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <porofrac/app/parameters.h>
#include <porofrac/app/simulator.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/interrupt.h>
#include <porofrac/io/deck.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "../file_text.h"

namespace fs = std::filesystem;

namespace
{
  std::string
  text(const fs::path &file)
  {
    return porofrac_tests::text_of(file.string());
  }

  /// summary.json without its timing and memory lines.
  std::string
  summary_without_timings(const fs::path &file)
  {
    std::stringstream in(text(file)), out;
    for (std::string line; std::getline(in, line);)
      if (line.find("wall_time") == std::string::npos &&
          line.find("memory_mb") == std::string::npos &&
          line.find("seconds") == std::string::npos && line.find("_s\"") == std::string::npos)
        out << line << '\n';
    return out.str();
  }

  /// Swallows the progress output and raises SIGINT when a line starts with @p trigger.
  class SignalAtLine : public std::streambuf
  {
  public:
    explicit SignalAtLine(const std::string &trigger)
        : trigger(trigger)
    {
    }

  protected:
    int
    overflow(int c) override
    {
      if (c == '\n')
        {
          if (line.rfind(trigger, 0) == 0)
            std::raise(SIGINT);
          line.clear();
        }
      else if (c != EOF)
        line += static_cast<char>(c);
      return c == EOF ? 0 : c;
    }

  private:
    const std::string trigger;
    std::string       line;
  };

  void
  run(const std::string              &deck_file,
      const std::string              &dir,
      const porofrac::io::RunOptions &o,
      const std::string              &verbosity = "quiet")
  {
    dealii::ParameterHandler prm;
    porofrac::app::declare_all_parameters(prm);
    porofrac::io::Deck deck(prm);
    const std::string  path = (fs::path(__FILE__).parent_path() / deck_file).string();
    deck.read(path);
    deck.set("Output/Verbosity=" + verbosity);
    deck.set("Output/Timer output=none");
    deck.set("Output/Format=vtu");
    std::ostringstream report;
    porofrac::app::run_scene<2>(prm, path, dir, report, o);
  }

  void
  check_resume(const std::string              &title,
               const std::string              &deck,
               const std::string              &series,
               const std::vector<std::string> &files)
  {
    porofrac::io::RunOptions every4;
    every4.checkpoint_every_steps = 4;
    const std::string full = "full-" + series, resumed = "resumed-" + series;
    fs::remove_all(full);
    fs::remove_all(resumed);
    run(deck, full, every4);
    fs::copy(full, resumed, fs::copy_options::recursive);
    porofrac::io::RunOptions restart;
    restart.restart_directory = resumed;
    run(deck, resumed, restart);
    std::cout << title << ":" << std::endl;
    for (const std::string &f : files)
      std::cout << "  " << f << " identical: "
                << (text(fs::path(full) / f) == text(fs::path(resumed) / f) ? "yes" : "NO")
                << std::endl;
    std::cout << "  summary.json totals identical: "
              << (summary_without_timings(fs::path(full) / "summary.json") ==
                      summary_without_timings(fs::path(resumed) / "summary.json") ?
                    "yes" :
                    "NO")
              << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  // run_scene is collective over MPI_COMM_WORLD (one process here).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_resume("two-phase flow",
               "../flow/fractured_square_drainage_short.prm",
               "flow",
               {"history.csv", "flow.pvd"});
  check_resume("poromechanics",
               "energy_drainage.prm",
               "coupled",
               {"history.csv", "fractures.csv", "poromechanics.pvd"});

  // SIGINT while step 5 is printed: the run must stop after step 5.
  porofrac::install_interrupt_handlers();
  SignalAtLine    trigger("  Step 5:");
  std::streambuf *original = std::cout.rdbuf(&trigger);
  fs::remove_all("interrupted");
  try
    {
      run("energy_drainage.prm", "interrupted", {}, "normal");
      std::cout.rdbuf(original);
      std::cout << "the run was not interrupted" << std::endl;
    }
  catch (const porofrac::Interrupted &e)
    {
      std::cout.rdbuf(original);
      std::cout << "Interrupted: " << std::string(e.what()).substr(0, 46) << std::endl;
    }
  std::cout << "summary status interrupted: "
            << (text("interrupted/summary.json").find("\"status\": \"interrupted\"") !=
                    std::string::npos ?
                  "yes" :
                  "no")
            << std::endl;
  // The totals of the 5 accepted steps are in it too.
  std::cout << "summary of the interrupted run has n_time_steps 5: "
            << (text("interrupted/summary.json").find("\"n_time_steps\": 5,") != std::string::npos ?
                  "yes" :
                  "no")
            << std::endl;
  porofrac::install_interrupt_handlers(); // forget the signal
  porofrac::io::RunOptions restart;
  restart.restart_directory = "interrupted";
  run("energy_drainage.prm", "interrupted", restart);
  for (const std::string f : {"history.csv", "fractures.csv", "poromechanics.pvd"})
    std::cout << "  after the restart, " << f << " identical: "
              << (text(fs::path("full-coupled") / f) == text(fs::path("interrupted") / f) ? "yes" :
                                                                                            "NO")
              << std::endl;
}
