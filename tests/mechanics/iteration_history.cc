// SPDX-License-Identifier: LGPL-2.1-or-later
// The per-iteration history of a contact solve (summary.json "residual_terms", "face_states"):
// on the coarse six-fracture scene (86 fracture faces), semi-smooth Newton from the open guess
// with the deck's globalization. Each iteration must record the three terms of the stopping test,
// whose maximum is the relative residual recorded for it (the same number, bitwise), and the face
// states its step was computed with: every face counted once, the first step with every face
// open (the open guess) and none changed, and the change of each state's count from the previous
// step at most the number of faces that changed state. A solve stopped by its iteration limit
// must still give its history to summary.json (app::summarize_contact_iterations).
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <porofrac/app/contact_report.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "six_fractures.h"

using namespace porofrac;
using namespace dealii;

int
main()
{
  auto mesh = six_fractures::mesh(0.1, 0.04);
  std::cout << "fracture faces: " << mesh->fracture_faces.size() << std::endl;

  mechanics::ContactParameters c = six_fractures::contact_parameters();
  c.linear_solver                = "schur complement";
  c.method                       = "semismooth newton";
  c.stick_guess                  = false;
  c.c                            = 1e9;
  c.line_search                  = true;
  c.line_search_on_stagnation    = true;
  c.cycle_damping                = 0.5;

  ConditionalOStream           quiet(std::cout, false);
  TimerOutput                  timer(quiet, TimerOutput::never, TimerOutput::wall_times);
  mechanics::ContactProblem<2> problem(*mesh, c, quiet, timer);
  problem.setup();
  problem.solve();
  const auto &s = problem.statistics();
  std::cout << "converged: " << (s.converged ? "yes" : "no") << " in " << s.iterations
            << " iterations; history lengths " << s.residual_terms_history.size() << ", "
            << s.face_state_history.size() << std::endl;
  const unsigned int n_faces = mesh->fracture_faces.size();
  for (unsigned int k = 0; k < s.iterations; ++k)
    {
      const auto  &t  = s.residual_terms_history.at(k);
      const auto  &f  = s.face_state_history.at(k);
      const double mx = std::max({t[0], t[1], t[2]});
      // Changed faces bound the change of each count from the previous step's.
      bool changes_cover_counts = true;
      if (k > 0)
        for (unsigned int j = 0; j < 3; ++j)
          changes_cover_counts &= (std::abs(static_cast<int>(f[j]) -
                                            static_cast<int>(s.face_state_history.at(k - 1)[j])) <=
                                   static_cast<int>(f[3]));
      std::cout << "iteration " << k + 1 << ": open " << f[0] << ", stick " << f[1] << ", slip "
                << f[2] << ", changed " << f[3]
                << "; every face counted once: " << (f[0] + f[1] + f[2] == n_faces ? "yes" : "no")
                << "; changes cover the counts: " << (changes_cover_counts ? "yes" : "no")
                << "; max of the terms is the residual: "
                << (mx == s.residual_history.at(k) ? "yes" : "no") << "; largest term: "
                << (mx == t[0] ? "contact" : (mx == t[1] ? "mechanical" : "stick slip"))
                << std::endl;
    }

  // The same solve stopped after 3 iterations.
  c.max_iterations = 3;
  mechanics::ContactProblem<2> stopped(*mesh, c, quiet, timer);
  stopped.setup();
  try
    {
      stopped.solve();
      std::cout << "stopped solve: no failure" << std::endl;
    }
  catch (const SolverFailure &)
    {
      io::Json   j    = app::summarize_contact_iterations(c, stopped.statistics());
      const auto text = [](io::Json &value) {
        std::ostringstream out;
        value.write(out);
        return out.str();
      };
      const auto length = [&](io::Json &array) {
        const std::string t = text(array);
        return std::count(t.begin(), t.end(), ',') + 1;
      };
      std::cout << "stopped solve: summary converged " << text(j["converged"])
                << ", nonlinear_iterations " << text(j["nonlinear_iterations"])
                << ", entries: residuals " << length(j["residuals"]) << ", contact terms "
                << length(j["residual_terms"]["contact"]) << ", stick-slip terms "
                << length(j["residual_terms"]["stick_slip"]) << ", changed counts "
                << length(j["face_states"]["changed"]) << std::endl;
    }
}
