// SPDX-License-Identifier: LGPL-2.1-or-later
// Axisymmetric mode (Mechanics/Axisymmetric): the radial section x in [0, 1], r in [1, 2] of a
// hollow cylinder, u_x = 0 on x = 0 and x = 1 (plane strain along the axis), an internal pressure
// p = 1 MPa on r = 1, a free outer surface, and a fracture at r = 1.5 with interior tips and
// friction coefficient 1. Lame's solution u_r = A r + B / r, A = p a^2 / (2 (lambda + mu)(b^2 -
// a^2)), B = p a^2 b^2 / (2 mu (b^2 - a^2)), u_x = 0 has no shear, so the fracture sticks with
// lambda_n = -sigma_rr(1.5) > 0, [u] = 0, and the P2 solution converges at order 3 in the
// r-weighted L2 norm. Printed: errors on a mesh and its red refinement and their observed order
// (asserted >= 2.7), the largest
// |[u]| and the error of lambda_n. Second part: a uniform pre-stress sigma0 = diag(s_x, s_r) with
// hoop component s_theta = s_r, balanced by boundary tractions sigma0 n, gives u = 0 (printed:
// max |u| / (s L / E), at round-off), and s_theta != s_r is rejected without Axisymmetric.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <deal.II/fe/fe_values.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/mechanics/contact_problem.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace porofrac;
using namespace dealii;

namespace
{
  const double E = 1e9, nu = 0.25, p = 1e6, a = 1, b = 2;
  const double mu_s = E / (2 * (1 + nu)), lambda_s = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double A = p * a * a / (2 * (lambda_s + mu_s) * (b * b - a * a));
  const double B = p * a * a * b * b / (2 * mu_s * (b * b - a * a));

  std::unique_ptr<geometry::CutMesh<2>>
  section(const double h, const unsigned int refinements = 0)
  {
    geometry::GeometryParameters g;
    g.domain              = "box";
    g.box                 = "(0, 1) (1, 2)";
    g.fractures           = "1: (0.2, 1.5) (0.8, 1.5)";
    g.mesh_size           = h;
    g.fracture_mesh_size  = h;
    g.transition_distance = 0.1;
    g.global_refinements  = refinements;
    g.delaunay_flips      = false;
    return geometry::make_cut_mesh<2>(g);
  }

  mechanics::ContactParameters
  parameters()
  {
    mechanics::ContactParameters c;
    c.young_modulus   = E;
    c.poisson_ratio   = nu;
    c.axisymmetric    = true;
    c.c               = 1e9;
    c.friction_all    = "1"; // the fracture sticks: Lame has no shear on it
    c.dirichlet[0][0] = "0";
    c.dirichlet[1][0] = "0";
    return c;
  }

  /// r-weighted L2 norms of the error of u and of the exact u.
  std::pair<double, double>
  lame_errors(const mechanics::ContactProblem<2> &problem)
  {
    const QGaussSimplex<2>      q(4);
    FEValues<2>                 fv(problem.get_mesh().mapping(),
                   problem.get_dof_handler().get_fe(),
                   q,
                   update_values | update_quadrature_points | update_JxW_values);
    std::vector<Vector<double>> values(q.size(), Vector<double>(2));
    double                      e2 = 0, n2 = 0;
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      {
        fv.reinit(cell);
        fv.get_function_values(problem.displacement(), values);
        for (unsigned int k = 0; k < q.size(); ++k)
          {
            const double r  = fv.quadrature_point(k)[1];
            const double ur = A * r + B / r;
            const double w  = 2 * numbers::PI * r * fv.JxW(k);
            e2 += w * (std::pow(values[k][0], 2) + std::pow(values[k][1] - ur, 2));
            n2 += w * ur * ur;
          }
      }
    return {std::sqrt(e2), std::sqrt(n2)};
  }
} // namespace

