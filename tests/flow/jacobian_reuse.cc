// SPDX-License-Identifier: LGPL-2.1-or-later
// The Newton solver sets the linear solver up again only for a Jacobian that changed. In the
// single-phase limit (p_w = p_nw, s_nw = 0, a mirrored non-wetting phase, no entry slope) the
// problem is linear and every Newton step has the same Jacobian: four steps with tolerances no
// step can meet make one set-up and reuse it three times, and end in the exact solution
// p = 2e5 - 1e5 x (tests/flow/single_phase_linear). In a drainage step the saturations, and with
// them the Jacobian, change every iteration: no set-up is reused.
#include <cmath>
#include <iostream>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

int
main()
{
  const auto mesh =
    flow_test::unit_square("1: (0.0, 0.5) (1.0, 0.5)", 0.1, 0.1, "frontal-delaunay");
  ConditionalOStream verbose(std::cout, std::getenv("V") != nullptr);
  bool               ok = true;

  // Linear: every update is applied in full, and the only stop is the iteration limit.
  {
    flow::TpfaGrid<2> grid(*mesh, false, {0, 1}, {0, 1});
    flow_test::set_data(grid);
    flow::NewtonParameters newton = flow_test::tight_newton();
    newton.entry_slope            = false;
    newton.residual_tolerance     = 0;
    newton.update_tolerance       = 0;
    newton.max_iterations         = 4;
    // The recipe of the single-phase decks: the non-wetting phase mirrors the water.
    // An entry pressure keeps s_nw = 0 and its derivative 0 however the round-off of the two
    // phases' updates moves p_c around 0.
    const std::shared_ptr<const flow::SaturationLaw> law = flow::make_saturation_law(
      "brooks corey", {{"Brooks-Corey entry pressure", "1e3"}, {"Brooks-Corey lambda", "2"}});
    auto rocks = flow_test::corey_rocks();
    for (auto &r : rocks)
      {
        r.saturation        = law;
        r.mobility_floor_nw = 1;
        r.viscosity[1]      = 1;
        r.viscosity[0]      = 1;
      }
    flow::TwoPhaseSolver<2> solver(grid, rocks, newton);
    solver.matrix_dirichlet   = {{0, {{2e5, 2e5}}}, {1, {{1e5, 1e5}}}};
    solver.fracture_dirichlet = {{0, {{2e5, 2e5}}}, {1, {{1e5, 1e5}}}};
    for (auto &p : solver.state)
      p = {{1.5e5, 1.5e5}};
    solver.apply_dirichlet(solver.state);
    solver.begin_time_step();
    const auto result = solver.solve_time_step(1e6, verbose);
    verbose << result.failure << std::endl;
    const auto s     = solver.linear_statistics();
    double     error = 0;
    for (unsigned int i = 0; i < grid.n_nodes(); ++i)
      for (unsigned int phase = 0; phase < 2; ++phase)
        error =
          std::max(error, std::abs(solver.state[i][phase] - (2e5 - 1e5 * grid.nodes[i].centre[0])));
    std::cout << "single phase: " << s.solves << " solves, " << s.reused_setups
              << " with the set-up reused, max relative error below 1e-10: "
              << (error < 1e-10 * 1e5 ? "yes" : "NO") << std::endl;
    ok = ok && s.solves == 4 && s.reused_setups == 3 && error < 1e-10 * 1e5;
  }
  // Two-phase drainage: a new set-up for every solve.
  {
    flow::TpfaGrid<2> grid(*mesh, false, {0, 1}, {0});
    flow_test::set_data(grid);
    const auto              rocks = flow_test::corey_rocks();
    flow::TwoPhaseSolver<2> solver(grid, rocks, flow_test::tight_newton());
    flow_test::set_drainage(solver, rocks);
    solver.begin_time_step();
    const auto result = solver.solve_time_step(1e3, verbose);
    const auto s      = solver.linear_statistics();
    std::cout << "drainage: converged " << (result.converged ? "yes" : "no") << ", "
              << (s.solves > 2 ? "more than 2" : "at most 2") << " solves, " << s.reused_setups
              << " with the set-up reused" << std::endl;
    ok = ok && result.converged && s.solves > 2 && s.reused_setups == 0;
  }
  return ok ? 0 : 1;
}
