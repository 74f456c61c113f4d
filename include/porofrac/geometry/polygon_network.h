// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_POLYGON_NETWORK_H
#define POROFRAC_GEOMETRY_POLYGON_NETWORK_H

#include <deal.II/base/point.h>

#include <porofrac/geometry/planar_polygon.h>

#include <string>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * A fracture in 3D: a planar polygon with a user id. Discs and ellipses are inscribed
     * polygons. n+ follows the right-hand rule of the corner order; t1 is the direction of the
     * first edge (polygons) or of the first axis (discs and ellipses).
     */
    struct PolygonFracture
    {
      unsigned int  id;
      std::string   shape; ///< "polygon", "disc" or "ellipse", for messages
      PlanarPolygon polygon;
    };

    /**
     * A 3D fracture network in an axis-aligned box, as read from a deck. Boundary ids of the box
     * faces: 0 x min, 1 x max, 2 y min, 3 y max, 4 z min, 5 z max. Fractures may cross, end on
     * each other, touch or cut the box (the part outside is dropped).
     */
    class PolygonNetwork
    {
    public:
      Point<3>                     lo, hi;
      std::vector<PolygonFracture> fractures;

      /**
       * Parses "id: <fracture>; id: <fracture>; ..." where a fracture is
       * - a polygon: "(x, y, z) (x, y, z) (x, y, z) ..." (at least three corners),
       * - a disc: "disc centre (x, y, z) normal (x, y, z) radius r [sides n]", or with
       *   "axes (x, y, z) (x, y, z)" instead of the normal,
       * - an ellipse: "ellipse centre (x, y, z) axes (x, y, z) (x, y, z) radii a b [sides n]".
       * Discs and ellipses default to 16 sides. Errors name @p parameter.
       */
      static std::vector<PolygonFracture>
      parse_fractures(const std::string &text, const std::string &parameter);

      /// Parses "(x, y, z) (x, y, z) ...".
      static std::vector<Point<3>>
      parse_points(const std::string &text, const std::string &parameter);

      /// The corners of an ellipse with semi-axes @p a along @p t1 and @p b along n x t1.
      static std::vector<Point<3>>
      ellipse_corners(const Point<3>     &centre,
                      const Tensor<1, 3> &normal,
                      const Tensor<1, 3> &t1,
                      const double        a,
                      const double        b,
                      const unsigned int  sides);

      /**
       * Rejects, with an InputError naming @p parameter: polygons that are not planar, fold or
       * cross themselves, or have zero area; fractures outside the box or lying in one of its
       * faces; two fractures in one plane that overlap.
       */
      void
      validate(const std::string &parameter) const;

      /// Diameter of the box (sets geometric tolerances).
      double
      diameter() const;

      /// Geometric tolerance for coincidence tests: 1e-10 times the diameter.
      double
      tolerance() const;
    };
  } // namespace geometry
} // namespace porofrac

#endif
