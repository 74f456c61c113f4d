// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_FRACTURE_BAND_H
#define POROFRAC_GEOMETRY_FRACTURE_BAND_H

#include <porofrac/geometry/fracture_network.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/geometry/polygon_network.h>

namespace porofrac
{
  namespace geometry
  {
    /**
     * The mesh size asked for near the fractures, by the distance d to the nearest one:
     * h_f + (h - h_f) min(1, d / D), with h_f = Fracture mesh size, h = Mesh size and D =
     * Transition distance (5 h if not set). gmsh's Threshold field in 2D, the size callback in 3D.
     */
    struct FractureBand
    {
      explicit FractureBand(const GeometryParameters &prm);

      double
      size(const double distance) const
      {
        return std::min(h_far, h_fracture + (h_far - h_fracture) * distance / transition);
      }

      double h_fracture, h_far, transition;
    };

    /// Distance from @p x to the nearest fracture polyline, or @p cap if all are farther.
    double
    distance_to_fractures(const FractureNetwork &network, const Point<3> &x, const double cap);

    /// Distance from @p x to the nearest fracture polygon, or @p cap if all are farther
    /// (polygons whose bounding box is farther than @p cap are skipped).
    double
    distance_to_fractures(const PolygonNetwork &network, const Point<3> &x, const double cap);
  } // namespace geometry
} // namespace porofrac

#endif
