// SPDX-License-Identifier: LGPL-2.1-or-later
// Output files that take no bytes (a full disk: each is a symbolic link to /dev/full, which
// opens but fails every write) stop the run with an InputError naming the file, and
// summary.json says so with the totals of the steps accepted until then. The short
// fractured-square drainage, once per file: history.csv (caught after the first accepted step),
// flow.pvd (at the first field file, t = 0: no time step), a sample line (at the end),
// poromechanics.pvd of a coupled drainage (t = 0), and fractures.csv of the six-fractures
// contact scene.
#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../file_text.h"
#include "../run_deck.h"

namespace
{
  /// The first capture of @p pattern in the file @p file, or "none".
  std::string
  capture(const std::string &file, const std::string &pattern)
  {
    const auto found = porofrac_tests::captures(porofrac_tests::text_of(file), pattern);
    return found.empty() ? "none" : found.front();
  }

  void
  run_on_full_disk(const std::string              &deck_file,
                   const std::string              &full,
                   const std::vector<std::string> &settings)
  {
    const std::string dir = "full-out";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::filesystem::create_symlink("/dev/full", dir + "/" + full);
    const std::string outcome =
      porofrac_tests::run_deck(porofrac_tests::deck_path(__FILE__, deck_file), settings, dir);
    const std::string summary = dir + "/summary.json";
    std::cout << full << " on a full disk: " << outcome << std::endl
              << full << " on a full disk: summary.json status "
              << capture(summary, "\"status\": *\"([^\"]*)\"") << ", reason "
              << capture(summary, "\"reason\": *\"([^\"]*)\"") << ", time steps "
              << capture(summary, "\"n_time_steps\": *([0-9]+)") << std::endl;
    std::filesystem::remove_all(dir);
  }
} // namespace

int
main(int argc, char **argv)
{
  // run_scene is collective over MPI_COMM_WORLD (one process here).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        drainage = "../flow/fractured_square_drainage_short.prm";
  run_on_full_disk(drainage, "history.csv", {});
  run_on_full_disk(drainage, "flow.pvd", {"Output/Format=vtu"});
  run_on_full_disk(drainage, "line_diagonal.csv", {"Flow/Sample lines=diagonal: (0, 0) (1, 1) 11"});
  run_on_full_disk("../coupling/energy_drainage.prm", "poromechanics.pvd", {"Output/Format=vtu"});
  run_on_full_disk("../mechanics/six_fractures_active_set.prm", "fractures.csv", {});
}
