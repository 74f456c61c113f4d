// SPDX-License-Identifier: LGPL-2.1-or-later
// The six-fracture scene of paper Section 5.2.2 (prm/six_fractures.prm) for the program tests.
#ifndef POROFRAC_TESTS_MECHANICS_SIX_FRACTURES_H
#define POROFRAC_TESTS_MECHANICS_SIX_FRACTURES_H

#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/mechanics/parameters.h>

#include <memory>

namespace six_fractures
{
  using namespace porofrac;

  /// The deck's geometry with mesh sizes @p h (cells) and @p hf (along the fractures); the deck
  /// has h = 0.05, hf = 0.02.
  inline std::unique_ptr<geometry::CutMesh<2>>
  mesh(const double h, const double hf)
  {
    geometry::GeometryParameters g;
    g.domain              = "box";
    g.box                 = "(0, 0) (2, 1)";
    g.fractures           = "1: (0.2, 0.7) (0.5, 0.7) (0.8, 0.65); 2: (1.0, 0.3) (1.8, 0.4); "
                            "3: (0.2, 0.3) (0.6, 0.25); 4: (1.0, 0.4) (1.7, 0.85); "
                            "5: (1.5, 0.65) (2.0, 0.55); 6: (1.5, 0.05) (1.4, 0.25)";
    g.mesh_size           = h;
    g.fracture_mesh_size  = hf;
    g.transition_distance = 0.05;
    g.global_refinements  = 0;
    return geometry::make_cut_mesh<2>(g);
  }

  /// The deck's material, boundary conditions and friction (solver settings: code defaults).
  inline mechanics::ContactParameters
  contact_parameters()
  {
    mechanics::ContactParameters c;
    c.young_modulus = 4e9;
    c.poisson_ratio = 0.2;
    c.dirichlet[2]  = {{0, "0"}, {1, "0"}};
    c.dirichlet[3]  = {{0, "0.005"}, {1, "-0.002"}};
    c.friction_all  = "0.5*(1+10*exp(-d^2/0.005))";
    return c;
  }
} // namespace six_fractures

#endif