int
main()
{
  ConditionalOStream quiet(std::cout, false);
  TimerOutput        timer(quiet, TimerOutput::never, TimerOutput::wall_times);
  std::cout << std::scientific << std::setprecision(3);

  // Part 1: Lame.
  double       errors[2];
  const double h[2] = {0.2, 0.1};
  for (unsigned int level = 0; level < 2; ++level)
    {
      auto mesh = section(0.2, level); // nested: the second mesh is the red refinement

      auto prm        = parameters();
      prm.pressure[2] = "1e6";
      mechanics::ContactProblem<2> problem(*mesh, prm, quiet, timer);
      problem.setup();
      problem.solve();
      const auto [e, n]     = lame_errors(problem);
      errors[level]         = e / n;
      double       max_jump = 0, ln_err = 0;
      const double sigma_rr = 2 * (lambda_s + mu_s) * A - 2 * mu_s * B / (1.5 * 1.5);
      for (const auto &face : mesh->fracture_faces)
        {
          max_jump = std::max(max_jump, problem.jump(face.index).norm());
          ln_err =
            std::max(ln_err, std::abs(problem.multiplier(face.index) * face.normal + sigma_rr) / p);
        }
      std::cout << "h = " << h[level] << ": relative L2(r) error of u " << errors[level]
                << ", states closed " << (max_jump < 1e-6 * (A * 1.5 + B / 1.5) ? "yes" : "NO")
                << ", max |lambda_n + sigma_rr(1.5)| / p below 1e-2: "
                << (ln_err < 1e-2 ? "yes" : "NO") << std::endl;
    }
  const double order = std::log(errors[0] / errors[1]) / std::log(2.);
  std::cout << std::fixed << std::setprecision(1) << "observed order " << order
            << ", at least 2.7: " << (order >= 2.7 ? "yes" : "NO") << std::endl;

  // Part 2: a uniform pre-stress with hoop component sigma0_theta = sigma0_r is in equilibrium
  // with the tractions sigma0 n: u = 0.
  {
    auto         mesh = section(0.2);
    auto         prm  = parameters();
    const double sx = -16e6, sr = -12e6;
    prm.pre_stress      = {sx, 0, 0, sr};
    prm.pre_stress_hoop = sr;
    prm.traction[2][1]  = std::to_string(-sr); // n = -e_r: sigma0 n = -s_r e_r
    prm.traction[3][1]  = std::to_string(sr);  // n = +e_r
    mechanics::ContactProblem<2> problem(*mesh, prm, quiet, timer);
    problem.setup();
    problem.solve();
    std::cout << std::scientific << std::setprecision(1)
              << "uniform pre-stress: max |u| / (|s| L / E) below 1e-10: "
              << (problem.displacement().linfty_norm() / (12e6 / E) < 1e-10 ? "yes" : "NO")
              << std::endl;
  }

  // Part 3: bad input.
  try
    {
      auto mesh           = section(0.2);
      auto prm            = parameters();
      prm.axisymmetric    = false;
      prm.pre_stress_hoop = 1e6;
      mechanics::ContactProblem<2> problem(*mesh, prm, quiet, timer);
      std::cout << "hoop pre-stress without Axisymmetric: accepted (WRONG)" << std::endl;
    }
  catch (const InputError &e)
    {
      std::cout << "hoop pre-stress without Axisymmetric: " << e.what() << std::endl;
    }
  try
    {
      geometry::GeometryParameters g;
      g.domain                          = "box";
      g.box                             = "(0, -1) (1, 1)";
      g.mesh_size                       = 0.5;
      auto                         mesh = geometry::make_cut_mesh<2>(g);
      mechanics::ContactProblem<2> problem(*mesh, parameters(), quiet, timer);
      std::cout << "section crossing r = 0: accepted (WRONG)" << std::endl;
    }
  catch (const InputError &e)
    {
      std::cout << "section crossing r = 0: " << e.what() << std::endl;
    }
}
