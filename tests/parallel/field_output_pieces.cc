// SPDX-License-Identifier: LGPL-2.1-or-later
// Field files of distributed time-dependent runs (2 MPI processes): every process writes its own
// cells as a piece, rank 0 the .pvtu record, and the .pvd lists the records. Runs: the short
// fractured-square drainage (two-phase flow) and the first step of the drying cylinder with the
// distributed contact problem (poromechanics: cell fields and the P2 displacement). Checked for
// every file of the .pvd: a .pvtu naming two pieces that exist, each with cells, whose cells
// add up to the mesh's (summary.json n_cells), and the fields the record declares; the same for
// the mesh file (mesh.pvtu; mesh_fractures.vtu whole on rank 0). A file that cannot be written
// (a directory in its place: a piece rank 1 writes; a sample line, fractures.csv or a
// checkpoint rank 0 writes) stops both processes with the same InputError, the .pvd lists only
// the files written whole, and summary.json says why.
// mpi: 2
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
  using porofrac_tests::captures;
  using porofrac_tests::text_of;

  /// Checks one .pvtu record and its pieces; prints its fields once (@p print_fields).
  bool
  check_record(const std::string &dir,
               const std::string &record,
               const unsigned int n_cells,
               const bool         print_fields)
  {
    const std::string text   = text_of(dir + "/" + record);
    const auto        pieces = captures(text, "<Piece Source=\"([^\"]+)\"");
    unsigned int      sum = 0, empty = 0;
    for (const auto &piece : pieces)
      {
        const auto cells     = captures(text_of(dir + "/" + piece), "NumberOfCells=\"([0-9]+)\"");
        const unsigned int n = cells.empty() ? 0 : std::stoul(cells.front());
        sum += n;
        empty += (n == 0);
      }
    if (print_fields)
      {
        std::cout << "  fields of " << record << ":";
        for (const auto &name : captures(text, "<PDataArray[^>]*Name=\"([^\"]+)\""))
          std::cout << ' ' << name;
        std::cout << std::endl;
      }
    const bool ok = pieces.size() == 2 && empty == 0 && sum == n_cells;
    if (!ok)
      std::cout << "  " << record << ": " << pieces.size() << " pieces, " << empty
                << " without cells, " << sum << " cells of " << n_cells << std::endl;
    return ok;
  }

  void
  run_and_check(const std::string              &deck_file,
                const std::string              &dir,
                const std::string              &pvd,
                const std::vector<std::string> &settings)
  {
    std::vector<std::string> vtu = settings;
    vtu.push_back("Output/Format=vtu");
    const std::string outcome =
      porofrac_tests::run_deck(porofrac_tests::deck_path(__FILE__, deck_file), vtu, dir);
    if (outcome != "no error")
      std::cout << deck_file << ": " << outcome << std::endl;
    // The other process may still be closing its last piece.
    MPI_Barrier(MPI_COMM_WORLD);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const auto n_cells_text    = captures(text_of(dir + "/summary.json"), "\"n_cells\": *([0-9]+)");
    const unsigned int n_cells = n_cells_text.empty() ? 0 : std::stoul(n_cells_text.front());
    const auto         files   = captures(text_of(dir + "/" + pvd), "file=\"([^\"]+)\"");
    unsigned int       good = 0, displacement_good = 0, n_displacement = 0;
    for (unsigned int i = 0; i < files.size(); ++i)
      {
        good += files[i].size() > 5 && files[i].substr(files[i].size() - 5) == ".pvtu" &&
                check_record(dir, files[i], n_cells, i == 0);
        const std::string displacement =
          files[i].substr(0, files[i].size() - 5) + "_displacement.pvtu";
        if (std::filesystem::exists(dir + "/" + displacement))
          {
            ++n_displacement;
            displacement_good += check_record(dir, displacement, n_cells, i == 0);
          }
      }
    std::cout << deck_file << ": " << files.size() << " files in " << pvd << ", " << good
              << " records of two pieces with all " << n_cells << " cells";
    if (n_displacement > 0)
      std::cout << "; displacement: " << displacement_good << " of " << n_displacement;
    std::cout << "; mesh.pvtu: "
              << (check_record(dir, "mesh.pvtu", n_cells, false) ? "two pieces with all cells" :
                                                                   "wrong")
              << ", mesh.vtu " << (std::filesystem::exists(dir + "/mesh.vtu") ? "exists" : "absent")
              << ", mesh_fractures.vtu "
              << (std::filesystem::exists(dir + "/mesh_fractures.vtu") ? "exists" : "absent")
              << std::endl;
  }
} // namespace

namespace
{
  using porofrac_tests::captures;
  using porofrac_tests::text_of;

  /// @p deck_file run again with the file @p blocked of the output directory blocked by a
  /// directory of its name; prints each process's outcome and what the .pvd (if the run has
  /// one) and summary.json say.
  void
  run_blocked(const std::string              &deck_file,
              const std::string              &blocked,
              const std::vector<std::string> &settings,
              const std::string              &pvd     = "",
              const porofrac::io::RunOptions &options = {})
  {
    const std::string dir  = "blocked-out";
    const unsigned    rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    if (rank == 0)
      {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir + "/" + blocked);
      }
    MPI_Barrier(MPI_COMM_WORLD);
    const std::string outcome = porofrac_tests::run_deck(
      porofrac_tests::deck_path(__FILE__, deck_file), settings, dir, options);
    const auto outcomes = dealii::Utilities::MPI::gather(MPI_COMM_WORLD, outcome);
    if (rank != 0)
      return;
    const auto summary = text_of(dir + "/summary.json");
    const auto status  = captures(summary, "\"status\": *\"([^\"]*)\"");
    const auto reason  = captures(summary, "\"reason\": *\"([^\"]*)\"");
    const auto steps   = captures(summary, "\"n_time_steps\": *([0-9]+)");
    for (unsigned int r = 0; r < outcomes.size(); ++r)
      std::cout << blocked << " blocked, rank " << r << ": " << outcomes[r] << std::endl;
    if (!pvd.empty())
      {
        const auto files = captures(text_of(dir + "/" + pvd), "file=\"([^\"]+)\"");
        std::cout << blocked << " blocked: files in " << pvd << ": " << files.size()
                  << ", the last " << (files.empty() ? "none" : files.back()) << std::endl;
      }
    std::cout << blocked << " blocked: summary.json status "
              << (status.empty() ? "none" : status[0]) << ", reason "
              << (reason.empty() ? "none" : reason[0]) << ", time steps "
              << (steps.empty() ? "none" : steps[0]) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run_and_check("../flow/fractured_square_drainage_short.prm", "flow-out", "flow.pvd", {});
  run_and_check("drying_cylinder_first_step_distributed_contact.prm",
                "coupled-out",
                "poromechanics.pvd",
                {});
  // A field piece of rank 1, and files only rank 0 writes: a sample line of the flow run and
  // fractures.csv of the distributed contact problem.
  run_blocked("../flow/fractured_square_drainage_short.prm",
              "flow-00003_0001.vtu",
              {"Output/Format=vtu"},
              "flow.pvd");
  run_blocked("../flow/fractured_square_drainage_short.prm",
              "line_diagonal.csv",
              {"Flow/Sample lines=diagonal: (0, 0) (1, 1) 11"});
  run_blocked("six_fractures_active_set.prm", "fractures.csv", {});
  // A checkpoint, which rank 0 writes, every second step.
  porofrac::io::RunOptions every_second_step;
  every_second_step.checkpoint_every_steps = 2;
  run_blocked(
    "../flow/fractured_square_drainage_short.prm", "checkpoint.bin", {}, "", every_second_step);
}
