// SPDX-License-Identifier: LGPL-2.1-or-later
// A massless interface node holding gas (s_nw > 0) downstream of neighbours without gas mobility
// (water-filled, linear k_r, no floor): its p^nw enters no equation, so the Jacobian row and
// column of that unknown have no entry of their own. The solver adds a Jacobian-only virtual
// compressibility on such zero diagonals. Asserted: the node's non-wetting diagonal is positive,
// the Jacobian factorizes (singular without the virtual compressibility), and the residual is the
// same with and without the Jacobian.
#include <deal.II/lac/sparse_direct.h>

#include <iostream>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

int
main()
{
  const auto        mesh = flow_test::unit_square(flow_test::xt_network, 0.2, 0.1);
  flow::TpfaGrid<2> grid(*mesh, false, {}, {});
  flow_test::set_data(grid);
  const auto              rocks = flow_test::corey_rocks();
  flow::TwoPhaseSolver<2> solver(grid, rocks, flow_test::tight_newton());

  // Both phases mobile everywhere (p_c = 500 Pa) but around one interface node: its neighbours
  // hold water only (p_c = 0) and the node gas (p_c = 3e3 Pa) at a gas pressure below theirs, so
  // it is downstream on every connection. The neighbours are downstream of the rest.
  unsigned int node = numbers::invalid_unsigned_int;
  for (unsigned int i = 0; i < grid.n_nodes() && node == numbers::invalid_unsigned_int; ++i)
    if (grid.nodes[i].kind == flow::TpfaGrid<2>::NodeKind::interface)
      node = i;
  auto state = solver.state;
  for (auto &p : state)
    p = {{1e5 + 100. - 500., 1e5 + 100.}};
  for (const auto &c : grid.connections)
    if (c.a == node || c.b == node)
      state[c.a == node ? c.b : c.a] = {{1e5, 1e5}};
  state[node]  = {{1e5 - 10. - 3e3, 1e5 - 10.}};
  solver.state = state;
  solver.begin_time_step();

  Vector<double> residual, residual_alone;
  solver.assemble(state, state, 1., residual, &solver.jacobian);
  solver.assemble(state, state, 1., residual_alone, nullptr);
  residual_alone -= residual;

  const flow::Rock rock     = grid.nodes[node].rock == 0 ? flow::matrix_rock : flow::fracture_rock;
  const double     s_nw     = solver.saturation(state, node, rock);
  const double     diagonal = solver.jacobian.diag_element(solver.dof(node, 1));
  bool             regular  = true;
  try
    {
      SparseDirectUMFPACK lu;
      lu.initialize(solver.jacobian);
    }
  catch (...)
    {
      regular = false;
    }
  std::cout << "interface node s_nw > 0.2: " << (s_nw > 0.2 ? "yes" : "NO") << std::endl
            << "its non-wetting diagonal is positive: " << (diagonal > 0 ? "yes" : "NO")
            << std::endl
            << "the Jacobian factorizes: " << (regular ? "yes" : "NO") << std::endl
            << "the residual is the same with and without the Jacobian: "
            << (residual_alone.linfty_norm() == 0 ? "yes" : "NO") << std::endl;
  return s_nw > 0.2 && diagonal > 0 && regular && residual_alone.linfty_norm() == 0 ? 0 : 1;
}
