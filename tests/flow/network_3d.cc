// SPDX-License-Identifier: LGPL-2.1-or-later
// Two-phase TPFA on 3D fracture networks (fracture-fracture connections through the edges of the
// fracture triangles, intersection-line unknowns, Dirichlet boundary edges):
// 1. a gmsh cube with two fractures crossing along an intersection line and a third reaching
//    the Dirichlet face x = 0: the analytic Jacobian against finite differences at a
//    pseudo-random two-phase state, then three drainage steps with the mass of each phase
//    balanced to 1e-10 per step;
// 2. a Kuhn-split Cartesian grid with the fracture z = 0.5 across the cube, fixed fracture
//    pressures on x = 0 and x = 1 and an impermeable matrix: the fracture carries
//    (d^3/12)/mu_w |grad p| per unit width (the two triangles of a grid square share their
//    circumcentre, so the fracture TPFA is the Cartesian one: exact up to the 1e-5 distance
//    that keeps the pair together).
#include <porofrac/flow/boundary_fluxes.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

namespace
{
  bool
  network_checks()
  {
    const auto mesh =
      flow_test::unit_cube("1: (0.2, 0.2, 0.5) (0.8, 0.2, 0.5) (0.8, 0.8, 0.5) (0.2, 0.8, 0.5); "
                           "2: (0.5, 0.3, 0.2) (0.5, 0.7, 0.2) (0.5, 0.7, 0.8) (0.5, 0.3, 0.8); "
                           "3: (0, 0.1, 0.1) (0.3, 0.1, 0.1) (0.3, 0.1, 0.4) (0, 0.1, 0.4)");
    flow::TpfaGrid<3> grid(*mesh, false, {0, 1}, {0}, flow::TpfaGrid<3>::Centres::centroid);
    flow_test::set_data(grid);
    const auto             rocks = flow_test::corey_rocks();
    flow::NewtonParameters newton;
    newton.entry_slope = false;
    flow::TwoPhaseSolver<3> solver(grid, rocks, newton);
    solver.matrix_dirichlet   = {{0, {{1.2e5, 1.25e5}}}, {1, {{1e5, 1.01e5}}}};
    solver.fracture_dirichlet = {{0, {{1.1e5, 1.12e5}}}};
    std::cout << "intersection nodes: " << (grid.n_intersections > 0 ? "some" : "NONE")
              << ", Dirichlet fracture nodes: ";
    unsigned int n_dirichlet_fracture = 0;
    for (const auto &node : grid.nodes)
      n_dirichlet_fracture += node.kind == flow::TpfaGrid<3>::NodeKind::dirichlet_fracture ? 1 : 0;
    std::cout << (n_dirichlet_fracture > 0 ? "some" : "NONE") << std::endl;

    unsigned int seed = 4321;
    auto         rnd  = [&seed]() {
      seed = 1103515245u * seed + 12345u;
      return (seed >> 8) / double(1u << 24);
    };
    auto state = solver.state;
    for (auto &p : state)
      {
        p[0] = 1e5 + 2e4 * rnd();
        p[1] = p[0] + 200. + 3e3 * rnd();
      }
    solver.apply_dirichlet(state);
    auto old = state;
    for (auto &p : old)
      p[1] += 500. * rnd();
    const double rel = flow_test::jacobian_error(solver, state, old, 50.);
    std::cout << "max |J - J_FD| / max |J| below 1e-6: " << (rel < 1e-6 ? "yes" : "NO")
              << std::endl;

    flow::TwoPhaseSolver<3> drainage(grid, rocks, flow::NewtonParameters());
    drainage.matrix_dirichlet   = {{0, {{1.2e5, 1.3e5}}}, {1, {{1e5, 1e5}}}};
    drainage.fracture_dirichlet = {{0, {{1.2e5, 1.3e5}}}};
    for (auto &p : drainage.state)
      p = {{1e5, 1e5}};
    drainage.apply_dirichlet(drainage.state);
    drainage.begin_time_step();
    ConditionalOStream quiet(std::cout, false);
    double             mass      = 0;
    bool               converged = true;
    for (unsigned int step = 0; step < 3; ++step)
      {
        const auto result = drainage.solve_time_step(500., quiet);
        converged         = converged && result.converged;
        mass              = std::max({mass, result.mass_defect[0], result.mass_defect[1]});
        drainage.begin_time_step();
      }
    const double nw = drainage.phase_volumes(drainage.state)[1];
    std::cout << "three drainage steps converged: " << (converged ? "yes" : "NO")
              << ", non-wetting phase entered: " << (nw > 0 ? "yes" : "NO")
              << ", mass defect of each phase below 1e-10: " << (mass < 1e-10 ? "yes" : "NO")
              << std::endl;
    return grid.n_intersections > 0 && n_dirichlet_fracture > 0 && rel < 1e-6 && converged &&
           nw > 0 && mass < 1e-10;
  }



  bool
  channel_checks()
  {
    const auto mesh =
      flow_test::unit_cube("1: (0, 0, 0.5) (1, 0, 0.5) (1, 1, 0.5) (0, 1, 0.5)", 1, 1, "4, 4, 4");
    flow::TpfaGrid<3> grid(*mesh, false, {}, {0, 1});
    flow_test::set_data(grid, 1e-3, 1e-24);
    flow::TwoPhaseSolver<3> solver(grid, flow_test::corey_rocks(), flow_test::tight_newton());
    solver.fracture_dirichlet = {{0, {{2e5, 2e5}}}, {1, {{1e5, 1e5}}}};
    for (auto &p : solver.state)
      p = {{1.5e5, 1.5e5}};
    solver.apply_dirichlet(solver.state);
    solver.begin_time_step();
    ConditionalOStream quiet(std::cout, false);
    const auto         result   = solver.solve_time_step(1e6, quiet);
    const auto         balances = flow::boundary_balances(*mesh, solver, {}, false);
    const double       expected = 1e-9 / 12. / 1e-3 * 1e5;
    const double       error    = std::abs(balances.at(1).outflow[0] - expected) / expected;
    if (std::getenv("V"))
      std::cout << balances.at(1).outflow[0] << " " << expected << " " << balances.at(0).outflow[0]
                << std::endl;
    std::cout << "channel: converged " << (result.converged ? "yes" : "NO")
              << ", fracture outflow (d^3/12)/mu_w |grad p| to 1e-4: "
              << (error < 1e-4 ? "yes" : "NO") << std::endl;
    return result.converged && error < 1e-4;
  }
} // namespace



int
main()
{
  const bool network = network_checks();
  const bool channel = channel_checks();
  return network && channel ? 0 : 1;
}
