// SPDX-License-Identifier: LGPL-2.1-or-later
// The analytic Newton Jacobian of the two-phase TPFA residual (exact mode, entry slope off)
// against centred finite differences, on a network with an X and a T intersection and a fracture
// reaching a Dirichlet boundary; van Genuchten-Mualem matrix, linear fracture k_r; a
// pseudo-random two-phase state (p_c > 0 everywhere, both upwind directions present); then with
// the Biot storage of eq. (11d) (porosity depending on p^E, with and without U).
#include <deal.II/lac/full_matrix.h>

#include <porofrac/coupling/biot_storage.h>
#include <porofrac/coupling/closure.h>

#include <cmath>
#include <iostream>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

int
main()
{
  const auto        mesh = flow_test::unit_square(flow_test::xt_network, 0.2, 0.1);
  flow::TpfaGrid<2> grid(*mesh, false, {0, 1}, {0});
  flow_test::set_data(grid);
  auto rocks = flow_test::corey_rocks();
  rocks[0].relative_permeability =
    flow::make_relative_permeability("van genuchten-mualem",
                                     {{"Mualem q", "0.5"}, {"S_lr", "0.1"}, {"S_gr", "0.05"}});
  flow::NewtonParameters newton;
  newton.entry_slope = false;
  flow::TwoPhaseSolver<2> solver(grid, rocks, newton);
  solver.matrix_dirichlet   = {{0, {{1.2e5, 1.25e5}}}, {1, {{1e5, 1.01e5}}}};
  solver.fracture_dirichlet = {{0, {{1.1e5, 1.12e5}}}};

  std::cout << "nodes " << grid.n_nodes() << ", intersections " << grid.n_intersections
            << ", unknowns " << solver.n_unknowns() << std::endl;

  unsigned int seed = 12345;
  auto         rnd  = [&seed]() {
    seed = 1103515245u * seed + 12345u;
    return (seed >> 8) / double(1u << 24);
  };
  auto state = solver.state;
  for (unsigned int i = 0; i < grid.n_nodes(); ++i)
    {
      state[i][0] = 1e5 + 2e4 * rnd();
      state[i][1] = state[i][0] + 200. + 3e3 * rnd(); // p_c in (200, 3200) Pa
    }
  solver.apply_dirichlet(state);
  auto old = state;
  for (unsigned int i = 0; i < grid.n_nodes(); ++i)
    old[i][1] += 500. * rnd();
  const double dt = 50.;

  const auto check = [&](flow::TwoPhaseSolver<2> &solver) {
    return flow_test::jacobian_error(solver, state, old, dt);
  };
  const double rel = check(solver);
  std::cout << "max |J - J_FD| / max |J| below 1e-6: " << (rel < 1e-6 ? "yes" : "NO") << std::endl;

  // Biot storage (eq. (11d)): phi_K = phi_base,K + (p^E_K - p^E_ref,K)/M depends on the unknowns,
  // with and without the capillary energy U in p^E; 1/M large enough that phi varies by ~0.02.
  std::vector<double> phi_base(grid.n_matrix_cells), p_E_ref(grid.n_matrix_cells);
  for (unsigned int K = 0; K < grid.n_matrix_cells; ++K)
    {
      phi_base[K] = 0.15 + 0.1 * rnd();
      p_E_ref[K]  = 1e5 + 2e4 * rnd();
    }
  bool biot_ok = true;
  for (const bool capillary_energy : {true, false})
    {
      const auto storage = std::make_shared<coupling::BiotStorage<2>>(
        grid, rocks[0].saturation, 1e-6, capillary_energy, p_E_ref, phi_base);
      solver.set_storage_model(storage);
      const double rel_biot = check(solver);
      // The porosity and p^E agree with their definitions.
      double phi_err = 0;
      for (unsigned int K = 0; K < grid.n_matrix_cells; ++K)
        {
          const auto  &law = *rocks[0].saturation;
          const double pc  = state[K][1] - state[K][0];
          const double S   = law.saturation(pc);
          const double pE =
            (1 - S) * state[K][0] + S * state[K][1] - (capillary_energy ? law.energy(pc) : 0.);
          phi_err = std::max(
            {phi_err,
             std::abs(coupling::equivalent_pressure(law, state[K][0], pc, capillary_energy) - pE) /
               1e5,
             std::abs(storage->porosity(K, state[K][0], pc) -
                      (phi_base[K] + (pE - p_E_ref[K]) * 1e-6))});
        }
      biot_ok = biot_ok && rel_biot < 1e-6 && phi_err < 1e-12;
      std::cout << "Biot storage, capillary energy " << (capillary_energy ? "on" : "off")
                << ": max |J - J_FD| / max |J| below 1e-6: " << (rel_biot < 1e-6 ? "yes" : "NO")
                << ", porosity and p^E as defined: " << (phi_err < 1e-12 ? "yes" : "NO")
                << std::endl;
    }
  Vector<double> r0;
  solver.assemble(state, old, dt, r0, nullptr);

  // With the entry slope the Jacobian differs only where p_c <= 0: identical here.
  flow::NewtonParameters  n2;
  flow::TwoPhaseSolver<2> solver2(grid, rocks, n2);
  solver2.matrix_dirichlet   = solver.matrix_dirichlet;
  solver2.fracture_dirichlet = solver.fracture_dirichlet;
  solver2.set_storage_model(std::make_shared<coupling::BiotStorage<2>>(
    grid, rocks[0].saturation, 1e-6, false, p_E_ref, phi_base));
  solver2.state = old;
  solver2.begin_time_step();
  Vector<double> r2;
  solver2.assemble(state, old, dt, r2, &solver2.jacobian);
  r2 -= r0;
  std::cout << "residual independent of the Jacobian mode: "
            << (r2.linfty_norm() == 0 ? "yes" : "NO") << std::endl;
  return rel < 1e-6 && biot_ok && r2.linfty_norm() == 0 ? 0 : 1;
}
