// SPDX-License-Identifier: LGPL-2.1-or-later
// Flow laws: Corey and van Genuchten saturations, capillary energy U against an independent
// quadrature of int_0^pc q S'(q) dq, derivatives against centred finite differences, van
// Genuchten-Mualem and linear relative permeabilities (the registered laws, built as a deck would
// build them), Kozeny-Carman (coupling/closure.h), and bad-input errors.
// Every check prints "ok" or the failing values.
#include <porofrac/base/exceptions.h>
#include <porofrac/coupling/closure.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/flow/rock_type.h>

#include <cmath>
#include <functional>
#include <iostream>

#include "law_test_tools.h"

using namespace porofrac;
using namespace porofrac::flow;
using namespace law_test;

namespace
{
  // Independent midpoint-rule quadrature of U = int_0^pc q S'(q) dq with 2e5 intervals.
  double
  energy_quadrature(const SaturationLaw &law, const double pc)
  {
    const unsigned int n = 200000;
    double             U = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        const double q = (k + 0.5) * pc / n;
        U += q * law.derivative(q) * pc / n;
      }
    return U;
  }
} // namespace

int
main()
{
  const auto corey_law = make_saturation_law("corey", {{"Corey R", "2e8"}});
  const auto vg_law =
    make_saturation_law("van genuchten",
                        {{"van Genuchten P_r", "1.5e7"}, {"van Genuchten n", "1.49"}});
  const SaturationLaw &corey = *corey_law;
  const SaturationLaw &vg    = *vg_law;
  // Corey saturation, closed form at p_c = R: 1 - 1/e
  check("Corey S(R)", corey.saturation(2e8), 1. - std::exp(-1.), 1e-14);
  check("Corey S(-1) = 0", corey.saturation(-1.), 0., 0);
  check("Corey inverse", corey.inverse(0.35, "x"), 86.157e6, 1e-5 * 86.157e6);
  for (const double pc : {1e6, 8.6e7, 4e8})
    {
      check("Corey U vs quadrature at " + std::to_string(pc),
            corey.energy(pc),
            energy_quadrature(corey, pc),
            1e-8 * pc);
      check("Corey S' vs FD",
            corey.derivative(pc) * 2e8,
            fd([&](double x) { return corey.saturation(x); }, pc, 1e3) * 2e8,
            1e-7);
      check("Corey U' = pc S'",
            fd([&](double x) { return corey.energy(x); }, pc, 1e3),
            pc * corey.derivative(pc),
            1e-6);
      check("vG U vs quadrature", vg.energy(pc), energy_quadrature(vg, pc), 1e-6 * pc);
      check("vG S' vs FD",
            vg.derivative(pc) * 1.5e7,
            fd([&](double x) { return vg.saturation(x); }, pc, 1e2) * 1.5e7,
            1e-6);
      check("vG inverse", vg.inverse(vg.saturation(pc), "x"), pc, 1e-9 * pc);
    }
  // Fracture Corey law of 5.3: p_c for s = 1 - 1e-8 (doc/algorithms.md §6.1).
  check("Corey fracture inverse",
        make_saturation_law("corey", {{"Corey R", "1e2"}}, fracture_rock)->inverse(1 - 1e-8, "x"),
        1842.068,
        1e-6 * 1842);

  const auto vgm_law =
    make_relative_permeability("van genuchten-mualem",
                               {{"Mualem q", "0.328"}, {"S_lr", "0.35"}, {"S_gr", "0"}});
  const auto                  lin_law = make_relative_permeability("linear");
  const RelativePermeability &vgm     = *vgm_law;
  const RelativePermeability &lin     = *lin_law;
  check("VGM k_rw(s_w = 1) = 1", vgm.value(0, 0.), 1., 1e-14);
  check("VGM k_rw(s_w = S_lr) = 0", vgm.value(0, 0.65), 0., 1e-14);
  check("VGM k_rnw(s_w = S_lr) = 1", vgm.value(1, 0.65), 1., 1e-14);
  check("VGM k_rnw(s_nw = 0) = 0", vgm.value(1, 0.), 0., 1e-14);
  {
    // s = 0.5: k_rw = sqrt(.5) (1 - (1 - .5^(1/q))^q)^2
    const double s = 0.5, q = 0.328, B = 1 - std::pow(s, 1 / q);
    check("VGM k_rw(s=1/2)",
          vgm.value(0, 1 - 0.35 - 0.5 * 0.65),
          std::sqrt(s) * std::pow(1 - std::pow(B, q), 2),
          1e-14);
    check("VGM k_rnw(s=1/2)",
          vgm.value(1, 1 - 0.35 - 0.5 * 0.65),
          std::sqrt(1 - s) * std::pow(B, 2 * q),
          1e-14);
  }
  for (const double snw : {0.05, 0.3, 0.6})
    for (unsigned int phase = 0; phase < 2; ++phase)
      {
        check("VGM dk_r/ds FD phase " + std::to_string(phase) + " s_nw " + std::to_string(snw),
              vgm.derivative(phase, snw),
              fd([&](double x) { return vgm.value(phase, x); }, snw, 1e-7),
              1e-6);
        check("linear dk_r/ds FD",
              lin.derivative(phase, snw),
              fd([&](double x) { return lin.value(phase, x); }, snw, 1e-7),
              1e-8);
      }
  check("Kozeny-Carman at phi0 = K0", coupling::kozeny_carman(5e-20, 0.15, 0.15) * 1e20, 5., 1e-14);
  check("Kozeny-Carman derivative FD",
        coupling::kozeny_carman_derivative(5e-20, 0.15, 0.2) * 1e20,
        fd([](double x) { return coupling::kozeny_carman(5e-20, 0.15, x) * 1e20; }, 0.2, 1e-6),
        1e-7);

  RockType rock;
  rock.relative_permeability = vgm_law;
  rock.viscosity[1]          = 1.851e-5;
  check("mobility nw = k_r/mu", rock.mobility(1, 0.3), vgm.value(1, 0.3) / 1.851e-5, 1e-14);

  expect_error("S_lr + S_gr >= 1", [] {
    make_relative_permeability("van genuchten-mualem",
                               {{"Mualem q", "0.3"}, {"S_lr", "0.6"}, {"S_gr", "0.4"}});
  });
  expect_error("zero viscosity", [] {
    RockType r;
    r.viscosity[0] = 0.;
    r.validate("Flow/Matrix", "Flow/Matrix");
  });
  expect_error("negative R", [] { make_saturation_law("corey", {{"Corey R", "-1"}}); });
  expect_error("saturation outside [0,1]",
               [&] { corey.inverse(1.2, "Flow/Boundary conditions/Matrix"); });

  std::cout << (failures == 0 ? "all checks passed" : "FAILURES") << std::endl;
  return failures == 0 ? 0 : 1;
}
