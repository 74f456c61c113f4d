// SPDX-License-Identifier: LGPL-2.1-or-later
// The memory check of the Schur complement solver (Mechanics/Linear solver = schur complement):
// after the symbolic analysis of K and before its numeric factorization, the Cholesky factor
// and the dense multiplier matrices are counted against the memory the run has, once per
// process that holds a copy (the coupled model's replicated contact mechanics). On the
// six-fracture scene of Section 5.2.2 (coarse deck mesh, 172 multipliers): with the memory capped
// far below the need the solve stops with InsufficientMemory on the dense matrices alone; capped
// at 1.5 times their need it stops before the copy of K and its ordering (SparseCholesky's own
// check); capped at 1.5 times that need, at the Cholesky factor that the symbolic analysis sizes;
// capped at 1.5 times the whole need it runs and gives the uncapped solution; with two copies per
// machine and room for two analyses it stops at the factor, and the message says why.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/contact_problem.h>

#include <algorithm>
#include <iostream>
#include <regex>

#include "six_fractures.h"

using namespace porofrac;
using namespace dealii;

namespace
{
  /// Solves the scene with a new contact problem; the message of an InsufficientMemory, or "".
  std::string
  solve(const geometry::CutMesh<2> &mesh, Vector<double> *displacement = nullptr)
  {
    ConditionalOStream           quiet(std::cout, false);
    TimerOutput                  timer(quiet, TimerOutput::never, TimerOutput::wall_times);
    mechanics::ContactParameters c = six_fractures::contact_parameters();
    c.linear_solver                = "schur complement";
    mechanics::ContactProblem<2> problem(mesh, c, quiet, timer);
    problem.setup();
    try
      {
        problem.solve(false);
      }
    catch (const InsufficientMemory &e)
      {
        return e.what();
      }
    if (displacement)
      *displacement = problem.displacement();
    return "";
  }

  /// @p message with its sizes replaced by "#".
  std::string
  masked(const std::string &message)
  {
    return std::regex_replace(message, std::regex("[0-9.]+ (MB|GB)"), "# $1");
  }

  /// The "at least N MB" of a memory message.
  double
  needed_mb(const std::string &message)
  {
    std::smatch match;
    const bool  found = std::regex_search(message, match, std::regex("at least ([0-9.]+) MB"));
    return found ? std::stod(match[1]) : 0.;
  }
} // namespace

int
main()
{
  auto mesh = six_fractures::mesh(0.1, 0.04);

  Vector<double> reference;
  std::cout << "no cap, solved: " << solve(*mesh, &reference).empty() << std::endl;


  // Far below the need: refused before the symbolic analysis of K, on the dense matrices.
  limit_available_memory(1e-3);
  const std::string dense = solve(*mesh);
  std::cout << "cap 1 kB: refused: " << !dense.empty() << "\n  " << masked(dense) << std::endl;

  // Enough for the dense matrices, not for the copy of K and its ordering.
  limit_available_memory(1.5 * needed_mb(dense));
  const std::string analysis = solve(*mesh);
  std::cout << "cap 1.5 x dense need: refused: " << !analysis.empty() << "\n  " << masked(analysis)
            << std::endl;

  // Enough for those, not with the factor that the analysis of K sizes.
  // (The need is printed to 0.01 MB.)
  limit_available_memory(needed_mb(analysis) + 0.01);
  const std::string factor = solve(*mesh);
  std::cout << "cap at the analysis need: refused: " << !factor.empty() << "\n  " << masked(factor)
            << std::endl;

  const double need = needed_mb(factor);
  limit_available_memory(1.5 * need);
  Vector<double> capped;
  const bool     solved = solve(*mesh, &capped).empty();
  capped -= reference;
  std::cout << "cap 1.5 x whole need, solved: " << solved
            << ", same solution: " << (capped.linfty_norm() <= 1e-12 * reference.linfty_norm())
            << std::endl;

  // Enough for two copies of the analysis, not for two factors with their dense matrices.
  limit_available_memory(2 * needed_mb(analysis) + 0.02);
  {
    const ReplicatedSerialSolves two_copies(2);
    const std::string            twice = solve(*mesh);
    std::cout << "cap at two analysis needs, 2 copies per machine: refused: " << !twice.empty()
              << ", need stated twice over: "
              << (std::abs(needed_mb(twice) - 2 * need) <= 0.01 * need) << "\n  " << masked(twice)
              << std::endl;
  }
  std::cout << "copies per machine after the scope: "
            << ReplicatedSerialSolves::copies_per_machine() << std::endl;
  limit_available_memory(0);
}
