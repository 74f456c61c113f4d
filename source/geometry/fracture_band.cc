// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/geometry/fracture_band.h>
#include <porofrac/geometry/planar_polygon.h>

#include <algorithm>

namespace porofrac
{
  namespace geometry
  {
    FractureBand::FractureBand(const GeometryParameters &prm)
        : h_fracture(prm.fracture_mesh_size)
        , h_far(prm.mesh_size)
        , transition(prm.transition_distance > 0 ? prm.transition_distance : 5 * prm.mesh_size)
    {
    }



    double
    distance_to_fractures(const FractureNetwork &network, const Point<3> &x, const double cap)
    {
      const Point<2> y(x[0], x[1]);
      double         d = cap;
      for (const auto &f : network.fractures)
        for (unsigned int i = 0; i + 1 < f.points.size(); ++i)
          d = std::min(d, distance_to_segment<2>(y, f.points[i], f.points[i + 1]));
      return d;
    }



    double
    distance_to_fractures(const PolygonNetwork &network, const Point<3> &x, const double cap)
    {
      double d = cap;
      for (const auto &f : network.fractures)
        if (f.polygon.box_distance(x) < d)
          d = std::min(d, f.polygon.distance(x));
      return d;
    }
  } // namespace geometry
} // namespace porofrac
