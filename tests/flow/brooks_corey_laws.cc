// SPDX-License-Identifier: LGPL-2.1-or-later
// The laws added through the registries alone (one source file each): the Brooks-Corey
// saturation S = 1 - (p_e/p_c)^lambda above its entry pressure p_e > 0 (0 below), and the
// Corey power-law relative permeabilities k_r^alpha = (s^alpha)^(n_alpha), built as a deck
// builds them (make_saturation_law, make_relative_permeability). Checked: closed-form values,
// S = S' = U = 0 up to p_e, derivatives against centred finite differences, the capillary energy
// U against an independent midpoint quadrature of int_0^pc q S'(q) dq (lambda = 2, 0.7 and the
// logarithmic case lambda = 1), U' = p_c S', the inverse (s = 0 gives p_e), the entry pressure and
// pressure scale that the Newton iteration reads, Corey with n = 1 equal to the linear law, and
// the InputErrors of bad parameters. Every check prints "ok" or the failing values.
#include <porofrac/base/exceptions.h>
#include <porofrac/flow/parameters.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>

#include "law_test_tools.h"

using namespace porofrac;
using namespace porofrac::flow;
using namespace law_test;

namespace
{
  /// Midpoint rule for U = int_{p_e}^{p_c} q S'(q) dq on a grid graded towards p_e (where S'
  /// is largest), 2e5 intervals in log(q).
  double
  energy_quadrature(const SaturationLaw &law, const double pc)
  {
    const unsigned int n = 200000;
    const double       a = std::log(law.entry_pressure()), b = std::log(pc);
    double             U = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        const double t = a + (k + 0.5) * (b - a) / n, q = std::exp(t);
        U += q * law.derivative(q) * q * (b - a) / n; // dq = q dt
      }
    return U;
  }

  std::shared_ptr<const SaturationLaw>
  brooks_corey(const std::string &p_e, const std::string &lambda)
  {
    return make_saturation_law("brooks corey",
                               {{"Brooks-Corey entry pressure", p_e},
                                {"Brooks-Corey lambda", lambda}});
  }
} // namespace

int
main()
{
  const double p_e = 5e3;
  for (const std::string lambda_text : {"2", "0.7", "1"})
    {
      const auto           law    = brooks_corey("5e3", lambda_text);
      const SaturationLaw &bc     = *law;
      const double         lambda = std::stod(lambda_text);
      const std::string    tag    = " (lambda " + lambda_text + ")";
      check("entry pressure" + tag, bc.entry_pressure(), p_e, 0);
      check("pressure scale" + tag, bc.pressure_scale(), p_e, 0);
      check("S(p_e) = 0" + tag, bc.saturation(p_e), 0., 0);
      check("S'(p_e) = 0" + tag, bc.derivative(p_e), 0., 0);
      check("U(p_e / 2) = 0" + tag, bc.energy(0.5 * p_e), 0., 0);
      check("S(2 p_e) = 1 - 2^-lambda" + tag,
            bc.saturation(2 * p_e),
            1. - std::pow(2., -lambda),
            1e-15);
      check("S'(p_e+) = lambda/p_e" + tag, bc.derivative(p_e * (1 + 1e-12)) * p_e, lambda, 1e-10);
      check("inverse(0) = p_e" + tag, bc.inverse(0., "x"), p_e, 0);
      for (const double x : {1.001, 1.5, 4., 40.})
        {
          const double      pc = x * p_e, h = 1e-5 * pc;
          const std::string at = tag + " at p_c/p_e = " + std::to_string(x);
          check("S' vs FD" + at,
                bc.derivative(pc) * p_e,
                fd([&](double q) { return bc.saturation(q); }, pc, h) * p_e,
                1e-7);
          check("U vs quadrature" + at, bc.energy(pc) / p_e, energy_quadrature(bc, pc) / p_e, 1e-9);
          check("U' = p_c S'" + at,
                fd([&](double q) { return bc.energy(q); }, pc, h),
                pc * bc.derivative(pc),
                1e-7);
          check("inverse" + at, bc.inverse(bc.saturation(pc), "x") / pc, 1., 1e-12);
        }
    }
  // lambda = 1 closed form U = p_e ln(p_c/p_e), and lambda next to 1 (the expm1 branch) close to
  // it.
  check("U(lambda = 1) = p_e ln 3",
        brooks_corey("5e3", "1")->energy(3 * p_e),
        p_e * std::log(3.),
        1e-15);
  check("U(lambda = 1 + 1e-9) ~ U(lambda = 1)",
        brooks_corey("5e3", "1.000000001")->energy(3 * p_e) / p_e,
        std::log(3.),
        1e-8);

  const auto corey_law =
    make_relative_permeability("corey", {{"Corey exponent w", "3"}, {"Corey exponent nw", "2.5"}});
  const auto one_law =
    make_relative_permeability("corey", {{"Corey exponent w", "1"}, {"Corey exponent nw", "1"}});
  const auto                  lin_law = make_relative_permeability("linear");
  const RelativePermeability &corey   = *corey_law;
  check("Corey k_rw(s_nw = 0.4) = 0.6^3", corey.value(0, 0.4), std::pow(0.6, 3.), 1e-15);
  check("Corey k_rnw(s_nw = 0.4) = 0.4^2.5", corey.value(1, 0.4), std::pow(0.4, 2.5), 1e-15);
  check("Corey k_rw(s_nw = 1) = 0", corey.value(0, 1.), 0., 0);
  check("Corey k_rnw(s_nw = 1.2) = 1", corey.value(1, 1.2), 1., 0);
  for (const double snw : {0.05, 0.3, 0.6, 0.95})
    for (unsigned int phase = 0; phase < 2; ++phase)
      {
        const std::string at = " phase " + std::to_string(phase) + " s_nw " + std::to_string(snw);
        check("Corey dk_r/ds vs FD" + at,
              corey.derivative(phase, snw),
              fd([&](double s) { return corey.value(phase, s); }, snw, 1e-6),
              1e-8);
        check("Corey n = 1 is linear" + at,
              one_law->value(phase, snw),
              lin_law->value(phase, snw),
              1e-15);
        check("Corey n = 1 slope is linear" + at,
              one_law->derivative(phase, snw),
              lin_law->derivative(phase, snw),
              1e-15);
      }

  expect_error("entry pressure 0", [] { brooks_corey("0", "2"); });
  expect_error("lambda < 0", [] { brooks_corey("1e3", "-1"); });
  expect_error("saturation 1",
               [] { brooks_corey("1e3", "2")->inverse(1., "Flow/Boundary conditions/Matrix"); });
  expect_error("Corey exponent < 1", [] {
    make_relative_permeability("corey", {{"Corey exponent nw", "0.5"}}, fracture_rock);
  });
  expect_error("unknown law", [] { make_saturation_law("brooks-corey"); });

  std::cout << (failures == 0 ? "all checks passed" : "FAILURES") << std::endl;
  return failures == 0 ? 0 : 1;
}
