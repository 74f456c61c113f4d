// SPDX-License-Identifier: LGPL-2.1-or-later
// Equivalent pressures of paper (11d) (coupling::equivalent_pressure, the function that the
// coupled scenes and the Biot storage evaluate) for the Corey law of Section 5.3, against the
// closed form p_E = p^nw - R S^nw(p_c) for p_c > 0, at the boundary states of the drying scene:
// - matrix at the drying wall: s^nw = 0.35, p^nw = 1e5 Pa, R_m = 2e8 Pa: p_E = 1e5 - 0.35 R_m
//   = -6.99e7 Pa;
// - fracture node at the wall: s^nw = 1 - 1e-8, p^nw = 1e5 Pa, R_f = 1e2 Pa: p_E = 99,900 Pa;
// - liquid-saturated (p_c <= 0): p_E = p^w.
// The derivatives with respect to (p^w, p^nw) are checked against central differences, with and
// without the capillary energy (Remark 3.1); without it p_E = p^nw S + p^w (1 - S).
#include <porofrac/coupling/closure.h>
#include <porofrac/flow/parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

using namespace porofrac;

int
main()
{
  std::cout << std::scientific << std::setprecision(6);
  const auto matrix_law = flow::make_saturation_law("corey", {{"Corey R", "2e8"}});
  const auto fracture_law =
    flow::make_saturation_law("corey", {{"Corey R", "1e2"}}, flow::fracture_rock);
  const auto &matrix   = *matrix_law;
  const auto &fracture = *fracture_law;
  // p_E as a function of the phase pressures.
  const auto p_E = [](const flow::SaturationLaw &law,
                      const double               p_w,
                      const double               p_nw,
                      const bool                 with_energy = true) {
    return coupling::equivalent_pressure(law, p_w, p_nw - p_w, with_energy);
  };

  const double pc_m = matrix.inverse(0.35, "test");
  const double pE_m = p_E(matrix, 1e5 - pc_m, 1e5);
  std::cout << "matrix wall: p_c = " << pc_m << " Pa, p_E = " << pE_m
            << " Pa, closed form 1e5 - 0.35 R_m = " << 1e5 - 0.35 * 2e8 << " Pa" << std::endl;

  const double pc_f = fracture.inverse(1 - 1e-8, "test");
  const double pE_f = p_E(fracture, 1e5 - pc_f, 1e5);
  std::cout << "fracture wall: p_c = " << pc_f << " Pa, p_E = " << pE_f
            << " Pa, closed form 1e5 - R_f (1 - 1e-8) = " << 1e5 - 1e2 * (1 - 1e-8) << " Pa"
            << std::endl;

  std::cout << "saturated (p_w = 4e6, p_nw = 3e6): p_E = " << p_E(matrix, 4e6, 3e6) << " Pa"
            << std::endl;

  double worst = 0;
  for (const bool with_energy : {true, false})
    for (const double pc : {-1e6, 1e3, 5e7, 2e8, 8e8})
      {
        const double pw = 1e6, h = 1e-6 * std::max(pw, std::abs(pc));
        const auto   d = coupling::equivalent_pressure_derivatives(matrix, pc, with_energy);
        const double fd_w =
          (p_E(matrix, pw + h, pw + pc, with_energy) - p_E(matrix, pw - h, pw + pc, with_energy)) /
          (2 * h);
        const double fd_nw =
          (p_E(matrix, pw, pw + pc + h, with_energy) - p_E(matrix, pw, pw + pc - h, with_energy)) /
          (2 * h);
        worst = std::max({worst, std::abs(d[0] - fd_w), std::abs(d[1] - fd_nw)});
      }
  std::cout << std::setprecision(2) << "derivatives against central differences below 1e-6: "
            << (worst < 1e-6 ? "yes" : "no") << std::endl;
}
