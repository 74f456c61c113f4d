// SPDX-License-Identifier: LGPL-2.1-or-later
// The two linear-solver paths of the contact iterations (Mechanics/Linear solver): UMFPACK on the
// whole (u, lambda) Jacobian, and the Schur complement on the multipliers with one Cholesky
// factorization of K (multiplier_schur_complement.h). They solve the same linear systems, so on
// the six-fracture scene of Section 5.2.2 (coarse deck mesh) they must take the same number of
// iterations, end in the same face states, and agree to solver tolerance on u and lambda; checked
// for the active-set method (open guess) and the semi-smooth Newton method (stick guess, c = 1e11),
// and again for a warm-started second solve after a load change (set_equivalent_pressures), which
// reuses the factorization and W.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <porofrac/mechanics/contact_problem.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "six_fractures.h"

using namespace porofrac;
using namespace dealii;

int
main()
{
  auto mesh = six_fractures::mesh(0.1, 0.04);
  std::cout << "fracture faces: " << mesh->fracture_faces.size() << std::endl;

  ConditionalOStream quiet(std::cout, false);
  TimerOutput        timer(quiet, TimerOutput::never, TimerOutput::wall_times);
  for (const std::string method : {"active set", "semismooth newton"})
    {
      mechanics::ContactParameters c = six_fractures::contact_parameters();
      c.method                       = method;
      c.stick_guess                  = (method == "semismooth newton");
      c.c                            = (method == "semismooth newton" ? 1e11 : 1e9);
      mechanics::ContactProblem<2> full(*mesh, c, quiet, timer);
      c.linear_solver = "schur complement";
      mechanics::ContactProblem<2> schur(*mesh, c, quiet, timer);
      full.setup();
      schur.setup();
      const std::vector<double> pm(mesh->triangulation.n_active_cells(), 1e6),
        pf(mesh->fracture_faces.size(), 0.5e6);
      for (const bool warm : {false, true})
        {
          if (warm)
            for (auto *p : {&full, &schur})
              p->set_equivalent_pressures(pm, pf, 0.8);
          full.solve(warm);
          schur.solve(warm);
          unsigned int same_states = 0;
          for (unsigned int f = 0; f < mesh->fracture_faces.size(); ++f)
            same_states += (full.state(f) == schur.state(f));
          Vector<double> du(full.displacement()), dl(full.multipliers());
          du -= schur.displacement();
          dl -= schur.multipliers();
          const double eu = du.linfty_norm() / full.displacement().linfty_norm();
          const double el = dl.linfty_norm() / full.multipliers().linfty_norm();
          std::cout << (method == "active set" ? "active set, open guess" :
                                                 "semismooth newton, stick guess")
                    << (warm ? ", warm start after a load change" : "") << ": iterations "
                    << full.statistics().iterations << " / " << schur.statistics().iterations
                    << ", same face states on " << same_states
                    << " faces, u and lambda agree to 1e-8: "
                    << (eu < 1e-8 && el < 1e-8 ? "yes" : "no") << std::endl;
        }
    }
}
