// SPDX-License-Identifier: LGPL-2.1-or-later
// Symmetric input gives symmetric output, for the coupled solver (two-phase flow + frictional
// contact, Physics = poromechanics, fixed point on p_E). The scene is mirror-symmetric about
// x = 1: the box [0, 2] x [0, 1] with a "V" of two fractures meeting on the axis (symmetry.geo),
// gas entering through the top (matrix s_nw = 0.5 at p_nw = 2e5 Pa), water leaving at the bottom
// (p_w = 1e5 Pa), u = 0 at the bottom, a 0.2 MPa pressure on the top, friction F = 0.5: as the
// gas arrives, the upper parts of the arms open and the lower parts slip. The mesh itself is
// mirror-symmetric (gmsh periodic surfaces through a reflection; vertex coordinates agree to
// ~1e-12), so after 11 coupled steps (600 s) the fields at mirrored places must agree to
// round-off. The test builds the coupled problem as app::run_poromechanics_scene does (same inner
// flow tolerances, same time loop) but drives coupling::Poromechanics itself, to read the matrix
// fields. Each fracture face and each matrix cell is paired with the one whose centre is its
// mirror image, and compared:
//   fracture faces: [u]_n, lambda_n, aperture, p_w, p_nw, s_nw, p_E equal; the tangential jump
//     and multiplier change sign (a tangential component is odd under a reflection, whichever
//     way each fracture is oriented); the face states (open/stick/slip) equal;
//   matrix cells: p_w, p_nw, s_nw, p_E, porosity (hence div u) equal; the cell mean of u_x
//     changes sign, that of u_y is equal.
// Printed per field: its scale (largest |value|; for a component of [u], lambda or u, the largest
// norm of the vector) and the largest mirror difference relative to it; then whether the largest
// of these is below 1e-8 with every place paired and every face state equal, and that the scene
// is not trivially symmetric (gas in the matrix and in the fractures, open and slipping faces).
// The program exits with status 1 if not.
//
// The test can fail: extra "Section/Name=value" arguments override the scene, e.g.
//   test-coupling-symmetry "Mechanics/Normal pressure=13: 2e5 * (1 + 1e-3 * x)"
// loads the top slightly more on the right and must print "no".
// The printed asymmetries are round-off (~1e-12, that of the mesh); numdiff compares them to an
// absolute 1e-8 only, the tolerance itself is asserted by the yes/no line and the exit status.
// numdiff: -a 1e-8 -r 1e-6
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <porofrac/app/parameters.h>
#include <porofrac/coupling/parameters.h>
#include <porofrac/coupling/poromechanics.h>
#include <porofrac/flow/model.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/io/deck.h>
#include <porofrac/mechanics/contact_problem.h>
#include <porofrac/mechanics/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace dealii;
using namespace porofrac;

namespace
{
  const std::vector<std::string> scene = {
    "Physics=poromechanics", // for the record: main builds the coupled problem itself
    "Geometry/Domain=mesh file",
    // (Geometry/Mesh file is set in main)
    "Mechanics/Young modulus=1e9",
    "Mechanics/Poisson ratio=0.25",
    "Mechanics/Dirichlet=12: x=0, y=0",
    "Mechanics/Normal pressure=13: 2e5",
    "Mechanics/Friction coefficient=0.5",
    "Mechanics/Complementarity parameter c=1e9",
    "Coupling/Biot coefficient=0.8",
    "Coupling/Biot modulus=1e9",
    "Flow/Viscosity w=1e-3",
    "Flow/Viscosity nw=1e-4",
    "Flow/Final time=600",
    "Flow/Initial time step=20",
    "Flow/Maximum time step=100",
    "Flow/Time step growth=1.2",
    "Flow/Matrix/Porosity=0.2",
    "Flow/Matrix/Permeability=1e-12",
    "Flow/Matrix/Saturation law=corey",
    "Flow/Matrix/Corey R=1e4",
    "Flow/Matrix/Relative permeability=linear",
    "Flow/Matrix/Initial pressure w=1e5",
    "Flow/Matrix/Initial pressure nw=1e5",
    "Flow/Fracture/Aperture=1e-3",
    "Flow/Fracture/Normal transmissibility=1e-10",
    "Flow/Fracture/Saturation law=corey",
    "Flow/Fracture/Corey R=1e3",
    "Flow/Fracture/Relative permeability=linear",
    "Flow/Fracture/Initial pressure w=1e5",
    "Flow/Fracture/Initial pressure nw=1e5",
    "Flow/Boundary conditions/Matrix=13: s_nw = 0.5, p_nw = 2e5; 12: s_w = 1, p_w = 1e5",
  };

