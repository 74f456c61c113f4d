// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/fracture_network.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

namespace porofrac
{
  namespace geometry
  {
    using io::trim;
    namespace
    {
      double
      cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      double
      distance_to_segment(const Point<2> &x, const Point<2> &a, const Point<2> &b)
      {
        const Tensor<1, 2> d  = b - a;
        const double       l2 = d.norm_square();
        const double       t  = l2 > 0 ? std::clamp((x - a) * d / l2, 0., 1.) : 0.;
        return x.distance(a + t * d);
      }

      /// How two segments [p0,p1] and [q0,q1] meet.
      struct Meeting
      {
        enum Kind
        {
          none,
          point,
          overlap
        } kind     = none;
        double   t = 0, u = 0; ///< parameters on the first and second segment (point)
        Point<2> where;
        Point<2> overlap_begin, overlap_end;
      };

      Meeting
      meet(const Point<2> &p0,
           const Point<2> &p1,
           const Point<2> &q0,
           const Point<2> &q1,
           const double    tol)
      {
        Meeting            m;
        const Tensor<1, 2> r = p1 - p0, s = q1 - q0, qp = q0 - p0;
        const double       rr = r.norm(), ss = s.norm();
        const double       c = cross(r, s);
        if (std::abs(c) <= 1e-12 * rr * ss)
          {
            if (std::abs(cross(qp, r)) / rr > tol)
              return m; // parallel, apart
            // Collinear: overlap of parameter intervals along r.
            double t0 = qp * r / (rr * rr), t1 = (q1 - p0) * r / (rr * rr);
            if (t0 > t1)
              std::swap(t0, t1);
            const double lo = std::max(0., t0), hi = std::min(1., t1);
            if ((hi - lo) * rr > tol)
              {
                m.kind          = Meeting::overlap;
                m.overlap_begin = p0 + lo * r;
                m.overlap_end   = p0 + hi * r;
              }
            else if ((hi - lo) * rr > -tol)
              {
                m.kind  = Meeting::point;
                m.t     = std::clamp(0.5 * (lo + hi), 0., 1.);
                m.where = p0 + m.t * r;
                m.u     = std::clamp((m.where - q0) * s / (ss * ss), 0., 1.);
              }
            return m;
          }
        const double t = cross(qp, s) / c, u = cross(qp, r) / c;
        const double tt = tol / rr, tu = tol / ss;
        if (t < -tt || t > 1 + tt || u < -tu || u > 1 + tu)
          return m;
        m.kind  = Meeting::point;
        m.t     = std::clamp(t, 0., 1.);
        m.u     = std::clamp(u, 0., 1.);
        m.where = p0 + m.t * r;
        return m;
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

      double
      parse_number(const std::string &s, const std::string &parameter)
      {
        try
          {
            std::size_t  used  = 0;
            const double value = std::stod(s, &used);
            if (used == s.size() && std::isfinite(value))
              return value;
          }
        catch (...)
          {
          }
        throw InputError(parameter, "'" + s + "' is not a number");
      }

    } // namespace



    std::vector<Point<2>>
    FractureNetwork::parse_points(const std::string &input, const std::string &parameter)
    {
      std::vector<Point<2>> points;
      const std::string     s   = trim(input);
      std::size_t           pos = 0;
      while (pos < s.size())
        {
          if (std::isspace(static_cast<unsigned char>(s[pos])))
            {
              ++pos;
              continue;
            }
          if (s[pos] != '(')
            throw InputError(parameter,
                             "expected '(' at '" + s.substr(pos, 20) + "'; write points as (x, y)");
          const auto close = s.find(')', pos);
          if (close == std::string::npos)
            throw InputError(parameter, "missing ')' after '" + s.substr(pos, 20) + "'");
          const std::string inner = s.substr(pos + 1, close - pos - 1);
          const auto        comma = inner.find(',');
          if (comma == std::string::npos || inner.find(',', comma + 1) != std::string::npos)
            throw InputError(parameter, "point '(" + inner + ")' must have two coordinates (x, y)");
          points.emplace_back(parse_number(trim(inner.substr(0, comma)), parameter),
                              parse_number(trim(inner.substr(comma + 1)), parameter));
          pos = close + 1;
        }
      return points;
    }



