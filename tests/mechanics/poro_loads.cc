// SPDX-License-Identifier: LGPL-2.1-or-later
// Poromechanical loads of paper eq. (11b) (ContactProblem::set_equivalent_pressures). A unit
// square with u = 0 on its whole boundary, crossed by a fracture network with a tip inside, a
// uniform matrix equivalent pressure p and Biot coefficient b. Since int_{Omega \ Gamma} div v =
// int_Gamma [v]_n for v = 0 on the outer boundary, the loads reduce to (b p - p_f) int [v]_n:
// with p_f = 0 the exact solution is u = 0, lambda = b p n+ (closed, lambda_n = b p, no shear);
// with p_f = b p, lambda = 0 with u = 0. Printed: max |u| (scaled), the range of lambda_n / (b p)
// and max |lambda_t| / (b p), and the same in the second case; then the cell divergence of an
// imposed affine field u = (e x, e y), 2 e in every cell, and the r-weighted hoop part in
// axisymmetric mode (div u = 3 e for u = e (x, r)), at round-off.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/mechanics/contact_problem.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

using namespace porofrac;
using namespace dealii;

namespace
{
  std::unique_ptr<geometry::CutMesh<2>>
  square(const std::string &box, const double y0 = 0)
  {
    geometry::GeometryParameters g;
    g.domain    = "box";
    g.box       = box;
    g.fractures = "1: (0.2, " + std::to_string(y0 + 0.5) + ") (0.8, " + std::to_string(y0 + 0.5) +
                  "); 2: (0.5, " + std::to_string(y0 + 0.2) + ") (0.5, " +
                  std::to_string(y0 + 0.5) + ")";
    g.mesh_size           = 0.1;
    g.fracture_mesh_size  = 0.1;
    g.transition_distance = 0.1;
    g.global_refinements  = 0;
    g.delaunay_flips      = false;
    return geometry::make_cut_mesh<2>(g);
  }
} // namespace

int
main()
{
  ConditionalOStream quiet(std::cout, false);
  TimerOutput        timer(quiet, TimerOutput::never, TimerOutput::wall_times);
  const double       E = 1e9, b = 0.6, p = 2e6;
  auto               mesh = square("(0, 0) (1, 1)");

  mechanics::ContactParameters c;
  c.young_modulus = E;
  c.poisson_ratio = 0.25;
  c.c             = 1e9;
  c.friction_all  = "0.3";
  for (unsigned int id = 0; id < 4; ++id)
    c.dirichlet[id] = {{0, "0"}, {1, "0"}};
  mechanics::ContactProblem<2> problem(*mesh, c, quiet, timer);
  problem.setup();
  const std::vector<double> pm(mesh->triangulation.n_active_cells(), p);
  std::cout << std::scientific << std::setprecision(3);
  for (const double pf : {0., b * p})
    {
      problem.set_equivalent_pressures(pm, std::vector<double>(mesh->fracture_faces.size(), pf), b);
      problem.solve();
      double ln_min = 1e300, ln_max = -1e300, lt_max = 0;
      for (const auto &face : mesh->fracture_faces)
        {
          const Tensor<1, 2> l = problem.multiplier(face.index);
          ln_min               = std::min(ln_min, l * face.normal);
          ln_max               = std::max(ln_max, l * face.normal);
          lt_max               = std::max(lt_max, std::abs(l * face.tangent));
        }
      std::cout << "p_f = " << pf << ": max |u| E / (b p) "
                << problem.displacement().linfty_norm() * E / (b * p) << ", lambda_n / (b p) in ["
                << ln_min / (b * p) << ", " << ln_max / (b * p) << "], max |lambda_t| / (b p) "
                << lt_max / (b * p) << std::endl;
    }

  // Cell divergence of the compression u = e (x, y) (e < 0): uniform isotropic strain, exact
  // for P2 with the boundary values imposed, fractures closed without shear. div u = 2e in the
  // plane, 3e in axisymmetric mode (hoop strain u_r / r = e).
  for (const bool axi : {false, true})
    {
      auto         box = axi ? square("(0, 1) (1, 2)", 1.) : square("(0, 0) (1, 1)");
      auto         prm = c;
      const double e   = -1e-3;
      prm.axisymmetric = axi;
      for (unsigned int id = 0; id < 4; ++id)
        prm.dirichlet[id] = {{0, "-1e-3*x"}, {1, "-1e-3*y"}};
      mechanics::ContactProblem<2> q(*box, prm, quiet, timer);
      q.setup();
      q.solve();
      const double expected = (axi ? 3 : 2) * e;
      double       worst    = 0;
      for (const double d : q.cell_divergence())
        worst = std::max(worst, std::abs(d - expected) / std::abs(expected));
      std::cout << (axi ? "axisymmetric" : "plane") << ": max relative error of the cell "
                << "divergence below 1e-10: " << (worst < 1e-10 ? "yes" : "NO") << std::endl;
    }
}