  /// Largest |value| of a field and largest difference between a value and its mirror's image.
  struct Asymmetry
  {
    double scale = 0, difference = 0;
    /// @p a at one place, @p b the image (sign applied) of the value at the mirrored place;
    /// @p size, if given, the norm of the vector @p a is a component of (it enters the scale, so
    /// that a component that is round-off everywhere, e.g. [u]_n with every face closed, is not
    /// divided by its own round-off).
    void
    add(const double a, const double b, const double size = 0)
    {
      scale      = std::max({scale, std::abs(a), std::abs(b), size});
      difference = std::max(difference, std::abs(a - b));
    }
    double
    relative() const
    {
      return scale > 0 ? difference / scale : 0.;
    }
  };

  /// For each point, the index of the point at its mirror image about x = 1 (or invalid).
  std::vector<unsigned int>
  mirror_pairs(const std::vector<Point<2>> &points)
  {
    std::vector<unsigned int> pair(points.size(), numbers::invalid_unsigned_int);
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const Point<2> image(2. - points[i][0], points[i][1]);
        for (unsigned int j = 0; j < points.size(); ++j)
          if (j != i && image.distance(points[j]) < 1e-8)
            pair[i] = j;
      }
    return pair;
  }
} // namespace

int
main(int argc, char **argv)
{
  ParameterHandler prm;
  app::declare_all_parameters(prm);
  io::Deck          deck(prm);
  const std::string directory = std::filesystem::path(__FILE__).parent_path().string();
  for (const auto &s : scene)
    deck.set(s);
  deck.set("Geometry/Mesh file=" + directory + "/symmetry.geo");
  for (int i = 1; i < argc; ++i)
    deck.set(std::string(argv[i]));

  geometry::GeometryParameters geometry_parameters;
  geometry_parameters.parse_parameters(prm, directory);
  const auto  cut  = geometry::make_cut_mesh<2>(geometry_parameters);
  const auto &mesh = *cut;

  ConditionalOStream           quiet(std::cout, false);
  TimerOutput                  timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  coupling::CouplingParameters coupling_parameters;
  coupling_parameters.parse_parameters(prm);
  // As app::run_poromechanics_scene: tight inner flow solves.
  flow::FlowParameters flow_parameters;
  flow_parameters.parse_parameters(prm);
  flow::FlowModel<2> flow =
    flow::make_flow_model<2>(flow_parameters, mesh, [&](flow::NewtonParameters &n) {
      n.stagnation_update_tolerance = n.update_tolerance;
      n.stagnation_mass_tolerance   = 1e-10;
      n.residual_tolerance =
        std::min(n.residual_tolerance, coupling_parameters.inner_flow_residual_tolerance);
      n.update_tolerance =
        std::min(n.update_tolerance, coupling_parameters.inner_flow_update_tolerance);
    });
  mechanics::ContactParameters mechanics_parameters;
  mechanics_parameters.parse_parameters(prm, 2);
  mechanics::ContactProblem<2> mech(mesh, mechanics_parameters, quiet, timer);
  mech.setup();
  coupling::Poromechanics<2> pm(mech, flow, coupling_parameters, quiet, timer);
  pm.initialize();

  // The time loop of app::run_poromechanics_scene: dt grows by the factor up to the maximum step,
  // and is halved when a coupled step fails.
  const flow::TimeStepping &stepping = flow.stepping;
  double                    t = 0, dt = stepping.initial_step;
  unsigned int              steps = 0, cuts = 0;
  while (t < stepping.final_time * (1 - 1e-12))
    {
      double dt_step = std::min(dt, stepping.final_time - t);
      while (!pm.solve_time_step(dt_step).converged)
        {
          if (++cuts > stepping.maximum_cuts)
            {
              std::cout << "FAILED: coupled step at t = " << t << std::endl;
              return 1;
            }
          dt_step /= 2;
        }
      pm.accept_time_step();
      t += dt_step;
      ++steps;
      dt = std::min(stepping.growth * dt_step, stepping.maximum_step);
    }

  const auto        &grid   = *flow.grid;
  const auto        &solver = *flow.solver;
  const unsigned int n = grid.n_matrix_cells, nf = grid.n_fracture_cells;

  // Fracture faces.
  std::vector<Point<2>> face_centres;
  for (const auto &face : mesh.fracture_faces)
    face_centres.push_back(face.centre);
  const auto                       face_pair = mirror_pairs(face_centres);
  std::map<std::string, Asymmetry> faces;
  unsigned int                     unpaired = 0, state_mismatches = 0;
  std::array<unsigned int, 3>      states{{0, 0, 0}};
  double                           max_slip = 0, max_s_nw_fracture = 0;
  for (unsigned int f = 0; f < nf; ++f)
    {
      const unsigned int g = face_pair[f];
      ++states[static_cast<unsigned int>(mech.state(f))];
      max_s_nw_fracture =
        std::max(max_s_nw_fracture, solver.saturation(solver.state, n + f, flow::fracture_rock));
      if (g == numbers::invalid_unsigned_int)
        {
          ++unpaired;
          continue;
        }
      const Tensor<2, 2> Rf = mech.frame(f), Rg = mech.frame(g);
      const Tensor<1, 2> jf = Rf * mech.jump(f), jg = Rg * mech.jump(g);
      const Tensor<1, 2> lf = Rf * mech.multiplier(f), lg = Rg * mech.multiplier(g);
      max_slip = std::max(max_slip, std::abs(jf[1]));
      faces["[u]_n"].add(jf[0], jg[0], jf.norm());
      faces["[u]_t (sign flipped)"].add(jf[1], -jg[1], jf.norm());
      faces["lambda_n"].add(lf[0], lg[0], lf.norm());
      faces["lambda_t (sign flipped)"].add(lf[1], -lg[1], lf.norm());
      faces["aperture"].add(grid.aperture[f], grid.aperture[g]);
      for (const unsigned int phase : {0u, 1u})
        faces[phase == 0 ? "p_w" : "p_nw"].add(solver.pressure(solver.state, n + f, phase),
                                               solver.pressure(solver.state, n + g, phase));
      faces["s_nw"].add(solver.saturation(solver.state, n + f, flow::fracture_rock),
                        solver.saturation(solver.state, n + g, flow::fracture_rock));
      faces["p_E"].add(pm.equivalent_pressure()[n + f], pm.equivalent_pressure()[n + g]);
      state_mismatches += mech.state(f) != mech.state(g);
    }

  // Matrix cells, with the cell means of the displacement.
  const auto               &dof_handler = mech.get_dof_handler();
  std::vector<Point<2>>     cell_centres(n);
  std::vector<Tensor<1, 2>> mean_u(n);
  {
    QGaussSimplex<2>                 quadrature(3);
    FEValues<2>                      fe_values(mesh.mapping(),
                          dof_handler.get_fe(),
                          quadrature,
                          update_values | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, 2>>        u_q(quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int K = cell->active_cell_index();
        cell_centres[K]      = cell->center();
        fe_values.reinit(cell);
        fe_values[displacement].get_function_values(mech.displacement(), u_q);
        double area = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            mean_u[K] += u_q[q] * fe_values.JxW(q);
            area += fe_values.JxW(q);
          }
        mean_u[K] /= area;
      }
  }
  const auto                       cell_pair = mirror_pairs(cell_centres);
  std::map<std::string, Asymmetry> cells;
  double                           max_s_nw_matrix = 0;
  for (unsigned int K = 0; K < n; ++K)
    {
      const unsigned int L = cell_pair[K];
      max_s_nw_matrix =
        std::max(max_s_nw_matrix, solver.saturation(solver.state, K, flow::matrix_rock));
      if (L == numbers::invalid_unsigned_int)
        {
          ++unpaired;
          continue;
        }
      for (const unsigned int phase : {0u, 1u})
        cells[phase == 0 ? "p_w" : "p_nw"].add(solver.pressure(solver.state, K, phase),
                                               solver.pressure(solver.state, L, phase));
      cells["s_nw"].add(solver.saturation(solver.state, K, flow::matrix_rock),
                        solver.saturation(solver.state, L, flow::matrix_rock));
      cells["p_E"].add(pm.equivalent_pressure()[K], pm.equivalent_pressure()[L]);
      cells["porosity"].add(grid.porosity[K], grid.porosity[L]);
      cells["mean u_x (sign flipped)"].add(mean_u[K][0], -mean_u[L][0], mean_u[K].norm());
      cells["mean u_y"].add(mean_u[K][1], mean_u[L][1], mean_u[K].norm());
    }

  const double tolerance = 1e-8;
  double       largest   = 0;
  std::cout << "Scene: " << n << " matrix cells, " << nf << " fracture faces, " << steps
            << " coupled steps to t = " << t << " s, " << cuts << " time-step cuts" << std::endl
            << "Cells and faces without a mirror partner: " << unpaired << std::endl
            << std::scientific << std::setprecision(3);
  for (const auto &[where, fields] :
       {std::make_pair("fracture faces", &faces), std::make_pair("matrix cells", &cells)})
    for (const auto &[name, a] : *fields)
      {
        std::cout << "  " << where << ", " << name << ": scale " << a.scale
                  << ", max mirror difference / scale " << std::setprecision(1) << a.relative()
                  << std::setprecision(3) << std::endl;
        largest = std::max(largest, a.relative());
      }
  const bool symmetric  = unpaired == 0 && state_mismatches == 0 && largest < tolerance;
  const bool nontrivial = max_s_nw_matrix > 0.1 && max_s_nw_fracture > 0.1 && states[0] > 0 &&
                          states[2] > 0 && max_slip > 0;
  std::cout << std::setprecision(1) << "Face states: open " << states[0] << ", stick " << states[1]
            << ", slip " << states[2]
            << "; mirrored faces in different states: " << state_mismatches << std::endl
            << "Largest relative asymmetry " << largest << ", below " << tolerance << ": "
            << (symmetric ? "yes" : "no") << std::endl
            << "Gas in the matrix and in the fractures, open and slipping faces: "
            << (nontrivial ? "yes" : "no") << std::endl;
  return symmetric && nontrivial ? 0 : 1;
}
