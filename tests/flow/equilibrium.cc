// SPDX-License-Identifier: LGPL-2.1-or-later
// A capillary-gravity-free equilibrium stays at rest: uniform phase pressures with p_c > 0 in
// matrix, fractures, interfaces and intersection nodes, the same pressures on every Dirichlet
// boundary. Ten implicit Euler steps must take zero Newton iterations and leave every pressure
// unchanged.
#include <cmath>
#include <iostream>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

int
main()
{
  const auto mesh = flow_test::unit_square(
    "1: (0.1, 0.5) (0.9, 0.5); 2: (0.3, 0.2) (0.3, 0.8); 3: (0.7, 0.5) (0.7, 0.2)", 0.15, 0.075);
  flow::TpfaGrid<2> grid(*mesh, false, {0, 1, 2, 3}, {});
  flow_test::set_data(grid);
  flow::TwoPhaseSolver<2>     solver(grid, flow_test::corey_rocks(), flow::NewtonParameters());
  const std::array<double, 2> p = {{1e5, 1.05e5}};
  solver.matrix_dirichlet       = {{0, p}, {1, p}, {2, p}, {3, p}};
  for (auto &q : solver.state)
    q = p;
  solver.begin_time_step();
  ConditionalOStream quiet(std::cout, false);
  unsigned int       iterations = 0;
  bool               converged  = true;
  for (unsigned int step = 0; step < 10; ++step)
    {
      const auto r = solver.solve_time_step(100., quiet);
      converged    = converged && r.converged;
      iterations += r.iterations;
      solver.begin_time_step();
    }
  double change = 0;
  for (const auto &q : solver.state)
    change = std::max({change, std::abs(q[0] - p[0]), std::abs(q[1] - p[1])});
  std::cout << "converged: " << (converged ? "yes" : "NO") << ", Newton iterations " << iterations
            << ", max pressure change (Pa) " << change << std::endl;
  return converged && iterations == 0 && change == 0 ? 0 : 1;
}
