// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/geometry/planar_polygon.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      double
      cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      /// Do the 2D segments [p0, p1] and [q0, q1] come closer than @p tol? Where, if so.
      std::optional<Point<2>>
      segments_meet(const Point<2> &p0,
                    const Point<2> &p1,
                    const Point<2> &q0,
                    const Point<2> &q1,
                    const double    tol)
      {
        const Tensor<1, 2> r = p1 - p0, s = q1 - q0;
        const double       c = cross(r, s);
        if (std::abs(c) > 1e-12 * r.norm() * s.norm())
          {
            const double t = cross(q0 - p0, s) / c, u = cross(q0 - p0, r) / c;
            if (t >= 0 && t <= 1 && u >= 0 && u <= 1)
              return p0 + t * r;
          }
        // Parallel, or a near miss at an end point.
        for (const auto &[x, a, b] : {std::make_tuple(p0, q0, q1),
                                      std::make_tuple(p1, q0, q1),
                                      std::make_tuple(q0, p0, p1),
                                      std::make_tuple(q1, p0, p1)})
          if (distance_to_segment<2>(x, a, b) <= tol)
            return x;
        return std::nullopt;
      }

      /// Distance from the segment [p, q] to the polygon: 0 if it pierces it.
      double
      segment_to_polygon(const Point<3> &p, const Point<3> &q, const PlanarPolygon &poly)
      {
        const double hp = poly.height(p), hq = poly.height(q);
        if ((hp <= 0 && hq >= 0) || (hp >= 0 && hq <= 0))
          {
            const double   t = (hp == hq) ? 0. : hp / (hp - hq);
            const Point<3> x = p + t * (q - p);
            if (inside_polygon(poly.to_plane(x), poly.plane_corners))
              return 0;
          }
        double      best = std::min(poly.distance(p), poly.distance(q));
        const auto &c    = poly.corners;
        for (unsigned int i = 0; i < c.size(); ++i)
          best = std::min(best, segment_distance(p, q, c[i], c[(i + 1) % c.size()]));
        return best;
      }

      /// Parameter intervals along the line x0 + s d where it runs inside @p poly (which contains
      /// the line's plane intersection with another plane).
      std::vector<std::pair<double, double>>
      line_intervals(const PlanarPolygon &poly,
                     const PlanarPolygon &other,
                     const Point<3>      &x0,
                     const Tensor<1, 3>  &d,
                     const double         tol)
      {
        std::vector<double> s;
        const auto         &c = poly.corners;
        for (unsigned int i = 0; i < c.size(); ++i)
          {
            const Point<3> &a = c[i], &b = c[(i + 1) % c.size()];
            const double    ha = other.height(a), hb = other.height(b);
            // Half-open rule on the corners, so that a crossing at a corner counts once.
            if ((ha > 0) != (hb > 0))
              {
                const Point<3> x = a + (ha / (ha - hb)) * (b - a);
                s.push_back((x - x0) * d);
              }
          }
        std::sort(s.begin(), s.end());
        std::vector<std::pair<double, double>> intervals;
        for (unsigned int i = 0; i + 1 < s.size(); i += 2)
          if (s[i + 1] - s[i] > tol)
            intervals.emplace_back(s[i], s[i + 1]);
        return intervals;
      }
    } // namespace



    Tensor<1, 3>
    vector_area(const std::vector<Point<3>> &corners)
    {
      Tensor<1, 3> n;
      for (unsigned int i = 0; i < corners.size(); ++i)
        n += 0.5 * cross_product_3d(corners[i], corners[(i + 1) % corners.size()]);
      return n;
    }



    Tensor<1, 3>
    default_tangent(const Tensor<1, 3> &normal)
    {
      unsigned int k = 0;
      for (unsigned int d = 1; d < 3; ++d)
        if (std::abs(normal[d]) < std::abs(normal[k]) - 1e-12)
          k = d;
      Tensor<1, 3> e;
      e[k]           = 1;
      Tensor<1, 3> t = e - (e * normal) / normal.norm_square() * normal;
      return t / t.norm();
    }



    template <int dim>
    double
    distance_to_segment(const Point<dim> &x, const Point<dim> &a, const Point<dim> &b)
    {
      const Tensor<1, dim> d  = b - a;
      const double         l2 = d.norm_square();
      const double         t  = l2 > 0 ? std::clamp((x - a) * d / l2, 0., 1.) : 0.;
      return x.distance(a + t * d);
    }



    double
    segment_distance(const Point<3> &p0, const Point<3> &p1, const Point<3> &q0, const Point<3> &q1)
    {
      const Tensor<1, 3> d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
      const double       a = d1 * d1, e = d2 * d2, f = d2 * r, c = d1 * r, b = d1 * d2;
      const double       denom = a * e - b * b;
      double             s     = 0;
      if (a > 0 && denom > 1e-14 * a * e)
        s = std::clamp((b * f - c * e) / denom, 0., 1.);
      double t = e > 0 ? (b * s + f) / e : 0.;
      if (t < 0 || t > 1)
        {
          t = std::clamp(t, 0., 1.);
          s = a > 0 ? std::clamp((b * t - c) / a, 0., 1.) : 0.;
        }
      double best = (p0 + s * d1).distance(q0 + t * d2);
      // Parallel segments: the clamped solution above may miss; the end points settle it.
      best = std::min({best,
                       distance_to_segment<3>(p0, q0, q1),
                       distance_to_segment<3>(p1, q0, q1),
                       distance_to_segment<3>(q0, p0, p1),
                       distance_to_segment<3>(q1, p0, p1)});
      return best;
    }



    bool
    inside_polygon(const Point<2> &x, const std::vector<Point<2>> &poly)
    {
      bool in = false;
      for (unsigned int i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if (((poly[i][1] > x[1]) != (poly[j][1] > x[1])) &&
            (x[0] < (poly[j][0] - poly[i][0]) * (x[1] - poly[i][1]) / (poly[j][1] - poly[i][1]) +
                      poly[i][0]))
          in = !in;
      return in;
    }



    std::optional<SelfIntersection>
    self_intersection(const std::vector<Point<2>> &p, const double tol)
    {
      const unsigned int n = p.size();
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = i + 1; j < n; ++j)
          {
            const bool adjacent = (j == i + 1) || (i == 0 && j == n - 1);
            if (adjacent)
              {
                // Neighbours share a corner; they must not fold back onto each other.
                const unsigned int shared = (j == i + 1) ? j : i;
                const unsigned int a = (shared == j) ? i : j, b = (shared == j) ? (j + 1) % n : 1;
                const Tensor<1, 2> u = p[a] - p[shared], v = p[b] - p[shared];
                if (std::abs(cross(u, v)) <= tol * std::max(u.norm(), v.norm()) && u * v > 0)
                  return SelfIntersection{i, j, p[shared], true};
                continue;
              }
            if (const auto x = segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n], tol))
              return SelfIntersection{i, j, *x, false};
          }
      return std::nullopt;
    }



    std::vector<std::array<unsigned int, 3>>
    triangulate(const std::vector<Point<2>> &poly)
    {
      std::vector<unsigned int> left(poly.size());
      for (unsigned int i = 0; i < left.size(); ++i)
        left[i] = i;
      double area2 = 0;
      for (unsigned int i = 0; i < poly.size(); ++i)
        area2 += cross(poly[i], poly[(i + 1) % poly.size()]);
      const double                             orientation = area2 > 0 ? 1. : -1.;
      std::vector<std::array<unsigned int, 3>> triangles;
      while (left.size() > 3)
        {
          bool clipped = false;
          for (unsigned int k = 0; k < left.size() && !clipped; ++k)
            {
              const unsigned int a = left[(k + left.size() - 1) % left.size()], b = left[k],
                                 c = left[(k + 1) % left.size()];
              if (orientation * cross(poly[b] - poly[a], poly[c] - poly[b]) <= 0)
                continue; // reflex corner
              bool empty = true;
              for (const unsigned int q : left)
                if (q != a && q != b && q != c &&
                    inside_polygon(poly[q], {poly[a], poly[b], poly[c]}))
                  empty = false;
              if (!empty)
                continue;
              triangles.push_back({{a, b, c}});
              left.erase(left.begin() + k);
              clipped = true;
            }
          if (!clipped) // only for degenerate input; validation rejects it before
            break;
        }
      if (left.size() == 3)
        triangles.push_back({{left[0], left[1], left[2]}});
      return triangles;
    }



    PlanarPolygon::PlanarPolygon(const std::vector<Point<3>> &c, const Tensor<1, 3> &tangent)
        : corners(c)
    {
      // A wide triangle of corners: the two farthest apart and the one farthest from their line.
      plane_triangle = {{0, 0, 0}};
      for (unsigned int i = 0; i < c.size(); ++i)
        for (unsigned int j = i + 1; j < c.size(); ++j)
          if (c[i].distance(c[j]) > c[plane_triangle[0]].distance(c[plane_triangle[1]]))
            plane_triangle = {{i, j, 0}};
      const Point<3> &a = c[plane_triangle[0]], &b = c[plane_triangle[1]];
      double          widest = -1;
      for (unsigned int k = 0; k < c.size(); ++k)
        {
          const double w = cross_product_3d(b - a, c[k] - a).norm();
          if (w > widest)
            {
              widest            = w;
              plane_triangle[2] = k;
            }
        }
      Tensor<1, 3> n = cross_product_3d(b - a, c[plane_triangle[2]] - a);
      // n+ is the right-hand rule of the corner order (Newell); the triangle's normal stands in
      // for polygons without area (e.g. bow-ties), which validation rejects.
      const Tensor<1, 3> newell = vector_area(c);
      if (newell.norm() > 1e-12 * a.distance(b) * a.distance(b) || n.norm() == 0)
        n = newell;
      else if (n * newell < 0)
        n *= -1;
      normal = n.norm() > 0 ? n / n.norm() : Tensor<1, 3>({0., 0., 1.});
      for (const auto &x : c)
        origin += x / double(c.size());
      Tensor<1, 3> t = tangent - (tangent * normal) * normal;
      t1             = t.norm() > 1e-12 * tangent.norm() && tangent.norm() > 0 ? t / t.norm() :
                                                                                 default_tangent(normal);
      t2             = cross_product_3d(normal, t1);
      box_lo = box_hi = c[0];
      for (const auto &x : c)
        {
          plane_corners.push_back(to_plane(x));
          for (unsigned int d = 0; d < 3; ++d)
            {
              box_lo[d] = std::min(box_lo[d], x[d]);
              box_hi[d] = std::max(box_hi[d], x[d]);
            }
        }
    }



    Point<2>
    PlanarPolygon::to_plane(const Point<3> &x) const
    {
      return Point<2>((x - origin) * t1, (x - origin) * t2);
    }



    Point<3>
    PlanarPolygon::from_plane(const Point<2> &x) const
    {
      return origin + x[0] * t1 + x[1] * t2;
    }



    double
    PlanarPolygon::height(const Point<3> &x) const
    {
      return (x - origin) * normal;
    }



    double
    PlanarPolygon::area() const
    {
      return std::abs(vector_area(corners) * normal);
    }



    std::pair<unsigned int, double>
    PlanarPolygon::planarity_deviation() const
    {
      const Point<3> &a = corners[plane_triangle[0]];
      Tensor<1, 3>    n =
        cross_product_3d(corners[plane_triangle[1]] - a, corners[plane_triangle[2]] - a);
      if (n.norm() == 0)
        return {0, 0.};
      n /= n.norm();
      std::pair<unsigned int, double> worst = {0, 0.};
      for (unsigned int k = 0; k < corners.size(); ++k)
        if (std::abs((corners[k] - a) * n) > worst.second)
          worst = {k, std::abs((corners[k] - a) * n)};
      return worst;
    }



    double
    PlanarPolygon::distance(const Point<3> &x) const
    {
      const double h = height(x);
      if (inside_polygon(to_plane(x), plane_corners))
        return std::abs(h);
      double best = std::numeric_limits<double>::infinity();
      for (unsigned int i = 0; i < corners.size(); ++i)
        best =
          std::min(best, distance_to_segment<3>(x, corners[i], corners[(i + 1) % corners.size()]));
      return best;
    }



    double
    PlanarPolygon::box_distance(const Point<3> &x) const
    {
      double d2 = 0;
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double g = std::max({box_lo[d] - x[d], 0., x[d] - box_hi[d]});
          d2 += g * g;
        }
      return std::sqrt(d2);
    }



    bool
    PlanarPolygon::contains(const Point<3> &x, const double tol) const
    {
      if (std::abs(height(x)) > tol)
        return false;
      const Point<2> y = to_plane(x);
      if (!inside_polygon(y, plane_corners))
        return false;
      for (unsigned int i = 0; i < plane_corners.size(); ++i)
        if (distance_to_segment<2>(y, plane_corners[i], plane_corners[(i + 1) % corners.size()]) <=
            tol)
          return false;
      return true;
    }



    double
    area_inside_box(const PlanarPolygon &polygon, const Point<3> &lo, const Point<3> &hi)
    {
      std::vector<Point<3>> poly = polygon.corners;
      for (unsigned int d = 0; d < 3 && !poly.empty(); ++d)
        for (const double sign : {1., -1.})
          {
            // Keep sign * (x_d - bound) >= 0.
            const double          bound = sign > 0 ? lo[d] : hi[d];
            std::vector<Point<3>> out;
            for (unsigned int i = 0; i < poly.size(); ++i)
              {
                const Point<3> &a = poly[i], &b = poly[(i + 1) % poly.size()];
                const double    fa = sign * (a[d] - bound), fb = sign * (b[d] - bound);
                if (fa >= 0)
                  out.push_back(a);
                if ((fa >= 0) != (fb >= 0))
                  out.push_back(a + (fa / (fa - fb)) * (b - a));
              }
            poly = out;
            if (poly.empty())
              break;
          }
      return poly.size() < 3 ? 0. : std::abs(vector_area(poly) * polygon.normal);
    }



    bool
    coplanar_overlap(const PlanarPolygon &a, const PlanarPolygon &b, const double tol)
    {
      if (cross_product_3d(a.normal, b.normal).norm() > 1e-9 || std::abs(a.height(b.origin)) > tol)
        return false;
      std::vector<Point<2>> pb;
      for (const auto &x : b.corners)
        pb.push_back(a.to_plane(x));
      const auto &pa = a.plane_corners;
      // Edges crossing properly (away from the end points) mean overlap.
      for (unsigned int i = 0; i < pa.size(); ++i)
        for (unsigned int j = 0; j < pb.size(); ++j)
          {
            const Point<2> &p0 = pa[i], &p1 = pa[(i + 1) % pa.size()];
            const Point<2> &q0 = pb[j], &q1 = pb[(j + 1) % pb.size()];
            const double    c = cross(p1 - p0, q1 - q0);
            if (std::abs(c) <= 1e-12 * (p1 - p0).norm() * (q1 - q0).norm())
              continue;
            const double t = cross(q0 - p0, q1 - q0) / c, u = cross(q0 - p0, p1 - p0) / c;
            const double et = tol / (p1 - p0).norm(), eu = tol / (q1 - q0).norm();
            if (t > et && t < 1 - et && u > eu && u < 1 - eu)
              return true;
          }
      // Otherwise one contains a part of the other: test a point inside each triangle.
      auto any_inside = [](const std::vector<Point<2>> &from, const std::vector<Point<2>> &in) {
        for (const auto &t : triangulate(from))
          if (inside_polygon(Point<2>((from[t[0]] + from[t[1]] + from[t[2]]) / 3.), in))
            return true;
        return false;
      };
      return any_inside(pa, pb) || any_inside(pb, pa);
    }



    double
    polygon_distance(const PlanarPolygon &a, const PlanarPolygon &b)
    {
      double best = std::numeric_limits<double>::infinity();
      for (const auto &[p, q] : {std::make_pair(&a, &b), std::make_pair(&b, &a)})
        for (unsigned int i = 0; i < p->corners.size(); ++i)
          best = std::min(
            best, segment_to_polygon(p->corners[i], p->corners[(i + 1) % p->corners.size()], *q));
      return best;
    }



    std::optional<std::array<Point<3>, 2>>
    intersection_segment(const PlanarPolygon &a, const PlanarPolygon &b, const double tol)
    {
      Tensor<1, 3> d = cross_product_3d(a.normal, b.normal);
      if (d.norm() < 1e-9)
        return std::nullopt;
      d /= d.norm();
      // A point on both planes: the one closest to a's origin.
      const Tensor<1, 3> na = a.normal, nb = b.normal;
      const double       ha = 0, hb = -b.height(a.origin);
      const double       c  = na * nb;
      const double       ka = (ha - hb * c) / (1 - c * c), kb = (hb - ha * c) / (1 - c * c);
      const Point<3>     x0 = a.origin + ka * na + kb * nb;

      const auto ia = line_intervals(a, b, x0, d, tol);
      const auto ib = line_intervals(b, a, x0, d, tol);
      double     lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const auto &[a0, a1] : ia)
        for (const auto &[b0, b1] : ib)
          {
            const double s0 = std::max(a0, b0), s1 = std::min(a1, b1);
            if (s1 - s0 > tol)
              {
                lo = std::min(lo, s0);
                hi = std::max(hi, s1);
              }
          }
      if (!(hi > lo))
        return std::nullopt;
      return std::array<Point<3>, 2>{{x0 + lo * d, x0 + hi * d}};
    }



    template double
    distance_to_segment<2>(const Point<2> &, const Point<2> &, const Point<2> &);
    template double
    distance_to_segment<3>(const Point<3> &, const Point<3> &, const Point<3> &);
  } // namespace geometry
} // namespace porofrac
