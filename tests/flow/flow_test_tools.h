// SPDX-License-Identifier: LGPL-2.1-or-later
// Shared set-up for the flow unit tests: a gmsh cut mesh of the unit square with a network.
#ifndef POROFRAC_TESTS_FLOW_TOOLS_H
#define POROFRAC_TESTS_FLOW_TOOLS_H

#include <porofrac/flow/parameters.h>
#include <porofrac/flow/rock_type.h>
#include <porofrac/flow/tpfa_grid.h>
#include <porofrac/flow/two_phase_solver.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/parameters.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace flow_test
{
  using namespace porofrac;

  inline std::unique_ptr<geometry::CutMesh<2>>
  unit_square(const std::string &fractures,
              const double       h         = 0.1,
              const double       hf        = 0.05,
              const std::string &algorithm = "delaunay")
  {
    geometry::GeometryParameters prm;
    prm.domain              = "box";
    prm.box                 = "(0, 0) (1, 1)";
    prm.fractures           = fractures;
    prm.mesh_size           = h;
    prm.fracture_mesh_size  = hf;
    prm.transition_distance = 0.1;
    prm.global_refinements  = 0;
    prm.delaunay_flips      = true; // TPFA needs ordered circumcentres (as Delaunay flips = auto)
    prm.algorithm           = algorithm;
    return geometry::make_cut_mesh<2>(prm);
  }

  /// An X and a T intersection, a corner-free network reaching the boundary (fracture 4).
  inline const char *xt_network =
    "1: (0.1, 0.5) (0.9, 0.5); 2: (0.3, 0.2) (0.3, 0.8); 3: (0.7, 0.5) (0.7, 0.2); "
    "4: (0.0, 0.85) (0.3, 0.9)";

  /// Newton tolerances tight enough that balances are checked to round-off.
  inline flow::NewtonParameters
  tight_newton()
  {
    flow::NewtonParameters newton;
    newton.residual_tolerance = 1e-13;
    newton.update_tolerance   = 1e-15;
    // These tolerances sit at round-off, where |R| stops halving: iterate to the update test.
    newton.stagnation_iterations = 0;
    return newton;
  }

  /// Corey matrix (R = 1e4 Pa) and fracture (R = 1e3 Pa), linear k_r, mu_w = 1e-3, mu_nw = 1e-4.
  inline std::array<flow::RockType, 2>
  corey_rocks()
  {
    std::array<flow::RockType, 2> rocks;
    rocks[0].saturation = flow::make_saturation_law("corey", {{"Corey R", "1e4"}});
    rocks[1].saturation = flow::make_saturation_law("corey", {{"Corey R", "1e3"}});
    for (auto &r : rocks)
      {
        r.relative_permeability = flow::make_relative_permeability("linear");
        r.viscosity[0]          = 1e-3;
        r.viscosity[1]          = 1e-4;
      }
    return rocks;
  }

  /// Porosity 0.2, permeability @p permeability, aperture @p aperture, Lambda_f = 1e-10.
  template <int dim>
  void
  set_data(flow::TpfaGrid<dim> &grid,
           const double         aperture     = 1e-3,
           const double         permeability = 1e-12)
  {
    grid.porosity.assign(grid.n_matrix_cells, 0.2);
    grid.permeability.assign(grid.n_matrix_cells, permeability);
    grid.aperture.assign(grid.n_fracture_cells, aperture);
    grid.normal_transmissibility = 1e-10;
    grid.update_transmissibilities();
  }

  /// The unit cube meshed by gmsh with 3D polygon @p fractures, or, with @p structured
  /// ("n, n, n"), a Kuhn-split Cartesian grid.
  inline std::unique_ptr<geometry::CutMesh<3>>
  unit_cube(const std::string &fractures,
            const double       h          = 0.25,
            const double       hf         = 0.125,
            const std::string &structured = "")
  {
    geometry::GeometryParameters prm;
    prm.domain              = "box";
    prm.box                 = "(0, 0, 0) (1, 1, 1)";
    prm.fractures           = fractures;
    prm.mesh_size           = h;
    prm.fracture_mesh_size  = hf;
    prm.transition_distance = 0.2;
    prm.structured_cells    = structured;
    return geometry::make_cut_mesh<3>(prm);
  }

  /**
   * max |J - J_FD| / max |J| of the analytic Jacobian of @p solver at @p state (old state
   * @p old, time step @p dt) against centred differences (step 1e-2 Pa); an entry missing from
   * the sparsity pattern is reported.
   */
  template <int dim>
  double
  jacobian_error(flow::TwoPhaseSolver<dim>                       &solver,
                 const typename flow::TwoPhaseSolver<dim>::State &state,
                 const typename flow::TwoPhaseSolver<dim>::State &old,
                 const double                                     dt)
  {
    // PV_old is the pore volume at begin_time_step(): store it for the old state.
    solver.state = old;
    solver.begin_time_step();
    dealii::Vector<double> r0, rp, rm;
    solver.assemble(state, old, dt, r0, &solver.jacobian);
    double err = 0, jmax = 0;
    for (unsigned int i = 0; i < solver.grid.n_nodes(); ++i)
      for (unsigned int phase = 0; phase < 2; ++phase)
        {
          const unsigned int col = solver.dof(i, phase);
          if (col == dealii::numbers::invalid_unsigned_int)
            continue;
          const double h  = 1e-2;
          auto         sp = state, sm = state;
          sp[i][phase] += h;
          sm[i][phase] -= h;
          solver.assemble(sp, old, dt, rp, nullptr);
          solver.assemble(sm, old, dt, rm, nullptr);
          for (unsigned int row = 0; row < r0.size(); ++row)
            {
              const double fd = (rp(row) - rm(row)) / (2 * h);
              const double an =
                solver.sparsity.exists(row, col) ? solver.jacobian.el(row, col) : 0.;
              if (fd != 0 && !solver.sparsity.exists(row, col))
                std::cout << "FAILED: entry (" << row << ", " << col << ") missing from the pattern"
                          << std::endl;
              err  = std::max(err, std::abs(fd - an));
              jmax = std::max(jmax, std::abs(an));
            }
        }
    return err / jmax;
  }

  /// Drainage from the left (boundary 0: matrix s_nw = 0.5, fractures s_nw = 0.9, p_nw = 2e5)
  /// to the right (boundary 1: water at 1e5 Pa), water at 1e5 Pa inside.
  inline void
  set_drainage(flow::TwoPhaseSolver<2> &solver, const std::array<flow::RockType, 2> &rocks)
  {
    const double pc_in        = rocks[0].saturation->inverse(0.5, "test");
    solver.matrix_dirichlet   = {{0, {{2e5 - pc_in, 2e5}}}, {1, {{1e5, 1e5}}}};
    solver.fracture_dirichlet = {{0, {{2e5 - rocks[1].saturation->inverse(0.9, "test"), 2e5}}}};
    for (auto &p : solver.state)
      p = {{1e5, 1e5}};
    solver.apply_dirichlet(solver.state);
  }
} // namespace flow_test

#endif
