// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_PLANAR_POLYGON_H
#define POROFRAC_GEOMETRY_PLANAR_POLYGON_H

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * Vector area of a closed 3D polygon (Newell's formula): its direction is the normal given by
     * the right-hand rule of the corner order, its length the area if the polygon is planar.
     */
    Tensor<1, 3>
    vector_area(const std::vector<Point<3>> &corners);

    /// Unit vector in the plane normal to @p normal: the coordinate axis least aligned with it,
    /// projected (ties go to the lower axis), so that the choice is deterministic.
    Tensor<1, 3>
    default_tangent(const Tensor<1, 3> &normal);

    /// Euclidean distance from @p x to the segment [a, b].
    template <int dim>
    double
    distance_to_segment(const Point<dim> &x, const Point<dim> &a, const Point<dim> &b);

    /// Smallest distance between the 3D segments [p0, p1] and [q0, q1].
    double
    segment_distance(const Point<3> &p0,
                     const Point<3> &p1,
                     const Point<3> &q0,
                     const Point<3> &q1);

    /// Is @p x strictly inside the simple 2D polygon @p polygon (even-odd rule)?
    bool
    inside_polygon(const Point<2> &x, const std::vector<Point<2>> &polygon);

    /// Where a polygon meets itself: edges i and j (edge k joins corners k and k+1).
    struct SelfIntersection
    {
      unsigned int i, j;
      Point<2>     where;
      bool         folds; ///< neighbouring edges folding back onto each other
    };

    /// Where the 2D polygon @p polygon crosses or touches itself, or nothing for a simple
    /// polygon. Segments closer than @p tol meet.
    std::optional<SelfIntersection>
    self_intersection(const std::vector<Point<2>> &polygon, const double tol);

    /// Ear-clipping triangulation of a simple 2D polygon (either orientation), as corner triples.
    std::vector<std::array<unsigned int, 3>>
    triangulate(const std::vector<Point<2>> &polygon);

    /**
     * A planar polygon with its frame: unit normal n (right-hand rule of the corners), unit
     * tangents t1, t2 = n x t1 in the plane, and the corners in plane coordinates (x - origin)
     * . (t1, t2). Answers the geometric questions of meshing and validation.
     */
    class PlanarPolygon
    {
    public:
      PlanarPolygon() = default;
      /// @p tangent is projected onto the plane; a zero tangent selects default_tangent().
      PlanarPolygon(const std::vector<Point<3>> &corners, const Tensor<1, 3> &tangent);

      std::vector<Point<3>> corners;
      Point<3>              origin;
      Tensor<1, 3>          normal, t1, t2;
      std::vector<Point<2>> plane_corners;
      Point<3>              box_lo, box_hi; ///< bounding box
      /// Three corners spanning a wide triangle (the two farthest apart, the one farthest from
      /// their line): their plane is the reference of the planarity test.
      std::array<unsigned int, 3> plane_triangle;

      Point<2>
      to_plane(const Point<3> &x) const;
      Point<3>
      from_plane(const Point<2> &x) const;
      /// Signed distance of @p x from the plane (positive on the side n points to).
      double
      height(const Point<3> &x) const;
      double
      area() const;
      /// The corner farthest from the plane of the corners plane_triangle, and its distance.
      std::pair<unsigned int, double>
      planarity_deviation() const;
      /// Euclidean distance from @p x to the polygon (a 2D region of the plane).
      double
      distance(const Point<3> &x) const;
      /// Distance from @p x to the bounding box (0 inside it): a cheap lower bound of distance().
      double
      box_distance(const Point<3> &x) const;
      /// Is @p x in the plane (within @p tol) and strictly inside the polygon?
      bool
      contains(const Point<3> &x, const double tol) const;
    };

    /// Area of the part of @p polygon inside the box [lo, hi] (Sutherland-Hodgman clipping).
    double
    area_inside_box(const PlanarPolygon &polygon, const Point<3> &lo, const Point<3> &hi);

    /**
     * Do two polygons lying in the same plane (within @p tol) share a region of positive area?
     * Polygons in different planes never overlap in that sense.
     */
    bool
    coplanar_overlap(const PlanarPolygon &a, const PlanarPolygon &b, const double tol);

    /// Smallest distance between two polygons (0 if they intersect).
    double
    polygon_distance(const PlanarPolygon &a, const PlanarPolygon &b);

    /**
     * The segment where two polygons in different planes intersect, as its end points, or
     * nothing. (Non-convex polygons may meet in several segments: the first and last points of
     * their union along the line are returned.)
     */
    std::optional<std::array<Point<3>, 2>>
    intersection_segment(const PlanarPolygon &a, const PlanarPolygon &b, const double tol);
  } // namespace geometry
} // namespace porofrac

#endif
