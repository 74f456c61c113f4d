// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_FRACTURE_NETWORK_H
#define POROFRAC_GEOMETRY_FRACTURE_NETWORK_H

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    using namespace dealii;

    /// A fracture in 2D: a polyline with a user id (ids must be distinct).
    struct Polyline
    {
      unsigned int          id;
      std::vector<Point<2>> points;
    };

    /// A 2D domain: a simple polygon, counter-clockwise, with one boundary id per edge
    /// (edge k joins corner k and corner k+1).
    struct Polygon
    {
      std::vector<Point<2>>           corners;
      std::vector<types::boundary_id> edge_ids;
    };

    /**
     * The straight-line graph that the mesher sees: points, boundary segments (with boundary ids,
     * split where fractures end on them) and fracture segments (with fracture ids, split where
     * fractures cross or meet).
     */
    struct PlanarGraph
    {
      struct Segment
      {
        unsigned int a, b; ///< point indices
        unsigned int tag;  ///< boundary id or fracture id
      };
      std::vector<Point<2>> points;
      std::vector<Segment>  boundary; ///< in counter-clockwise order around the domain
      std::vector<Segment>  fractures;
    };

    /**
     * A 2D fracture network in a polygonal domain, as read from a deck. validate() rejects, with
     * an InputError naming @p parameter_name, fractures that leave the domain, zero-length
     * segments, overlapping fractures, fractures along the boundary and self-crossing fractures.
     */
    class FractureNetwork
    {
    public:
      Polygon               domain;
      std::vector<Polyline> fractures;

      /// Parses "id: (x, y) (x, y) ...; id: ..." (an empty string gives no fractures).
      static std::vector<Polyline>
      parse_fractures(const std::string &text, const std::string &parameter_name);

      /// Parses "(x, y) (x, y) ..." (at least three points).
      static std::vector<Point<2>>
      parse_points(const std::string &text, const std::string &parameter_name);

      void
      validate(const std::string &parameter_name) const;

      /// Splits fractures at their crossings and boundary edges at fracture ends.
      PlanarGraph
      planar_graph() const;

      /// Diameter of the domain's bounding box (sets geometric tolerances).
      double
      diameter() const;
    };
  } // namespace geometry
} // namespace porofrac

#endif
