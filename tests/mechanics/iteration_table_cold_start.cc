// SPDX-License-Identifier: LGPL-2.1-or-later
// ContactProblem::set_contact_solver() (used by Mechanics/Iteration table) must give cold solves:
// on the six-fracture scene of Section 5.2.2 (a mesh coarser than the deck's, 86 fracture faces,
// so that 12 fresh set-ups stay quick in Debug; the deck's globalization: Schur complement, line
// search on stagnation, cycle damping 0.5), every cell of paper Tables 3-4
// (method x c x initial guess) solved by ONE problem after the previous cells (sharing K, its
// Cholesky factors and W) must repeat the solve of a fresh ContactProblem: same convergence, same
// iteration count, the same residual history and the same u, lambda (to 1e-12; the operations
// are the same, so they are in fact bitwise equal). The cells run in the table's order, so every
// cell follows a solve with other rows, another c or another guess. (On the deck mesh the counts
// of the in-process table equal those of separate processes: iteration_table_six_fractures.)
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/contact_problem.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "six_fractures.h"

using namespace porofrac;
using namespace dealii;

namespace
{
  bool
  solve(mechanics::ContactProblem<2> &p)
  {
    try
      {
        p.solve();
      }
    catch (const SolverFailure &)
      {
      }
    return p.statistics().converged;
  }

  double
  relative_difference(const Vector<double> &a, const Vector<double> &b)
  {
    Vector<double> d(a);
    d -= b;
    return a.linfty_norm() > 0 ? d.linfty_norm() / a.linfty_norm() : d.linfty_norm();
  }
} // namespace

int
main()
{
  auto mesh = six_fractures::mesh(0.1, 0.04); // coarser than the deck (0.05, 0.02)
  std::cout << "fracture faces: " << mesh->fracture_faces.size() << std::endl;

  mechanics::ContactParameters c = six_fractures::contact_parameters();
  c.linear_solver                = "schur complement";
  c.line_search                  = true;
  c.line_search_on_stagnation    = true;
  c.cycle_damping                = 0.5;
  c.initial_lambda_n             = 100;
  c.max_iterations               = 50;

  ConditionalOStream quiet(std::cout, false);
  TimerOutput        timer(quiet, TimerOutput::never, TimerOutput::wall_times);
  // The shared problem first does the deck's solve (active set, stick, c = 1e9).
  mechanics::ContactProblem<2> shared(*mesh, c, quiet, timer);
  shared.setup();
  solve(shared);
  for (const std::string method : {"active set", "semismooth newton"})
    for (const bool stick : {true, false})
      for (const double cc : {1e6, 1e9, 1e11})
        {
          mechanics::ContactParameters cp = c;
          cp.method                       = method;
          cp.c                            = cc;
          cp.stick_guess                  = stick;
          mechanics::ContactProblem<2> fresh(*mesh, cp, quiet, timer);
          fresh.setup();
          const bool fresh_converged = solve(fresh);
          shared.set_contact_solver(method, cc, stick);
          const bool  shared_converged = solve(shared);
          const auto &h1               = fresh.statistics().residual_history,
                     &h2               = shared.statistics().residual_history;
          bool same_history            = (h1.size() == h2.size());
          for (unsigned int k = 0; same_history && k < h1.size(); ++k)
            same_history = std::abs(h1[k] - h2[k]) <= 1e-12 * std::abs(h1[k]);
          const bool same_solution =
            relative_difference(fresh.displacement(), shared.displacement()) <= 1e-12 &&
            relative_difference(fresh.multipliers(), shared.multipliers()) <= 1e-12;
          std::cout << method << ", " << (stick ? "stick" : "open") << ", c = " << std::scientific
                    << std::setprecision(0) << cc << std::defaultfloat << ": fresh "
                    << (fresh_converged ? "converged" : "not converged") << " in "
                    << fresh.statistics().iterations << ", shared "
                    << (shared_converged ? "converged" : "not converged") << " in "
                    << shared.statistics().iterations
                    << "; same residual history: " << (same_history ? "yes" : "no")
                    << "; same u, lambda: " << (same_solution ? "yes" : "no") << std::endl;
        }
}
