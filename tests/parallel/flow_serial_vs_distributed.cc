// SPDX-License-Identifier: LGPL-2.1-or-later
// The distributed two-phase flow Newton (2 MPI processes: METIS partition of the cells, each
// process assembling its rows, MUMPS) against the serial one (rank 0: UMFPACK) on a drainage of
// the unit square with an X and a T intersection (gas enters through the left side and the
// fracture reaching it, water leaves on the right): 12 implicit Euler steps of growing size, at
// the default Newton tolerances (tolerances at round-off would make the last iteration depend
// on the round-off of the linear solver).
// The same Newton iteration count per step, phase pressures equal to 1e-8 relative (only the
// round-off of the linear solvers differs), the per-step mass defect below 1e-10 on both, the
// energy terms of every step (dissipation, positive, and boundary work) equal to 1e-8 relative,
// and the same state on both processes to the last bit.
// mpi: 2
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <porofrac/geometry/distributed_cut_mesh.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "../flow/flow_test_tools.h"

using namespace porofrac;
using namespace dealii;

namespace
{
  struct Run
  {
    std::vector<unsigned int>      iterations;
    std::vector<double>            mass_defect, dissipation, boundary_work;
    flow::TwoPhaseSolver<2>::State state;
  };

  /// The drainage on @p grid, distributed over @p communicator if @p cell_owner is given.
  Run
  drain(const flow::TpfaGrid<2>         &grid,
        const MPI_Comm                   communicator,
        const std::vector<unsigned int> &cell_owner)
  {
    ConditionalOStream      quiet(std::cout, false);
    const auto              rocks = flow_test::corey_rocks();
    flow::TwoPhaseSolver<2> solver(grid, rocks, flow::NewtonParameters());
    if (!cell_owner.empty())
      solver.distribute(communicator, grid.node_owners(cell_owner));
    flow_test::set_drainage(solver, rocks);
    Run    run;
    double dt = 2.;
    for (unsigned int step = 0; step < 12; ++step, dt *= 1.5)
      {
        solver.begin_time_step();
        const auto result = solver.solve_time_step(dt, quiet);
        if (!result.converged)
          throw std::runtime_error("flow step failed: " + result.failure);
        const auto e = solver.energy_exchange(solver.state, dt);
        run.iterations.push_back(result.iterations);
        run.mass_defect.push_back(std::max(result.mass_defect[0], result.mass_defect[1]));
        run.dissipation.push_back(e.dissipation);
        run.boundary_work.push_back(e.boundary_work);
      }
    run.state = solver.state;
    return run;
  }

  double
  relative_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double d = 0, scale = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        d     = std::max(d, std::abs(a[i] - b[i]));
        scale = std::max(scale, std::abs(b[i]));
      }
    return d / scale;
  }

  std::vector<double>
  flatten(const flow::TwoPhaseSolver<2>::State &s, const double offset)
  {
    std::vector<double> v;
    for (const auto &p : s)
      for (const double x : p)
        v.push_back(x + offset);
    return v;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   world = MPI_COMM_WORLD;
  const bool                       rank0 = Utilities::MPI::this_mpi_process(world) == 0;
  const auto                       mesh  = flow_test::unit_square(flow_test::xt_network, 0.1, 0.05);
  flow::TpfaGrid<2>                grid(*mesh, false, {0, 1}, {0});
  flow_test::set_data(grid);
  const auto cell_owner  = geometry::partition_cells(*mesh, world);
  const Run  distributed = drain(grid, world, cell_owner);

  // Every process holds the same state, bit for bit.
  const std::vector<double> mine = flatten(distributed.state, 0.);
  std::vector<double>       low(mine.size()), high(mine.size());
  Utilities::MPI::min(mine, world, low);
  Utilities::MPI::max(mine, world, high);
  const bool same_on_processes = low == high;
  if (!rank0)
    return same_on_processes ? 0 : 1;

  const Run    serial     = drain(grid, MPI_COMM_SELF, {});
  unsigned int owned_by_1 = 0;
  for (const unsigned int o : cell_owner)
    owned_by_1 += o;
  std::cout << "cells on process 1: " << (owned_by_1 > 0.3 * cell_owner.size() ? "yes" : "NO")
            << " (at least 30 %)" << std::endl
            << "Newton iterations per step, serial:";
  for (const unsigned int n : serial.iterations)
    std::cout << ' ' << n;
  std::cout << std::endl << "Newton iterations per step, 2 processes:";
  for (const unsigned int n : distributed.iterations)
    std::cout << ' ' << n;
  std::cout << std::endl
            << "same iteration counts on 2 processes: "
            << (serial.iterations == distributed.iterations ? "yes" : "NO") << std::endl;
  const double dp =
    relative_difference(flatten(distributed.state, 1e5), flatten(serial.state, 1e5));
  std::cout << "phase pressures equal to 1e-8 relative: " << (dp < 1e-8 ? "yes" : "NO")
            << std::endl;
  double mass = 0;
  for (unsigned int s = 0; s < serial.mass_defect.size(); ++s)
    mass = std::max({mass, serial.mass_defect[s], distributed.mass_defect[s]});
  std::cout << "mass defect of every step below 1e-10 on 1 and 2 processes: "
            << (mass < 1e-10 ? "yes" : "NO") << std::endl;
  const double de       = std::max(relative_difference(distributed.dissipation, serial.dissipation),
                             relative_difference(distributed.boundary_work, serial.boundary_work));
  bool         positive = true;
  for (const double d : distributed.dissipation)
    positive = positive && d > 0;
  std::cout << "dissipation positive and energy terms equal to 1e-8 relative: "
            << (positive && de < 1e-8 ? "yes" : "NO") << std::endl
            << "the same state on both processes: " << (same_on_processes ? "yes" : "NO")
            << std::endl;
  return 0;
}
