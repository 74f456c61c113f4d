// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/polygon_network.h>
#include <porofrac/io/text.h>

#include <cmath>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      double
      polygon_diameter(const std::vector<Point<3>> &corners)
      {
        double d = 0;
        for (const auto &a : corners)
          for (const auto &b : corners)
            d = std::max(d, a.distance(b));
        return d;
      }

      /// The shape of one fracture on its own: edges, area, planarity, simplicity.
      void
      validate_shape(const PolygonFracture &f, const double tol, const std::string &parameter)
      {
        const std::string name    = "fracture " + std::to_string(f.id);
        const auto       &corners = f.polygon.corners;
        for (unsigned int k = 0; k < corners.size(); ++k)
          if (corners[k].distance(corners[(k + 1) % corners.size()]) <= tol)
            throw InputError(parameter,
                             name + ": corners " + std::to_string(k + 1) + " and " +
                               std::to_string((k + 1) % corners.size() + 1) + " coincide at " +
                               io::to_text(corners[k]));
        const double size = polygon_diameter(corners);
        // Relative to the polygon's size: corners typed with a few digits stay acceptable.
        const auto [worst, deviation] = f.polygon.planarity_deviation();
        if (deviation > 1e-6 * size)
          {
            const auto &t = f.polygon.plane_triangle;
            throw InputError(parameter,
                             name + " is not planar: corner " + std::to_string(worst + 1) + " " +
                               io::to_text(corners[worst]) + " lies " + io::to_text(deviation) +
                               " m from the plane of corners " + std::to_string(t[0] + 1) + ", " +
                               std::to_string(t[1] + 1) + " and " + std::to_string(t[2] + 1));
          }
        if (const auto x = self_intersection(f.polygon.plane_corners, 1e-9 * size))
          throw InputError(parameter,
                           name + " is not a simple polygon: edges " + std::to_string(x->i + 1) +
                             " and " + std::to_string(x->j + 1) +
                             (x->folds ? " fold back onto each other at " : " meet at ") +
                             io::to_text(f.polygon.from_plane(x->where)));
        check_input(f.polygon.area() > 1e-12 * size * size,
                    parameter,
                    name + " has zero area (its corners are collinear)");
      }



      /// The fracture against the box: inside (at least partly), not in a face of the box.
      void
      validate_in_box(const PolygonFracture &f,
                      const Point<3>        &lo,
                      const Point<3>        &hi,
                      const double           tol,
                      const std::string     &parameter)
      {
        const std::string name = "fracture " + std::to_string(f.id);
        for (unsigned int d = 0; d < 3; ++d)
          for (const double bound : {lo[d], hi[d]})
            {
              bool in_face = true;
              for (const auto &x : f.polygon.corners)
                in_face &= std::abs(x[d] - bound) <= tol;
              if (in_face)
                throw InputError(parameter,
                                 name + " lies in the boundary face " + std::string(1, "xyz"[d]) +
                                   " = " + io::to_text(bound) + " of the domain");
            }
        check_input(area_inside_box(f.polygon, lo, hi) > 1e-9 * f.polygon.area(),
                    parameter,
                    name + " lies outside the domain " + io::to_text(lo) + " " + io::to_text(hi));
      }
    } // namespace



    void
    PolygonNetwork::validate(const std::string &parameter) const
    {
      const double tol = tolerance();
      for (const auto &f : fractures)
        {
          validate_shape(f, tol, parameter);
          validate_in_box(f, lo, hi, tol, parameter);
        }
      for (unsigned int i = 0; i < fractures.size(); ++i)
        for (unsigned int j = i + 1; j < fractures.size(); ++j)
          check_input(!coplanar_overlap(fractures[i].polygon, fractures[j].polygon, tol),
                      parameter,
                      "fractures " + std::to_string(fractures[i].id) + " and " +
                        std::to_string(fractures[j].id) + " lie in one plane and overlap");
    }
  } // namespace geometry
} // namespace porofrac
