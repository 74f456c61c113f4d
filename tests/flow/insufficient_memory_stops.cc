// SPDX-License-Identifier: LGPL-2.1-or-later
// A time-dependent run whose factorization is refused for lack of memory stops at once, without
// cutting its time step (a shorter step needs the same memory): with the available memory capped
// at 1 kB, the short fractured-square drainage (its flow Jacobian by UMFPACK, the flow's default
// solver, refused in the first time step) and the drying cylinder (coupled; its contact
// mechanics by UMFPACK's full system, refused in the initial state, through the vote of
// collectively()) each throw InsufficientMemory naming the solver, with no time-step cut in the
// message, and write summary.json with status "failed"; the drainage has no accepted step in
// history.csv. After a time-step cut the message would read "... after N time-step cuts" and
// the error would be a plain SolverFailure.
#include <deal.II/base/mpi.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>

#include <fstream>
#include <iostream>
#include <regex>
#include <string>

#include "../run_deck.h"
#include "../summary_json.h"

namespace
{
  /// Runs @p deck (relative to this file) with 1 kB of memory into @p dir; prints how it ended.
  void
  run_capped(const std::string &deck, const std::string &dir)
  {
    porofrac::limit_available_memory(1e-3);
    std::cout << deck << ": ";
    try
      {
        porofrac_tests::run_deck(porofrac_tests::deck_path(__FILE__, deck), {}, dir);
        std::cout << "the run did not fail" << std::endl;
      }
    catch (const porofrac::InsufficientMemory &e)
      {
        const std::string message = e.what();
        std::cout << "InsufficientMemory, time-step cuts in the message: "
                  << (message.find("cut") != std::string::npos ? "yes" : "no") << std::endl
                  << "  "
                  << std::regex_replace(message.substr(0, message.find(", more than")),
                                        std::regex("[0-9.]+ (kB|MB|GB)"),
                                        "# $1")
                  << std::endl;
      }
    catch (const porofrac::SolverFailure &e)
      {
        std::cout << "another solver failure: " << e.what() << std::endl;
      }
    porofrac::limit_available_memory(0);
    std::cout << "  summary status: "
              << porofrac_tests::json_string(dir + "/summary.json", "status") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  // run_scene is collective over MPI_COMM_WORLD (one process here).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run_capped("fractured_square_drainage_short.prm", "out-flow");
  std::ifstream history("out-flow/history.csv");
  unsigned int  lines = 0;
  for (std::string l; std::getline(history, l);)
    ++lines;
  std::cout << "  accepted steps in history.csv: " << (lines > 0 ? lines - 1 : 0) << std::endl;
  run_capped("../coupling/drying_cylinder_first_step.prm", "out-coupled");
}