    std::vector<Polyline>
    FractureNetwork::parse_fractures(const std::string &input, const std::string &parameter)
    {
      std::vector<Polyline>  result;
      std::stringstream      all(input);
      std::string            item;
      std::set<unsigned int> ids;
      while (std::getline(all, item, ';'))
        {
          item = trim(item);
          if (item.empty())
            continue;
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            throw InputError(parameter,
                             "fracture '" + item.substr(0, 30) +
                               "' has no id; write 'id: (x, y) (x, y) ...'");
          const std::string id_text = trim(item.substr(0, colon));
          if (id_text.empty() || !std::all_of(id_text.begin(), id_text.end(), ::isdigit) ||
              id_text.size() > 6)
            throw InputError(parameter,
                             "fracture id '" + id_text +
                               "' is not a non-negative integer below 1000000");
          Polyline f;
          f.id     = std::stoul(id_text);
          f.points = parse_points(item.substr(colon + 1), parameter);
          if (!ids.insert(f.id).second)
            throw InputError(parameter, "fracture id " + id_text + " is used twice");
          if (f.points.size() < 2)
            throw InputError(parameter, "fracture " + id_text + " needs at least two points");
          result.push_back(f);
        }
      return result;
    }



    double
    FractureNetwork::diameter() const
    {
      Point<2> lo = domain.corners[0], hi = domain.corners[0];
      for (const auto &p : domain.corners)
        for (unsigned int d = 0; d < 2; ++d)
          {
            lo[d] = std::min(lo[d], p[d]);
            hi[d] = std::max(hi[d], p[d]);
          }
      return lo.distance(hi);
    }



    void
    FractureNetwork::validate(const std::string &parameter) const
    {
      const auto  &poly        = domain.corners;
      const double tol         = 1e-10 * diameter();
      auto         on_boundary = [&](const Point<2> &x) {
        for (unsigned int i = 0; i < poly.size(); ++i)
          if (distance_to_segment(x, poly[i], poly[(i + 1) % poly.size()]) <= tol)
            return true;
        return false;
      };

      for (const auto &f : fractures)
        {
          const std::string name = "fracture " + std::to_string(f.id);
          for (unsigned int k = 0; k + 1 < f.points.size(); ++k)
            if (f.points[k].distance(f.points[k + 1]) <= tol)
              throw InputError(parameter,
                               name + ": segment from " + io::to_text(f.points[k]) + " to " +
                                 io::to_text(f.points[k + 1]) + " has zero length");
          for (unsigned int k = 0; k < f.points.size(); ++k)
            {
              const bool end = (k == 0 || k + 1 == f.points.size());
              if (on_boundary(f.points[k]))
                {
                  if (!end)
                    throw InputError(parameter,
                                     name + ": point " + io::to_text(f.points[k]) +
                                       " lies on the domain boundary; only the end "
                                       "points of a fracture may");
                }
              else if (!inside_polygon(f.points[k], poly))
                throw InputError(parameter,
                                 name + ": point " + io::to_text(f.points[k]) +
                                   " lies outside the domain");
            }
          for (unsigned int k = 0; k + 1 < f.points.size(); ++k)
            {
              const Point<2> &a = f.points[k], &b = f.points[k + 1];
              for (unsigned int i = 0; i < poly.size(); ++i)
                {
                  const Meeting m = meet(a, b, poly[i], poly[(i + 1) % poly.size()], tol);
                  if (m.kind == Meeting::overlap)
                    throw InputError(parameter,
                                     name + " runs along the domain boundary between " +
                                       io::to_text(m.overlap_begin) + " and " +
                                       io::to_text(m.overlap_end));
                  if (m.kind == Meeting::point && m.where.distance(a) > tol &&
                      m.where.distance(b) > tol)
                    throw InputError(parameter,
                                     name + " leaves the domain at " + io::to_text(m.where));
                }
              if (!on_boundary(0.5 * (a + b)) && !inside_polygon(0.5 * (a + b), poly))
                throw InputError(parameter,
                                 name + ": segment from " + io::to_text(a) + " to " +
                                   io::to_text(b) + " lies outside the domain");
              // Self-crossings of the polyline.
              for (unsigned int j = k + 1; j + 1 < f.points.size(); ++j)
                {
                  const Meeting m = meet(a, b, f.points[j], f.points[j + 1], tol);
                  if (m.kind == Meeting::overlap)
                    throw InputError(parameter,
                                     name + " overlaps itself between " +
                                       io::to_text(m.overlap_begin) + " and " +
                                       io::to_text(m.overlap_end));
                  if (m.kind == Meeting::point && j > k + 1)
                    throw InputError(parameter,
                                     name + " crosses itself at " + io::to_text(m.where));
                }
            }
        }

      // Overlaps between different fractures (crossings and touching are allowed).
      for (unsigned int i = 0; i < fractures.size(); ++i)
        for (unsigned int j = i + 1; j < fractures.size(); ++j)
          for (unsigned int k = 0; k + 1 < fractures[i].points.size(); ++k)
            for (unsigned int l = 0; l + 1 < fractures[j].points.size(); ++l)
              {
                const Meeting m = meet(fractures[i].points[k],
                                       fractures[i].points[k + 1],
                                       fractures[j].points[l],
                                       fractures[j].points[l + 1],
                                       tol);
                if (m.kind == Meeting::overlap)
                  throw InputError(parameter,
                                   "fractures " + std::to_string(fractures[i].id) + " and " +
                                     std::to_string(fractures[j].id) + " overlap between " +
                                     io::to_text(m.overlap_begin) + " and " +
                                     io::to_text(m.overlap_end));
              }
    }



