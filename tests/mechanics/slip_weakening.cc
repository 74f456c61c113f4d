// SPDX-License-Identifier: LGPL-2.1-or-later
// The slip-weakening friction law (Mechanics/Friction law = slip weakening): F falls linearly
// from the static coefficient F_s (Friction coefficient) to F_d over the critical slip D_c. On
// the coarse six-fracture scene of 5.2.2 (top shear) with F_s = 0.6, F_d = 0.3:
// - with D_c = 1 mm (of the order of the slips) the converged state satisfies Coulomb's law with
//   the weakened coefficient on every face: |lambda_t| = F(|[u]_t|) lambda_n on slipping faces,
//   |lambda_t| <= F(|[u]_t|) lambda_n and no slip on sticking ones; some faces are partly and
//   some fully weakened;
// - with D_c = 1e-12 m every slipping face is fully weakened (F = F_d) while sticking faces,
//   which have not slipped, hold up to F_s (the law is not Coulomb's with F_d);
// - with D_c = 1e6 m no face weakens: the solution equals the Coulomb one with F = F_s.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <porofrac/mechanics/contact_problem.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "six_fractures.h"

using namespace porofrac;
using namespace dealii;

namespace
{
  /// The deck's mechanics with the given friction entries, parsed as from a deck.
  mechanics::ContactParameters
  parameters(const std::string &law, const std::string &F, const std::string &F_d, double D_c)
  {
    ParameterHandler prm;
    mechanics::ContactParameters::declare_parameters(prm);
    prm.enter_subsection("Mechanics");
    prm.set("Young modulus", "4e9");
    prm.set("Poisson ratio", "0.2");
    prm.set("Dirichlet", "2: x=0, y=0; 3: x=0.005, y=-0.002");
    prm.set("Friction coefficient", F);
    prm.set("Friction law", law);
    prm.set("Dynamic friction coefficient", F_d);
    std::ostringstream d;
    d << std::setprecision(17) << D_c;
    prm.set("Critical slip distance", d.str());
    prm.set("Solver", "semismooth newton");
    prm.set("Complementarity parameter c", "1e11");
    prm.set("Tolerance", "1e-12");
    prm.leave_subsection();
    mechanics::ContactParameters c;
    c.parse_parameters(prm, 2);
    return c;
  }

  double
  relative_difference(const Vector<double> &a, const Vector<double> &b)
  {
    Vector<double> d(a);
    d -= b;
    return d.linfty_norm() / a.linfty_norm();
  }
} // namespace

int
main()
{
  auto               mesh = six_fractures::mesh(0.1, 0.04);
  ConditionalOStream quiet(std::cout, false);
  TimerOutput        timer(quiet, TimerOutput::never, TimerOutput::wall_times);
  const auto         solve = [&](const mechanics::ContactParameters &c) {
    auto p = std::make_unique<mechanics::ContactProblem<2>>(*mesh, c, quiet, timer);
    p->setup();
    p->solve();
    return p;
  };

  const double F_s = 0.6, F_d = 0.3;
  for (const double D_c : {1e-3, 1e-12})
    {
      auto         weakening = solve(parameters("slip weakening", "0.6", "0.3", D_c));
      unsigned int n[3] = {0, 0, 0}, partly = 0, fully = 0;
      double       slip_defect = 0, stick_excess = 0, stick_slip = 0;
      for (const auto &face : mesh->fracture_faces)
        {
          const Tensor<2, 2> R     = weakening->frame(face.index);
          const Tensor<1, 2> j     = R * weakening->jump(face.index);
          const Tensor<1, 2> l     = R * weakening->multiplier(face.index);
          const double       s     = std::abs(j[1]);
          const double       F     = F_d + (F_s - F_d) * std::max(0., 1 - s / D_c);
          const auto         state = weakening->state(face.index);
          ++n[static_cast<unsigned int>(state)];
          if (state == mechanics::FaceState::slip)
            {
              slip_defect = std::max(slip_defect, std::abs(std::abs(l[1]) - F * l[0]) / l[0]);
              partly += (s < D_c);
              fully += (s >= D_c);
            }
          if (state == mechanics::FaceState::stick)
            {
              stick_excess = std::max(stick_excess, (std::abs(l[1]) - F_s * l[0]) / l[0]);
              stick_slip   = std::max(stick_slip, s);
            }
        }
      std::cout << "slip weakening, D_c = " << std::scientific << std::setprecision(0) << D_c
                << std::defaultfloat << " m: converged in " << weakening->statistics().iterations
                << " iterations; faces open " << n[0] << ", stick " << n[1] << ", slip " << n[2]
                << "; slipping faces partly weakened " << partly << ", fully " << fully << std::endl
                << "  slipping faces: |lambda_t| = F(|[u]_t|) lambda_n to 1e-8: "
                << (slip_defect < 1e-8 ? "yes" : "no") << std::endl
                << "  sticking faces: |lambda_t| <= F_s lambda_n and |[u]_t| < 1e-12 m: "
                << (stick_excess < 1e-9 && stick_slip < 1e-12 ? "yes" : "no") << std::endl;
    }

  // D_c far above every slip: F = F_s on every face, the Coulomb solution with F = 0.6.
  auto       limit   = solve(parameters("slip weakening", "0.6", "0.3", 1e6));
  auto       coulomb = solve(parameters("coulomb", "0.6", "0", 1e-3));
  const bool same    = relative_difference(coulomb->displacement(), limit->displacement()) < 1e-6 &&
                    relative_difference(coulomb->multipliers(), limit->multipliers()) < 1e-6;
  std::cout << "D_c = 1e6 m: u and lambda equal those of Coulomb friction with F = 0.6 to 1e-6: "
            << (same ? "yes" : "no") << std::endl;
}
