// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_PLANAR_GRAPH_CHECKS_H
#define POROFRAC_GEOMETRY_PLANAR_GRAPH_CHECKS_H

#include <porofrac/geometry/fracture_network.h>

#include <string>

namespace porofrac
{
  namespace geometry
  {
    /**
     * Refuses, with an InputError naming @p parameter and the location, a 2D fracture graph
     * that no mesh of reasonable quality can resolve: a fracture point (tip, corner, crossing)
     * closer than @p min_gap to a fracture or boundary segment it is not on, a graph point
     * closer than @p min_gap to a fracture segment it is not on (near-misses of T junctions,
     * nearly touching parallel fractures), and two segments that meet at a point with an angle
     * below @p min_angle_degrees where at least one of them is a fracture.
     */
    void
    check_near_degenerate(const PlanarGraph &graph,
                          const double       min_gap,
                          const double       min_angle_degrees,
                          const std::string &parameter);
  } // namespace geometry
} // namespace porofrac

#endif