    PlanarGraph
    FractureNetwork::planar_graph() const
    {
      PlanarGraph  graph;
      const double tol       = 1e-10 * diameter();
      auto         add_point = [&](const Point<2> &p) {
        for (unsigned int i = 0; i < graph.points.size(); ++i)
          if (graph.points[i].distance(p) <= 1e3 * tol)
            return i;
        graph.points.push_back(p);
        return static_cast<unsigned int>(graph.points.size() - 1);
      };

      // Fracture segments, split where any other fracture segment meets them.
      struct Seg
      {
        Point<2>     a, b;
        unsigned int id;
      };
      std::vector<Seg> segs;
      for (const auto &f : fractures)
        for (unsigned int k = 0; k + 1 < f.points.size(); ++k)
          segs.push_back({f.points[k], f.points[k + 1], f.id});
      for (const auto &c : domain.corners)
        add_point(c);
      for (unsigned int i = 0; i < segs.size(); ++i)
        {
          std::vector<double> ts = {0., 1.};
          for (unsigned int j = 0; j < segs.size(); ++j)
            if (j != i)
              {
                const Meeting m = meet(segs[i].a, segs[i].b, segs[j].a, segs[j].b, tol);
                if (m.kind == Meeting::point)
                  ts.push_back(m.t);
              }
          std::sort(ts.begin(), ts.end());
          for (unsigned int k = 0; k + 1 < ts.size(); ++k)
            {
              const Point<2> p = segs[i].a + ts[k] * (segs[i].b - segs[i].a);
              const Point<2> q = segs[i].a + ts[k + 1] * (segs[i].b - segs[i].a);
              if (p.distance(q) <= 1e3 * tol)
                continue;
              graph.fractures.push_back({add_point(p), add_point(q), segs[i].id});
            }
        }

      // Boundary edges, split at fracture end points lying on them.
      const auto &poly = domain.corners;
      for (unsigned int e = 0; e < poly.size(); ++e)
        {
          const Point<2> &a = poly[e], &b = poly[(e + 1) % poly.size()];
          std::vector<std::pair<double, unsigned int>> on_edge = {{0., add_point(a)},
                                                                  {1., add_point(b)}};
          for (unsigned int i = 0; i < graph.points.size(); ++i)
            if (distance_to_segment(graph.points[i], a, b) <= 1e3 * tol)
              {
                const double t = (graph.points[i] - a) * (b - a) / (b - a).norm_square();
                if (t > 1e-12 && t < 1 - 1e-12)
                  on_edge.emplace_back(t, i);
              }
          std::sort(on_edge.begin(), on_edge.end());
          for (unsigned int k = 0; k + 1 < on_edge.size(); ++k)
            graph.boundary.push_back(
              {on_edge[k].second, on_edge[k + 1].second, domain.edge_ids[e]});
        }
      return graph;
    }
  } // namespace geometry
} // namespace porofrac
