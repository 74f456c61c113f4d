// SPDX-License-Identifier: LGPL-2.1-or-later
// The coupling API of TwoPhaseSolver:
// 1. energy_exchange: single-phase linear flow (p = 2e5 - 1e5 x, no Dirichlet-to-Dirichlet
//    connections) supplies the boundary work dt Q (p_in - p_out), Q = (K/mu + d_f^3/(12 mu)) dp;
//    the dissipation over interior connections is positive and smaller.
// 2. Discrete energy identity of a closed network (no Dirichlet node) with Biot storage:
//    sum_i sum_alpha p^alpha_i ((PV s^alpha)_i - (PV_old s^alpha_old)_i) + dissipation = 0
//    (Biot storage of eq. (11d): coupling::BiotStorage as the solver's storage model).
// 3. Mass conservation when the aperture and the displacement porosity change between steps
//    (begin_time_step() stores the old pore volumes): per-step mass defect below 1e-10.
// 4. A failed step returns converged = false (non-finite state), without an exception.
#include <porofrac/coupling/biot_storage.h>

#include <cmath>
#include <iostream>
#include <limits>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

int
main()
{
  ConditionalOStream quiet(std::cout, false);
  bool               ok = true;
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
    const double dt        = 1e6;
    const bool   converged = solver.solve_time_step(dt, quiet).converged;
    const auto   e         = solver.energy_exchange(solver.state, dt);
    const double Q         = (1e-12 + 1e-9 / 12.) / 1e-3 * 1e5; // m^2/s per unit depth
    const double expected  = dt * Q * 1e5;
    const bool   work_ok   = converged && std::abs(e.boundary_work - expected) < 1e-8 * expected;
    const bool   diss_ok   = e.dissipation > 0.5 * expected && e.dissipation < e.boundary_work;
    std::cout << "boundary work dt Q (p_in - p_out) of linear flow: " << (work_ok ? "yes" : "NO")
              << std::endl
              << "0.5 boundary work < dissipation < boundary work: " << (diss_ok ? "yes" : "NO")
              << std::endl;
    ok = ok && work_ok && diss_ok;
  }

  const auto mesh  = flow_test::unit_square(flow_test::xt_network, 0.1, 0.05);
  const auto rocks = flow_test::corey_rocks();
  {
    flow::TpfaGrid<2> grid(*mesh, false, {}, {});
    flow_test::set_data(grid);
    flow::TwoPhaseSolver<2> solver(grid, rocks, flow_test::tight_newton());
    std::vector<double>     phi_base(grid.n_matrix_cells, 0.2), p_E_ref(grid.n_matrix_cells, 1e5);
    solver.set_storage_model(std::make_shared<coupling::BiotStorage<2>>(
      grid, rocks[flow::matrix_rock].saturation, 1e-7, true, p_E_ref, phi_base));
    // Gas (p_c = 2e4 Pa) in the left quarter, water elsewhere.
    for (unsigned int i = 0; i < grid.n_nodes(); ++i)
      solver.state[i] = grid.nodes[i].centre[0] < 0.25 ? std::array<double, 2>{{1e5, 1.2e5}} :
                                                         std::array<double, 2>{{1e5, 1e5}};
    double identity_max = 0, dissipation = 0;
    bool   converged = true;
    for (unsigned int step = 0; step < 4; ++step)
      {
        std::vector<double> pv_old(grid.n_nodes());
        for (unsigned int i = 0; i < grid.n_nodes(); ++i)
          pv_old[i] = solver.pore_volume(solver.state, i);
        solver.begin_time_step();
        const double dt = 20.;
        converged       = converged && solver.solve_time_step(dt, quiet).converged;
        const auto e    = solver.energy_exchange(solver.state, dt);
        double     sum  = e.dissipation;
        for (unsigned int i = 0; i < grid.n_nodes(); ++i)
          {
            const unsigned int rock  = grid.nodes[i].rock;
            const double       S     = solver.saturation(solver.state, i, flow::Rock(rock));
            const double       S_old = solver.saturation(solver.old_state, i, flow::Rock(rock));
            const double       PV    = solver.pore_volume(solver.state, i);
            sum += solver.state[i][1] * (PV * S - pv_old[i] * S_old) +
                   solver.state[i][0] * (PV * (1 - S) - pv_old[i] * (1 - S_old));
          }
        identity_max = std::max(identity_max, std::abs(sum) / e.dissipation);
        dissipation += e.dissipation;
        ok = ok && e.boundary_work == 0;
      }
    const bool id_ok = converged && identity_max < 1e-8 && dissipation > 0;
    std::cout << "closed network with Biot storage: energy identity to 1e-8 of the dissipation: "
              << (id_ok ? "yes" : "NO") << std::endl;
    ok = ok && id_ok;
  }
  {
    flow::TpfaGrid<2> grid(*mesh, false, {0, 1}, {0});
    flow_test::set_data(grid);
    flow::TwoPhaseSolver<2> solver(grid, rocks, flow_test::tight_newton());
    flow_test::set_drainage(solver, rocks);
    std::vector<double> phi_base(grid.n_matrix_cells, 0.2), p_E_ref(grid.n_matrix_cells, 1e5);
    const auto          storage = std::make_shared<coupling::BiotStorage<2>>(
      grid, rocks[flow::matrix_rock].saturation, 1e-7, false, p_E_ref, phi_base);
    solver.set_storage_model(storage);
    double mass_max  = 0;
    bool   converged = true;
    for (unsigned int step = 0; step < 5; ++step)
      {
        solver.begin_time_step();
        // The mechanics opens the fractures and dilates the matrix between steps.
        for (auto &d : grid.aperture)
          d *= 1.1;
        grid.update_transmissibilities();
        for (auto &phi : phi_base)
          phi += 0.002;
        storage->set_displacement_porosity(phi_base);
        const auto r = solver.solve_time_step(20., quiet);
        converged    = converged && r.converged;
        mass_max     = std::max({mass_max, r.mass_defect[0], r.mass_defect[1]});
      }
    const bool mass_ok = converged && mass_max < 1e-10;
    std::cout << "aperture and porosity changing between steps: mass defect below 1e-10: "
              << (mass_ok ? "yes" : "NO") << std::endl;
    ok = ok && mass_ok;

    solver.begin_time_step();
    solver.state[grid.n_matrix_cells][0] = std::numeric_limits<double>::quiet_NaN();
    bool failed                          = false;
    try
      {
        failed = !solver.solve_time_step(20., quiet).converged;
      }
    catch (...)
      {
        failed = false;
      }
    std::cout << "non-finite state: converged = false, no exception: " << (failed ? "yes" : "NO")
              << std::endl;
    ok = ok && failed;
  }
  return ok ? 0 : 1;
}
