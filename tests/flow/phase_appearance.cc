// SPDX-License-Identifier: LGPL-2.1-or-later
// The Newton options of the 5.3 decks solve the same problem as the default Newton:
// gas drains a water-saturated fractured square (X and T intersections) for 8 implicit Euler steps
//  A. default: entry slope in the Jacobian where p_c <= 0, mobility floor 1e-8 on both phases;
//  B. capillary-pressure bound (p_c >= 0 at every node), no gas mobility floor, line search;
//  C. B with the pressures stored relative to 1e5 Pa (reference pressure).
// Asserted: C equals B to round-off (the reference pressure is a gauge: pressures to 1e-9
// relative, saturations to 1e-10); B agrees with A to the size of A's gas floor (saturations to
// 1e-7; measured 8e-9); the bound holds (p_c >= 0 at every free node of B) and gas did enter.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

namespace
{
  struct Run
  {
    std::vector<std::array<double, 2>> pressures; // absolute (w, nw)
    std::vector<double>                saturations;
    double                             min_pc     = 0;
    double                             gas_volume = 0;
    unsigned int                       iterations = 0;
    bool                               converged  = true;
  };

  Run
  run(const geometry::CutMesh<2> &mesh, const bool new_options, const double reference)
  {
    flow::TpfaGrid<2> grid(mesh, false, {0, 1}, {});
    flow_test::set_data(grid);
    auto rocks = flow_test::corey_rocks();
    for (auto &r : rocks)
      {
        r.mobility_floor    = 1e-8;
        r.mobility_floor_nw = new_options ? 0. : -1.;
      }
    flow::NewtonParameters newton;
    newton.residual_tolerance    = 1e-10;
    newton.update_tolerance      = 1e-13;
    newton.mass_tolerance        = 1e-12;
    newton.stagnation_iterations = 0;
    newton.capillary_bound       = new_options;
    newton.line_search           = new_options;
    flow::TwoPhaseSolver<2> solver(grid, rocks, newton);
    solver.reference_pressure = reference;
    const double pc_in        = rocks[0].saturation->inverse(0.5, "test");
    solver.matrix_dirichlet   = {{0, {{2e5 - pc_in, 2e5}}}, {1, {{1e5, 1e5}}}};
    for (auto &p : solver.state)
      p = {{1e5 - reference, 1e5 - reference}};
    solver.apply_dirichlet(solver.state);
    solver.begin_time_step();
    ConditionalOStream quiet(std::cout, false);
    Run                r;
    for (unsigned int step = 0; step < 8; ++step)
      {
        const auto result = solver.solve_time_step(20., quiet);
        r.converged       = r.converged && result.converged;
        r.iterations += result.iterations;
        solver.begin_time_step();
      }
    r.min_pc = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < grid.n_nodes(); ++i)
      {
        r.pressures.push_back(
          {{solver.pressure(solver.state, i, 0), solver.pressure(solver.state, i, 1)}});
        const flow::Rock rock = grid.nodes[i].rock == 0 ? flow::matrix_rock : flow::fracture_rock;
        r.saturations.push_back(solver.saturation(solver.state, i, rock));
        if (!grid.is_dirichlet(i))
          r.min_pc = std::min(r.min_pc, solver.state[i][1] - solver.state[i][0]);
      }
    r.gas_volume = solver.phase_volumes(solver.state)[1];
    return r;
  }

  /// Largest difference of the saturations and relative difference of the pressures.
  std::array<double, 2>
  difference(const Run &a, const Run &b)
  {
    double ds = 0, dp = 0;
    for (unsigned int i = 0; i < a.saturations.size(); ++i)
      {
        ds = std::max(ds, std::abs(a.saturations[i] - b.saturations[i]));
        for (unsigned int k = 0; k < 2; ++k)
          dp = std::max(dp,
                        std::abs(a.pressures[i][k] - b.pressures[i][k]) /
                          std::max(std::abs(a.pressures[i][k]), 1e5));
      }
    return {{ds, dp}};
  }
} // namespace

int
main()
{
  const auto mesh = flow_test::unit_square(flow_test::xt_network);
  const Run  a = run(*mesh, false, 0.), b = run(*mesh, true, 0.), c = run(*mesh, true, 1e5);
  const auto bc = difference(b, c), ab = difference(a, b);
  const bool gauge = bc[0] < 1e-10 && bc[1] < 1e-9;
  const bool agree = ab[0] < 1e-7;
  const bool bound = b.min_pc >= 0 && c.min_pc >= 0;
  const bool gas   = b.gas_volume > 1e-3;
  std::cout << "all steps converged: " << (a.converged && b.converged && c.converged ? "yes" : "NO")
            << std::endl
            << "gas entered: " << (gas ? "yes" : "NO") << std::endl
            << "reference pressure is a gauge (S to 1e-10, p to 1e-9): " << (gauge ? "yes" : "NO")
            << std::endl
            << "bound + no gas floor agrees with entry slope + floor (S to 1e-7): "
            << (agree ? "yes" : "NO") << std::endl
            << "p_c >= 0 at every free node with the bound: " << (bound ? "yes" : "NO")
            << std::endl;
  if (std::getenv("V"))
    std::cout << bc[0] << ' ' << bc[1] << ' ' << ab[0] << ' ' << ab[1] << ' ' << a.min_pc << ' '
              << b.gas_volume << " iterations " << a.iterations << ' ' << b.iterations << ' '
              << c.iterations << std::endl;
  return a.converged && b.converged && c.converged && gas && gauge && agree && bound ? 0 : 1;
}
