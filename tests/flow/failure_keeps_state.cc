// SPDX-License-Identifier: LGPL-2.1-or-later
// A time-dependent run whose step fails after the allowed cuts keeps its last accepted state:
// the short fractured-square drainage with at most 3 Newton iterations fails its first step
// after 2 cuts (it needs 9 iterations at dt = 10 s). Checked: a SolverFailure naming the time and
// the cuts, summary.json with "status": "failed" and the reason, an empty history.csv (no
// accepted step), and flow.pvd listing the one field file of the last accepted state, t = 0.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <porofrac/app/parameters.h>
#include <porofrac/app/simulator.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/io/deck.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../summary_json.h"

namespace
{
  std::vector<std::string>
  lines(const std::string &file)
  {
    std::ifstream            in(file);
    std::vector<std::string> result;
    for (std::string l; std::getline(in, l);)
      result.push_back(l);
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  // run_scene is collective over MPI_COMM_WORLD (one process here).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::ParameterHandler                 prm;
  porofrac::app::declare_all_parameters(prm);
  porofrac::io::Deck deck(prm);
  const std::string  path =
    (std::filesystem::path(__FILE__).parent_path() / "fractured_square_drainage_short.prm")
      .string();
  deck.read(path);
  for (const char *s : {"Flow/Maximum Newton iterations=3",
                        "Flow/Maximum time step cuts=2",
                        "Output/Format=vtu",
                        "Output/Verbosity=quiet",
                        "Output/Timer output=none"})
    deck.set(s);
  const std::string  dir = "out";
  std::ostringstream report;
  try
    {
      porofrac::app::run_scene<2>(prm, path, dir, report);
      std::cout << "the run did not fail" << std::endl;
    }
  catch (const porofrac::SolverFailure &e)
    {
      std::cout << "SolverFailure: " << std::string(e.what()).substr(0, 50) << std::endl;
    }
  std::cout << "summary status: " << porofrac_tests::json_string(dir + "/summary.json", "status")
            << std::endl;
  const std::string reason = porofrac_tests::json_string(dir + "/summary.json", "reason");
  std::cout << "summary reason names the last failure: "
            << (reason.find("last failure") != std::string::npos ? "yes" : "no") << std::endl;
  const auto history = lines(dir + "/history.csv");
  const auto pvd     = lines(dir + "/flow.pvd");
  unsigned   files   = 0;
  for (const auto &l : pvd)
    files += l.find("<DataSet") != std::string::npos;
  const double last_time =
    history.size() > 1 ? std::stod(history.back().substr(0, history.back().find(','))) : 0.;
  const auto  &last_file = pvd[pvd.size() - 3];
  const auto   stamp     = last_file.find("timestep=\"") + 10;
  const double file_time = std::stod(last_file.substr(stamp));
  std::cout << "accepted steps in history.csv: " << history.size() - 1 << std::endl
            << "field files in flow.pvd: " << files << std::endl
            << "last field file at the last accepted time: "
            << (std::abs(file_time - last_time) <= 1e-9 * std::abs(last_time) ? "yes" : "no")
            << std::endl;
}
