// SPDX-License-Identifier: LGPL-2.1-or-later
// The planar-polygon geometry behind 3D fracture validation, meshing sizes and the random disc
// generator, against hand-computed values: areas (also clipped by a box), distances, the
// segment where two polygons meet, coplanar overlaps, self-intersections, and the disc
// generator's determinism and rejections.
#include <porofrac/geometry/planar_polygon.h>
#include <porofrac/geometry/polygon_network.h>
#include <porofrac/geometry/random_discs.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace porofrac::geometry;

namespace
{
  PlanarPolygon
  polygon(const std::string &text)
  {
    return PolygonNetwork::parse_fractures("1: " + text, "test")[0].polygon;
  }
} // namespace

int
main()
{
  std::cout << std::scientific << std::setprecision(6);
  const Point<3> lo(0, 0, 0), hi(1, 1, 1);

  // A unit square at z = 0.5, corners counter-clockwise seen from +z: n+ = +z, area 1; half of
  // it (x < 1) lies in the unit box when shifted by 0.5 in x.
  const auto square  = polygon("(0, 0, 0.5) (1, 0, 0.5) (1, 1, 0.5) (0, 1, 0.5)");
  const auto shifted = polygon("(0.5, 0, 0.5) (1.5, 0, 0.5) (1.5, 1, 0.5) (0.5, 1, 0.5)");
  std::cout << "square: normal " << square.normal << ", area " << square.area()
            << ", shifted area inside the box " << area_inside_box(shifted, lo, hi) << std::endl;

  // A disc of radius 1 with 64 sides: area 32 sin(2 pi / 64); an ellipse with radii 2 and 1:
  // twice that. Reversed corner order flips n+.
  const auto disc = polygon("disc centre (0, 0, 0) normal (0, 0, 2) radius 1 sides 64");
  const auto ellipse =
    polygon("ellipse centre (0, 0, 0) axes (0, 1, 0) (0, 0, 1) radii 2 1 sides 64");
  const auto reversed = polygon("(0, 1, 0.5) (1, 1, 0.5) (1, 0, 0.5) (0, 0, 0.5)");
  std::cout << "disc: area error " << disc.area() - 32 * std::sin(2 * M_PI / 64)
            << ", ellipse: area error " << ellipse.area() - 64 * std::sin(2 * M_PI / 64)
            << ", normal " << ellipse.normal << ", t1 " << ellipse.t1 << std::endl
            << "reversed square: normal " << reversed.normal << std::endl;

  // Distances: above the centre, beside an edge, beyond a corner.
  std::cout << "distances to the square: " << square.distance(Point<3>(0.5, 0.5, 0.8)) << " "
            << square.distance(Point<3>(1.3, 0.5, 0.5)) << " "
            << square.distance(Point<3>(1.3, 1.4, 0.5)) << std::endl;

  // Where polygons meet: a vertical square x = 0.5 crossing the horizontal one along
  // y in [0.2, 0.8]; a disc missing it by 0.1.
  const auto vertical = polygon("(0.5, 0.2, 0.2) (0.5, 0.8, 0.2) (0.5, 0.8, 0.8) (0.5, 0.2, 0.8)");
  const auto s        = intersection_segment(square, vertical, 1e-12);
  std::cout << "intersection: " << (s ? "yes" : "no") << ", length "
            << (s ? (*s)[0].distance((*s)[1]) : 0.) << ", midpoint "
            << (s ? Point<3>(0.5 * ((*s)[0] + (*s)[1])) : Point<3>()) << std::endl;
  const auto high = polygon("disc centre (0.5, 0.5, 0.9) normal (1, 0, 0) radius 0.3");
  std::cout << "disc above: meets " << (intersection_segment(square, high, 1e-12) ? "yes" : "no")
            << ", distance " << polygon_distance(square, high) << std::endl;

  // Overlaps in one plane: overlapping, touching along an edge, apart, and contained.
  const auto a = polygon("(0, 0, 0.5) (0.6, 0, 0.5) (0.6, 0.6, 0.5) (0, 0.6, 0.5)");
  const auto b = polygon("(0.4, 0.4, 0.5) (1, 0.4, 0.5) (1, 1, 0.5) (0.4, 1, 0.5)");
  const auto c = polygon("(0.6, 0, 0.5) (1, 0, 0.5) (1, 0.6, 0.5) (0.6, 0.6, 0.5)");
  const auto d = polygon("(0.7, 0.7, 0.5) (0.9, 0.7, 0.5) (0.9, 0.9, 0.5) (0.7, 0.9, 0.5)");
  const auto e = polygon("(0.1, 0.1, 0.5) (0.2, 0.1, 0.5) (0.2, 0.2, 0.5) (0.1, 0.2, 0.5)");
  std::cout << "coplanar overlaps: crossing " << coplanar_overlap(a, b, 1e-12)
            << ", sharing an edge " << coplanar_overlap(a, c, 1e-12) << ", apart "
            << coplanar_overlap(a, d, 1e-12) << ", contained " << coplanar_overlap(a, e, 1e-12)
            << ", other plane " << coplanar_overlap(a, vertical, 1e-12) << std::endl;

  // Self-intersections: a bow-tie, an L-shaped (non-convex) hexagon, a spike folding back.
  const auto bowtie =
    self_intersection({Point<2>(0, 0), Point<2>(1, 1), Point<2>(1, 0), Point<2>(0, 1)}, 1e-12);
  const auto l_shape = self_intersection({Point<2>(0, 0),
                                          Point<2>(2, 0),
                                          Point<2>(2, 1),
                                          Point<2>(1, 1),
                                          Point<2>(1, 2),
                                          Point<2>(0, 2)},
                                         1e-12);
  const auto spike =
    self_intersection({Point<2>(0, 0), Point<2>(2, 0), Point<2>(1, 0), Point<2>(1, 1)}, 1e-12);
  std::cout << "bow-tie: edges " << bowtie->i + 1 << " and " << bowtie->j + 1 << " at "
            << bowtie->where << "; L shape simple: " << !l_shape.has_value()
            << "; spike folds: " << (spike && spike->folds) << std::endl;

  // The generator: the same seed gives the same discs; with h > 0 it rejects more.
  PolygonNetwork network;
  network.lo = Point<3>(0, 0, 0);
  network.hi = Point<3>(2, 2, 2);
  RandomDiscParameters p;
  p.count              = 40;
  p.seed               = 7;
  p.radius_min         = 0.2;
  p.radius_max         = 0.5;
  PolygonNetwork first = network, again = network, strict = network;
  const auto     s0 = add_random_discs(p, first);
  add_random_discs(p, again);
  double difference = 0;
  for (unsigned int k = 0; k < first.fractures.size(); ++k)
    for (unsigned int i = 0; i < first.fractures[k].polygon.corners.size(); ++i)
      difference +=
        first.fractures[k].polygon.corners[i].distance(again.fractures[k].polygon.corners[i]);
  p.minimum_feature_size = 0.05;
  p.minimum_angle        = 20;
  const auto   s1        = add_random_discs(p, strict);
  unsigned int rejected0 = 0, rejected1 = 0;
  for (const auto &[why, n] : s0.rejected)
    rejected0 += n;
  for (const auto &[why, n] : s1.rejected)
    rejected1 += n;
  std::cout << "random discs: " << first.fractures.size() << " placed, same seed differs by "
            << difference << ", first centre " << first.fractures[0].polygon.origin
            << "; rejected without h: " << rejected0
            << ", with h = 0.05 and 20 degrees: " << rejected1 << std::endl;
  for (const auto &[why, n] : s1.rejected)
    std::cout << "  " << why << ": " << n << std::endl;
  // Every accepted pair that meets does so at 20 degrees or more.
  double smallest_angle = 90;
  for (unsigned int i = 0; i < strict.fractures.size(); ++i)
    for (unsigned int j = i + 1; j < strict.fractures.size(); ++j)
      if (intersection_segment(strict.fractures[i].polygon, strict.fractures[j].polygon, 1e-12))
        smallest_angle =
          std::min(smallest_angle,
                   std::asin(std::min(1.,
                                      cross_product_3d(strict.fractures[i].polygon.normal,
                                                       strict.fractures[j].polygon.normal)
                                        .norm())) *
                     180 / M_PI);
  std::cout << "smallest angle between accepted discs that meet: " << std::fixed
            << std::setprecision(2) << smallest_angle << std::endl;
}
