// SPDX-License-Identifier: LGPL-2.1-or-later
// Mirror symmetry in 3D: two fractures x = 1/2 and y = 1/2 crossing along the line x = y = 1/2
// (an X intersection line), gas entering through z = 0 (s_nw = 0.5) and water leaving through
// z = 1, on a Kuhn-split Cartesian grid (invariant under x <-> y) with circumcentres. The set-up
// is symmetric under the mirror x <-> y, so after several implicit Euler steps every matrix and
// fracture cell must have the phase pressures of its mirror cell, to round-off.
#include <porofrac/flow/boundary_fluxes.h>

#include <cmath>
#include <iostream>
#include <map>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

namespace
{
  using Key = std::array<long, 3>;

  Key
  key(const Point<3> &x)
  {
    return {{std::lround(x[0] * 1e6), std::lround(x[1] * 1e6), std::lround(x[2] * 1e6)}};
  }

  /// Cell centroids (matrix cells, then fracture faces) as keys, with their node index.
  std::map<Key, unsigned int>
  centroid_keys(const geometry::CutMesh<3> &mesh, const flow::TpfaGrid<3> &grid)
  {
    std::map<Key, unsigned int> keys;
    for (const auto &cell : mesh.triangulation.active_cell_iterators())
      keys[key(cell->center())] = cell->active_cell_index();
    for (unsigned int s = 0; s < grid.n_fracture_cells; ++s)
      keys[key(mesh.fracture_faces[s].centre)] = grid.n_matrix_cells + s;
    return keys;
  }
} // namespace

int
main()
{
  const auto mesh = flow_test::unit_cube(
    "1: (0.5, 0.16666666666666667, 0.16666666666666667) (0.5, 0.83333333333333333, "
    "0.16666666666666667) (0.5, 0.83333333333333333, 0.83333333333333333) (0.5, "
    "0.16666666666666667, 0.83333333333333333); "
    "2: (0.16666666666666667, 0.5, 0.16666666666666667) (0.83333333333333333, 0.5, "
    "0.16666666666666667) (0.83333333333333333, 0.5, 0.83333333333333333) "
    "(0.16666666666666667, 0.5, 0.83333333333333333)",
    1,
    1,
    "6, 6, 6");
  flow::TpfaGrid<3> grid(*mesh, false, {4, 5}, {}, flow::TpfaGrid<3>::Centres::circumcentre);
  flow_test::set_data(grid, 1e-4);
  const auto              rocks = flow_test::corey_rocks();
  flow::TwoPhaseSolver<3> solver(grid, rocks, flow::NewtonParameters());
  const double            pc_in = rocks[0].saturation->inverse(0.5, "test");
  solver.matrix_dirichlet       = {{4, {{2e5 - pc_in, 2e5}}}, {5, {{1e5, 1e5}}}};
  for (auto &p : solver.state)
    p = {{1e5, 1e5}};
  solver.apply_dirichlet(solver.state);
  solver.begin_time_step();
  ConditionalOStream quiet(std::cout, false);
  bool               converged = true;
  for (unsigned int step = 0; step < 4; ++step)
    {
      converged = converged && solver.solve_time_step(200., quiet).converged;
      solver.begin_time_step();
    }

  const auto   keys      = centroid_keys(*mesh, grid);
  double       asymmetry = 0, scale = 0;
  unsigned int unmatched = 0;
  for (const auto &[k, i] : keys)
    {
      const auto mirror = keys.find({{k[1], k[0], k[2]}});
      if (mirror == keys.end())
        {
          ++unmatched;
          continue;
        }
      for (unsigned int phase = 0; phase < 2; ++phase)
        {
          asymmetry =
            std::max(asymmetry,
                     std::abs(solver.state[i][phase] - solver.state[mirror->second][phase]));
          scale = std::max(scale, std::abs(solver.state[i][phase]));
        }
    }
  const double nw = solver.phase_volumes(solver.state)[1];
  std::cout << "intersection nodes: " << grid.n_intersections << ", fracture cells "
            << grid.n_fracture_cells << std::endl
            << "four drainage steps converged: " << (converged ? "yes" : "NO")
            << ", non-wetting phase entered: " << (nw > 0 ? "yes" : "NO") << std::endl
            << "every cell has its mirror cell: " << (unmatched == 0 ? "yes" : "NO") << std::endl
            << "max |p(x, y, z) - p(y, x, z)| / max |p| below 1e-12: "
            << (asymmetry < 1e-12 * scale ? "yes" : "NO") << std::endl;
  return converged && nw > 0 && unmatched == 0 && asymmetry < 1e-12 * scale ? 0 : 1;
}
