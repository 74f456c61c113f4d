// SPDX-License-Identifier: LGPL-2.1-or-later
// The paper's P2 reconstructions used for the 5.2.1 error norms (Section 5;
// fracture_reconstruction.h) on a horizontal fracture (0.5, 0.5)-(1.5, 0.5) of the box (0, 2) x (0,
// 1):
// - the displacement is the P2 interpolant of u = Q(x) (1, -2), Q = (x - 0.5)(1.5 - x), on the
// cells
//   above the fracture and 0 below, so the natural P2 jump must equal -+Q (1, -2) at every
//   quadrature point (Q is quadratic and vanishes at the tips, where the sides share vertices), and
//   the face mean of eq. (10) the mean of Q over the face;
// - a uniform multiplier (3e6, -2e6) must be reproduced exactly by the node-based P2 multiplier
//   (partition of unity of the plus-side traces), and a multiplier that changes from face to face
//   must not be (the reconstruction is a nodal average, not the face values).
// Printed: the largest deviations (scaled) and yes/no answers.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/fe/fe_values.h>

#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/mechanics/contact_problem.h>
#include <porofrac/mechanics/fracture_reconstruction.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace porofrac;
using namespace dealii;

int
main()
{
  geometry::GeometryParameters g;
  g.domain              = "box";
  g.box                 = "(0, 0) (2, 1)";
  g.fractures           = "1: (0.5, 0.5) (1.5, 0.5)";
  g.mesh_size           = 0.2;
  g.fracture_mesh_size  = 0.1;
  g.transition_distance = 0.1;
  g.global_refinements  = 0;
  g.delaunay_flips      = false;
  auto mesh             = geometry::make_cut_mesh<2>(g);

  ConditionalOStream           quiet(std::cout, false);
  TimerOutput                  timer(quiet, TimerOutput::never, TimerOutput::wall_times);
  mechanics::ContactParameters c;
  c.young_modulus = 1e9;
  c.poisson_ratio = 0.25;
  c.dirichlet[0]  = {{0, "0"}, {1, "0"}};
  mechanics::ContactProblem<2> problem(*mesh, c, quiet, timer);
  problem.setup();

  auto               Q = [](const Point<2> &p) { return (p[0] - 0.5) * (1.5 - p[0]); };
  const Tensor<1, 2> e({1., -2.});
  const auto        &fe = problem.get_dof_handler().get_fe();
  FEValues<2>        fv(mesh->mapping(),
                 fe,
                 Quadrature<2>(fe.get_unit_support_points()),
                 update_quadrature_points);
  std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
  Vector<double> u(problem.n_displacement_dofs()), lambda(problem.multipliers().size());
  for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
    if (cell->center()[1] > 0.5)
      {
        fv.reinit(cell);
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          u(local[i]) = Q(fv.quadrature_point(i)) * e[fe.system_to_component_index(i).first];
      }
  for (const auto &face : mesh->fracture_faces)
    for (unsigned int d = 0; d < 2; ++d)
      lambda(2 * face.index + d) = (d == 0 ? 3e6 : -2e6);
  problem.set_state(u, lambda);

  std::cout << std::scientific << std::setprecision(2);
  std::cout << "fracture faces: " << mesh->fracture_faces.size() << std::endl;
  double     jump_error = 0, lambda_error = 0, mean_error = 0, total_weight = 0;
  int        sign     = 0;
  bool       one_sign = true;
  const auto values   = mechanics::reconstruct_fracture_fields(problem, 4);
  for (const auto &v : values)
    {
      const double q = Q(v.x);
      const int    s = (v.jump * e > 0 ? 1 : -1);
      if (q > 1e-3)
        {
          if (sign == 0)
            sign = s;
          one_sign = one_sign && (s == sign);
        }
      jump_error   = std::max(jump_error, (v.jump - s * q * e).norm() / (0.25 * e.norm()));
      lambda_error = std::max(lambda_error, (v.lambda - Tensor<1, 2>({3e6, -2e6})).norm() / 3e6);
      total_weight += v.JxW;
    }
  // Face means (eq. (10)): (1/|sigma|) int_sigma [u] = sign * mean of Q e (Simpson is exact).
  for (const auto &face : mesh->fracture_faces)
    {
      const double a = face.abscissa_begin + 0.5, b = face.abscissa_end + 0.5; // x on the face
      auto         P    = [](const double x) { return -x * x * x / 3 + x * x - 0.75 * x; };
      const double mean = (P(b) - P(a)) / (b - a);
      mean_error =
        std::max(mean_error,
                 (problem.jump(face.index) - sign * mean * e).norm() / (0.25 * e.norm()));
    }
  std::cout << "quadrature points: " << values.size() << ", total weight " << std::fixed
            << std::setprecision(6) << total_weight << std::scientific << std::setprecision(2)
            << std::endl;
  std::cout << "P2 jump = +-Q (1, -2) with one sign on the whole fracture: "
            << (one_sign && jump_error < 1e-12 ? "yes" : "no") << std::endl;
  std::cout << "face means of eq. (10) = mean of +-Q (1, -2): "
            << (mean_error < 1e-12 ? "yes" : "no") << std::endl;
  std::cout << "uniform multiplier reproduced: " << (lambda_error < 1e-12 ? "yes" : "no")
            << std::endl;

  // A multiplier that varies from face to face (lambda_n = abscissa of the centre, in MPa): the
  // node-based reconstruction averages neighbouring faces, so it differs from the face values
  // (by about half a face step) but is continuous along the fracture.
  for (const auto &face : mesh->fracture_faces)
    {
      lambda(2 * face.index)     = 1e6 * face.abscissa;
      lambda(2 * face.index + 1) = 0;
    }
  problem.set_state(u, lambda);
  double dev = 0;
  for (const auto &v : mechanics::reconstruct_fracture_fields(problem, 4))
    dev = std::max(dev, std::abs(v.lambda[0] - 1e6 * v.abscissa) / 1e6);
  std::cout << "linear multiplier: reconstruction within one face length of the exact line: "
            << (dev < 0.1 ? "yes" : "no")
            << ", and not the face values: " << (dev > 1e-6 ? "yes" : "no") << std::endl;
}
