// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/planar_graph_checks.h>
#include <porofrac/geometry/planar_polygon.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      struct GraphSegment
      {
        unsigned int a, b;
        bool         fracture;
        unsigned int tag;
      };

      std::string
      describe(const GraphSegment &s)
      {
        return s.fracture ? "fracture " + std::to_string(s.tag) :
                            "the boundary (id " + std::to_string(s.tag) + ")";
      }

      std::vector<GraphSegment>
      all_segments(const PlanarGraph &graph)
      {
        std::vector<GraphSegment> segments;
        for (const auto &s : graph.boundary)
          segments.push_back({s.a, s.b, false, s.tag});
        for (const auto &s : graph.fractures)
          segments.push_back({s.a, s.b, true, s.tag});
        return segments;
      }

      /// Smallest angle between two segments leaving one point, at least one a fracture.
      void
      check_angles(const PlanarGraph               &graph,
                   const std::vector<GraphSegment> &segments,
                   const double                     min_angle_degrees,
                   const std::string               &parameter)
      {
        std::vector<std::vector<unsigned int>> at(graph.points.size());
        for (unsigned int i = 0; i < segments.size(); ++i)
          {
            at[segments[i].a].push_back(i);
            at[segments[i].b].push_back(i);
          }
        for (unsigned int p = 0; p < graph.points.size(); ++p)
          for (unsigned int x = 0; x < at[p].size(); ++x)
            for (unsigned int y = x + 1; y < at[p].size(); ++y)
              {
                const auto &s = segments[at[p][x]], &t = segments[at[p][y]];
                if (!s.fracture && !t.fracture)
                  continue;
                const auto   u = graph.points[s.a == p ? s.b : s.a] - graph.points[p];
                const auto   v = graph.points[t.a == p ? t.b : t.a] - graph.points[p];
                const double angle =
                  std::acos(std::clamp(u * v / (u.norm() * v.norm()), -1., 1.)) * 180 / M_PI;
                if (angle < min_angle_degrees)
                  {
                    std::ostringstream m;
                    m.precision(3);
                    m << describe(s) << " and " << describe(t) << " meet at "
                      << io::to_text(graph.points[p]) << " at an angle of " << angle
                      << " degrees, below " << min_angle_degrees
                      << ": no mesh resolves it; widen the angle";
                    throw InputError(parameter, m.str());
                  }
              }
      }
    } // namespace



    void
    check_near_degenerate(const PlanarGraph &graph,
                          const double       min_gap,
                          const double       min_angle_degrees,
                          const std::string &parameter)
    {
      const auto        segments = all_segments(graph);
      std::vector<bool> on_fracture(graph.points.size(), false);
      for (const auto &s : graph.fractures)
        on_fracture[s.a] = on_fracture[s.b] = true;
      for (unsigned int p = 0; p < graph.points.size(); ++p)
        for (const auto &s : segments)
          {
            if (s.a == p || s.b == p || (!s.fracture && !on_fracture[p]))
              continue;
            const double gap =
              distance_to_segment(graph.points[p], graph.points[s.a], graph.points[s.b]);
            if (gap < min_gap)
              {
                std::ostringstream m;
                m.precision(3);
                m << "the " << (on_fracture[p] ? "fracture point " : "boundary corner ")
                  << io::to_text(graph.points[p]) << " is " << gap << " m from " << describe(s)
                  << ", closer than " << min_gap
                  << " m (1e-3 of Fracture mesh size): join them or move them apart";
                throw InputError(parameter, m.str());
              }
          }
      check_angles(graph, segments, min_angle_degrees, parameter);
    }
  } // namespace geometry
} // namespace porofrac
