// SPDX-License-Identifier: LGPL-2.1-or-later
// The cell-count estimate behind Geometry/Maximum cells against integrals known in closed form:
// the number of regular cells (area sqrt(3)/4 h^2, volume h^3/(6 sqrt(2))) that fill the domain at
// the size asked for, times the cells gmsh makes per regular cell (1.15 in 2D, 0.65 in 3D).
// - a uniform size: the domain's measure over the cell's, exactly;
// - a fracture across the domain: the band of width D on each side where the size grows linearly
//   from h_f to h adds 2 L int_0^D dd / v(h_f + (h - h_f) d / D) (L the length or area);
// - a refinement box inside the domain;
// - the three sizes together with a size expression, where the smallest wins;
// - a polygonal 2D domain (an L shape) at a uniform size;
// and which parameter is named for the largest share, and that an expression that is not positive
// at a sample point is refused with that point (the domain's first corner).
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/polygon_mesher.h>
#include <porofrac/geometry/size_guard.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace porofrac::geometry;

namespace
{
  /// Regular cells per unit measure at size h.
  double
  density(const double h, const unsigned int dim)
  {
    return dim == 2 ? 4 / (std::sqrt(3.) * h * h) : 6 * std::sqrt(2.) / (h * h * h);
  }

  /// int_0^D density(h_f + (h - h_f) d / D) dd.
  double
  band(const double h_f, const double h, const double D, const unsigned int dim)
  {
    const double s = (h - h_f) / D;
    return dim == 2 ? 4 / std::sqrt(3.) * (1 / h_f - 1 / h) / s :
                      6 * std::sqrt(2.) * (1 / (h_f * h_f) - 1 / (h * h)) / (2 * s);
  }

  void
  report(const std::string &name, const CellEstimate &e, const double exact, const double tol)
  {
    const double ratio = e.cells / exact;
    std::cout << std::left << std::setw(44) << name << std::right << std::fixed
              << std::setprecision(3) << " estimate / exact = " << ratio << " (within "
              << std::defaultfloat << tol << ": " << (std::abs(ratio - 1) <= tol ? "yes" : "NO")
              << "), named: " << e.parameter << "\n";
  }

  CellEstimate
  estimate(const GeometryParameters &prm, const unsigned int dim)
  {
    return dim == 2 ? estimate_cells(network_from_parameters(prm), prm) :
                      estimate_cells(polygon_network_from_parameters(prm), prm);
  }

  GeometryParameters
  box(const unsigned int dim)
  {
    GeometryParameters prm;
    prm.box                 = dim == 2 ? "(0, 0) (2, 1)" : "(0, 0, 0) (2, 1, 1)";
    prm.mesh_size           = 0.1;
    prm.fracture_mesh_size  = 0.01;
    prm.transition_distance = 0.2;
    return prm;
  }
} // namespace

int
main()
{
  for (const unsigned int dim : {2u, 3u})
    {
      const double gmsh = dim == 2 ? 1.15 : 0.65, measure = 2;
      std::cout << dim << "D, box of measure 2, h = 0.1, h_f = 0.01, D = 0.2:\n";

      GeometryParameters prm = box(dim);
      report("uniform size", estimate(prm, dim), gmsh * measure * density(0.1, dim), 1e-12);

      prm.fractures = dim == 2 ? "1: (0, 0.5) (2, 0.5)" :
                                 "1: (-0.1, -0.1, 0.5) (2.1, -0.1, 0.5) (2.1, 1.1, 0.5) "
                                 "(-0.1, 1.1, 0.5)";
      const double fracture =
        2 * 2 * band(0.01, 0.1, 0.2, dim) + (measure - 2 * 2 * 0.2) * density(0.1, dim);
      report("a fracture across the domain", estimate(prm, dim), gmsh * fracture, 0.05);

      prm = box(dim);
      prm.refinement_regions =
        dim == 2 ? "(0.5, 0.25) (1.5, 0.75): 0.02" : "(0.5, 0.25, 0.25) (1.5, 0.75, 0.75): 0.02";
      const double inner = dim == 2 ? 0.5 : 0.25;
      report("a refinement box",
             estimate(prm, dim),
             gmsh * (inner * density(0.02, dim) + (measure - inner) * density(0.1, dim)),
             0.05);

      // All four parts, against a midpoint rule on a fine grid of the smallest size: the
      // fracture at y (z) = 0.125, the refinement box, the expression 0.04 + 0.05 x.
      prm.fractures                = dim == 2 ? "1: (0, 0.125) (2, 0.125)" :
                                                "1: (-0.1, -0.1, 0.125) (2.1, -0.1, 0.125) "
                                                "(2.1, 1.1, 0.125) (-0.1, 1.1, 0.125)";
      prm.size_expression          = "0.04 + 0.05*x";
      const unsigned int n         = dim == 2 ? 1000 : 200;
      double             reference = 0;
      for (unsigned int i = 0; i < 2 * n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int k = 0; k < (dim == 2 ? 1 : n); ++k)
            {
              const double x = (i + 0.5) / n, y = (j + 0.5) / n, z = (k + 0.5) / n;
              const double d = std::abs((dim == 2 ? y : z) - 0.125);
              double h = std::min({0.1, 0.01 + 0.09 * std::min(1., d / 0.2), 0.04 + 0.05 * x});
              if (x > 0.5 && x < 1.5 && y > 0.25 && y < 0.75 &&
                  (dim == 2 || (z > 0.25 && z < 0.75)))
                h = std::min(h, 0.02);
              reference += density(h, dim) / std::pow(n, dim);
            }
      report("all four parts", estimate(prm, dim), gmsh * reference, 0.05);
      prm.refinement_regions = "";
      prm.size_expression    = "";
      prm.fracture_mesh_size = 0.001;
      std::cout << "fracture mesh size 0.001, named: " << estimate(prm, dim).parameter << "\n";

      prm                 = box(dim);
      prm.size_expression = "0.1*(x - 1)";
      try
        {
          estimate(prm, dim);
          std::cout << "an expression negative for x < 1: NOT refused\n";
        }
      catch (const porofrac::InputError &e)
        {
          std::cout << "an expression negative for x < 1: refused: " << e.what() << "\n";
        }
    }

  GeometryParameters prm = box(2);
  prm.domain             = "polygon";
  prm.polygon            = "(0, 0) (2, 0) (2, 1) (1, 1) (1, 2) (0, 2)";
  std::cout << "2D L shape of area 3, h = 0.1:\n";
  report("uniform size", estimate(prm, 2), 1.15 * 3 * density(0.1, 2), 0.05);
}
