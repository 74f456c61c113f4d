// SPDX-License-Identifier: LGPL-2.1-or-later
// Single-phase limit with a conductive fracture crossing the square along the flow: p_w = p_nw
// (p_c = 0, only water) with p = 2e5 Pa on x = 0 and 1e5 Pa on x = 1 for both the matrix and
// the fracture ends. The exact solution p = 2e5 - 1e5 x is linear, with no matrix-fracture
// exchange; TPFA with circumcentres reproduces it exactly in matrix cells, fracture cells and
// interface nodes. Also checks the fracture carries the flux (d_f^3/12) |grad p|.
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
  flow::TpfaGrid<2> grid(*mesh, false, {0, 1}, {0, 1});
  flow_test::set_data(grid);
  flow::TwoPhaseSolver<2> solver(grid, flow_test::corey_rocks(), flow::NewtonParameters());
  solver.matrix_dirichlet   = {{0, {{2e5, 2e5}}}, {1, {{1e5, 1e5}}}};
  solver.fracture_dirichlet = {{0, {{2e5, 2e5}}}, {1, {{1e5, 1e5}}}};
  for (auto &p : solver.state)
    p = {{1.5e5, 1.5e5}};
  solver.apply_dirichlet(solver.state);
  solver.begin_time_step();
  ConditionalOStream quiet(std::cout, std::getenv("V") != nullptr);
  const auto         result = solver.solve_time_step(1e6, quiet);
  std::cout << "converged: " << (result.converged ? "yes" : "no") << ", Newton iterations "
            << result.iterations << std::endl;

  double err[3] = {0, 0, 0};
  for (unsigned int i = 0; i < grid.n_nodes(); ++i)
    {
      const double exact = 2e5 - 1e5 * grid.nodes[i].centre[0];
      const double e     = std::max(std::abs(solver.state[i][0] - exact),
                                std::abs(solver.state[i][1] - solver.state[i][0]));
      const int    k     = grid.nodes[i].kind == flow::TpfaGrid<2>::NodeKind::matrix   ? 0 :
                           grid.nodes[i].kind == flow::TpfaGrid<2>::NodeKind::fracture ? 1 :
                                                                                         2;
      err[k]             = std::max(err[k], e / 1e5);
    }
  // Fracture flux: the connection from the first fracture cell to the x = 0 Dirichlet node.
  double fracture_flux = 0;
  for (const auto &c : grid.connections)
    if (c.kind == flow::TpfaGrid<2>::ConnectionKind::fracture_node &&
        grid.nodes[c.b].kind == flow::TpfaGrid<2>::NodeKind::dirichlet_fracture &&
        grid.nodes[c.b].centre[0] == 0.)
      fracture_flux = -c.transmissibility * (solver.state[c.a][0] - solver.state[c.b][0]);
  const double expected = 1e-9 / 12. * 1e5;
  // Exactness needs every circumcentre on the inner side of its boundary and fracture faces.
  std::cout << "faces with a circumcentre on the wrong side: " << grid.n_non_admissible
            << std::endl;
  const bool ok = grid.n_non_admissible == 0 && result.converged && err[0] < 1e-10 &&
                  err[1] < 1e-10 && err[2] < 1e-10 &&
                  std::abs(fracture_flux - expected) < 1e-8 * expected;
  std::cout << "max relative error, matrix cells below 1e-10: " << (err[0] < 1e-10 ? "yes" : "NO")
            << std::endl
            << "max relative error, fracture cells below 1e-10: " << (err[1] < 1e-10 ? "yes" : "NO")
            << std::endl
            << "max relative error, interface nodes below 1e-10: "
            << (err[2] < 1e-10 ? "yes" : "NO") << std::endl
            << "fracture flux (d^3/12) |grad p| (m^2/s per unit depth, / mu_w): " << std::scientific
            << std::setprecision(4) << fracture_flux << " expected " << expected << std::endl;
  return ok ? 0 : 1;
}
