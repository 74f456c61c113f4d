// SPDX-License-Identifier: LGPL-2.1-or-later
// Drainage through a network with an X and a T intersection and a fracture reaching the inlet:
// every implicit Euler step must conserve the mass of each phase to 1e-10 (relative, boundary
// fluxes accounted), and at every massless intersection node the fluxes of each phase must
// balance (to 1e-10 relative to the largest flux through the node). The non-wetting phase must
// have entered the fractures and the matrix.
#include <cmath>
#include <iostream>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

int
main()
{
  const auto        mesh = flow_test::unit_square(flow_test::xt_network, 0.1, 0.05);
  flow::TpfaGrid<2> grid(*mesh, false, {0, 1}, {0});
  flow_test::set_data(grid);
  const auto rocks = flow_test::corey_rocks();
  // Tight Newton tolerances, so that the node balances are checked to round-off.
  flow::TwoPhaseSolver<2> solver(grid, rocks, flow_test::tight_newton());
  const double            pc_in_m = rocks[0].saturation->inverse(0.5, "test");
  const double            pc_in_f = rocks[1].saturation->inverse(0.9, "test");
  solver.matrix_dirichlet         = {{0, {{2e5 - pc_in_m, 2e5}}}, {1, {{1e5, 1e5}}}};
  solver.fracture_dirichlet       = {{0, {{2e5 - pc_in_f, 2e5}}}};
  for (auto &p : solver.state)
    p = {{1e5, 1e5}};
  solver.apply_dirichlet(solver.state);
  solver.begin_time_step();
  std::cout << "intersection nodes: " << grid.n_intersections << std::endl;

  ConditionalOStream quiet(std::cout, false);
  double             dt = 10, mass_max = 0, node_max = 0;
  unsigned int       iterations = 0;
  bool               converged  = true;
  for (unsigned int step = 0; step < 8; ++step, dt *= 1.5)
    {
      const auto result = solver.solve_time_step(dt, quiet);
      converged         = converged && result.converged;
      iterations += result.iterations;
      const auto defect = solver.mass_defect(solver.state, solver.old_state, dt);
      mass_max          = std::max({mass_max, defect[0], defect[1]});
      // Flux balance at intersection nodes.
      std::vector<std::array<double, 2>> sum(grid.n_nodes(), {{0., 0.}}),
        big(grid.n_nodes(), {{0., 0.}});
      for (const auto &c : grid.connections)
        for (unsigned int phase = 0; phase < 2; ++phase)
          {
            const double       delta = solver.state[c.a][phase] - solver.state[c.b][phase];
            const unsigned int up    = delta >= 0 ? c.a : c.b;
            const auto        &rock  = rocks[delta >= 0 ? c.rock_a : c.rock_b];
            const double       F     = c.transmissibility *
                             rock.mobility(phase,
                                           rock.saturation->saturation(solver.state[up][1] -
                                                                       solver.state[up][0])) *
                             delta;
            sum[c.a][phase] += F;
            sum[c.b][phase] -= F;
            big[c.a][phase] = std::max(big[c.a][phase], std::abs(F));
            big[c.b][phase] = std::max(big[c.b][phase], std::abs(F));
          }
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        if (grid.nodes[i].kind == flow::TpfaGrid<2>::NodeKind::intersection)
          for (unsigned int phase = 0; phase < 2; ++phase)
            if (big[i][phase] > 0)
              node_max = std::max(node_max, std::abs(sum[i][phase]) / big[i][phase]);
      solver.begin_time_step();
    }
  const auto volumes = solver.phase_volumes(solver.state);
  double     sf_max  = 0;
  for (unsigned int s = 0; s < grid.n_fracture_cells; ++s)
    sf_max =
      std::max(sf_max,
               solver.saturation(solver.state, grid.n_matrix_cells + s, flow::fracture_rock));
  if (std::getenv("V"))
    std::cout << mass_max << ' ' << node_max << ' ' << iterations << std::endl;
  const bool ok =
    converged && mass_max < 1e-10 && node_max < 1e-10 && volumes[1] > 0 && sf_max > 0.5;
  std::cout << "all steps converged: " << (converged ? "yes" : "NO") << std::endl
            << "mass defect per step below 1e-10: " << (mass_max < 1e-10 ? "yes" : "NO")
            << std::endl
            << "flux balance at intersection nodes below 1e-10: "
            << (node_max < 1e-10 ? "yes" : "NO") << std::endl
            << "non-wetting phase entered (volume > 0, fracture s_nw > 0.5): "
            << (volumes[1] > 0 && sf_max > 0.5 ? "yes" : "NO") << std::endl;
  return ok ? 0 : 1;
}
