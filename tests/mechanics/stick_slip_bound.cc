// SPDX-License-Identifier: LGPL-2.1-or-later
// The stopping test bounds the slip that stick faces keep (doc/algorithms.md §1.3): on the
// six-fracture scene of Section 5.2.2 (the coarse mesh of iteration_table_cold_start), both
// methods, both initial guesses and c = 1e6, 1e9, 1e11 must end with max |[u]_tau| over the
// stick faces below 1e-6 of max |[u]| (the complementarity residual alone lets it reach
// tol |lambda| / c, 1e-5 m at c = 1e6). Printed: the ratio bound per cell and the counts.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/contact_output.h>
#include <porofrac/mechanics/contact_problem.h>

#include <iomanip>
#include <iostream>

#include "six_fractures.h"

using namespace porofrac;
using namespace dealii;

int
main()
{
  auto                         mesh = six_fractures::mesh(0.1, 0.04);
  mechanics::ContactParameters c    = six_fractures::contact_parameters();
  c.line_search                     = true;
  c.line_search_on_stagnation       = true;
  c.cycle_damping                   = 0.5;
  c.max_iterations                  = 50;
  ConditionalOStream quiet(std::cout, false);
  TimerOutput        timer(quiet, TimerOutput::never, TimerOutput::wall_times);
  for (const std::string method : {"active set", "semismooth newton"})
    for (const bool stick : {true, false})
      for (const double cc : {1e6, 1e9, 1e11})
        {
          mechanics::ContactParameters cp = c;
          cp.method                       = method;
          cp.c                            = cc;
          cp.stick_guess                  = stick;
          mechanics::ContactProblem<2> problem(*mesh, cp, quiet, timer);
          problem.setup();
          try
            {
              problem.solve();
            }
          catch (const SolverFailure &)
            {
            }
          double slip_stick = 0, jump_max = 0;
          for (const auto &face : mesh->fracture_faces)
            {
              const auto v = mechanics::contact_face_values(problem, face.index);
              jump_max     = std::max(jump_max, v.jump.norm());
              if (v.state == mechanics::FaceState::stick)
                slip_stick = std::max(slip_stick, std::abs(v.jump[1]));
            }
          const auto n = mechanics::count_states(problem);
          std::cout << method << ", " << (stick ? "stick" : "open") << ", c = " << std::scientific
                    << std::setprecision(0) << cc << std::defaultfloat << ": "
                    << (problem.statistics().converged ? "converged" : "not converged")
                    << ", stick faces " << n[1] << ", stick slip below 1e-6 max |[u]|: "
                    << (slip_stick <= 1e-6 * jump_max ? "yes" : "NO") << std::endl;
        }
}
