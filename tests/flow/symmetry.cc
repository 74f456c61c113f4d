// SPDX-License-Identifier: LGPL-2.1-or-later
// Symmetric input gives symmetric output: a drainage problem and its mirror image (mesh, network
// and boundary conditions reflected by x -> 1 - x, the inlet moving from x = 0 to x = 1) must give
// the same sorted lists of matrix and fracture pressures and saturations and the same phase
// volumes, to round-off, after several implicit Euler steps.
#include <porofrac/geometry/fracture_network.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

namespace
{
  struct Result
  {
    std::vector<double>   values;
    std::array<double, 2> volumes;
  };

  Result
  run(const geometry::CutMesh<2> &mesh,
      const types::boundary_id    inlet,
      const types::boundary_id    outlet)
  {
    flow::TpfaGrid<2> grid(mesh, false, {inlet, outlet}, {});
    flow_test::set_data(grid);
    const auto              rocks = flow_test::corey_rocks();
    flow::TwoPhaseSolver<2> solver(grid, rocks, flow_test::tight_newton());
    const double            pc_in = rocks[0].saturation->inverse(0.5, "test");
    solver.matrix_dirichlet       = {{inlet, {{2e5 - pc_in, 2e5}}}, {outlet, {{1e5, 1e5}}}};
    for (auto &p : solver.state)
      p = {{1e5, 1e5}};
    solver.apply_dirichlet(solver.state);
    solver.begin_time_step();
    ConditionalOStream quiet(std::cout, false);
    for (unsigned int step = 0; step < 5; ++step)
      {
        if (!solver.solve_time_step(20., quiet).converged)
          std::cout << "FAILED: Newton" << std::endl;
        solver.begin_time_step();
      }
    Result r;
    for (unsigned int i = 0; i < grid.n_matrix_cells + grid.n_fracture_cells; ++i)
      r.values.push_back(solver.state[i][0] + 10 * solver.state[i][1] +
                         (i < grid.n_matrix_cells ? 0. : 1e7));
    std::sort(r.values.begin(), r.values.end());
    r.volumes = solver.phase_volumes(solver.state);
    return r;
  }
} // namespace

int
main()
{
  geometry::GeometryParameters prm;
  prm.domain              = "box";
  prm.box                 = "(0, 0) (1, 1)";
  prm.fractures           = "1: (0.2, 0.4) (0.7, 0.6); 2: (0.5, 0.1) (0.5, 0.9)";
  prm.mesh_size           = 0.15;
  prm.fracture_mesh_size  = 0.075;
  prm.transition_distance = 0.1;
  prm.global_refinements  = 0;
  prm.delaunay_flips      = false;
  prm.algorithm           = "delaunay";
  auto raw                = geometry::mesh_network(geometry::network_from_parameters(prm), prm);
  auto mirror             = raw;
  for (auto &v : mirror.vertices)
    v[0] = 1. - v[0];
  for (auto &f : mirror.boundary_faces)
    if (f.tag <= 1)
      f.tag = 1 - f.tag;
  for (auto &s : mirror.fracture_start)
    s.second[0] = 1. - s.second[0];
  mirror.orient_cells();
  const geometry::CutMesh<2> mesh(raw), mirrored(mirror);

  const Result a = run(mesh, 0, 1), b = run(mirrored, 1, 0);
  double       diff = 0;
  for (unsigned int i = 0; i < a.values.size(); ++i)
    diff = std::max(diff, std::abs(a.values[i] - b.values[i]) / std::abs(a.values[i]));
  const double dv =
    std::max(std::abs(a.volumes[0] - b.volumes[0]), std::abs(a.volumes[1] - b.volumes[1])) /
    (a.volumes[0] + a.volumes[1]);
  std::cout << "non-wetting phase entered: " << (a.volumes[1] > 1e-3 ? "yes" : "NO") << std::endl
            << "mirror fields equal to 1e-9: " << (diff < 1e-9 ? "yes" : "NO") << std::endl
            << "mirror phase volumes equal to 1e-10: " << (dv < 1e-10 ? "yes" : "NO") << std::endl;
  if (std::getenv("V"))
    std::cout << diff << ' ' << dv << ' ' << a.volumes[1] << std::endl;
  return diff < 1e-9 && dv < 1e-10 && a.volumes[1] > 1e-3 ? 0 : 1;
}
