// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/random_discs.h>

#include <cmath>
#include <optional>
#include <random>
#include <set>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      const std::string section = "Geometry/Random discs";

      /// Uniform numbers in [0, 1) from the 53 high bits (the same on every platform).
      class UniformSource
      {
      public:
        explicit UniformSource(const unsigned int seed)
            : engine(seed)
        {
        }
        double
        operator()()
        {
          return (engine() >> 11) * 0x1.0p-53;
        }

      private:
        std::mt19937_64 engine;
      };

      /// A unit normal, uniform on the sphere or Fisher-distributed about @p mean.
      Tensor<1, 3>
      draw_normal(const RandomDiscParameters &p, const Tensor<1, 3> &mean, UniformSource &u)
      {
        const double phi = 2 * M_PI * u();
        double       c   = 0; // cosine of the angle to the pole
        if (p.orientation == "uniform")
          c = 2 * u() - 1;
        else
          {
            const double k = p.fisher_concentration;
            c              = 1 + std::log1p(-u() * -std::expm1(-2 * k)) / k;
          }
        const double       s  = std::sqrt(std::max(0., 1 - c * c));
        const Tensor<1, 3> e1 = default_tangent(mean);
        const Tensor<1, 3> e2 = cross_product_3d(mean, e1);
        return c * mean + s * (std::cos(phi) * e1 + std::sin(phi) * e2);
      }

      double
      draw_radius(const RandomDiscParameters &p, UniformSource &u)
      {
        const double a = p.radius_min, b = p.radius_max, x = u();
        if (p.radius_distribution == "uniform" || a == b)
          return a + x * (b - a);
        // Inverse of the CDF of the density r^-e on [a, b].
        const double e = p.power_law_exponent;
        if (std::abs(e - 1) < 1e-12)
          return a * std::pow(b / a, x);
        return std::pow(std::pow(a, 1 - e) + x * (std::pow(b, 1 - e) - std::pow(a, 1 - e)),
                        1 / (1 - e));
      }

      /// The six faces of the box as polygons (for the feature-size tests).
      std::vector<PlanarPolygon>
      box_faces(const Point<3> &lo, const Point<3> &hi)
      {
        std::vector<PlanarPolygon> faces;
        for (unsigned int d = 0; d < 3; ++d)
          for (const double x : {lo[d], hi[d]})
            {
              const unsigned int    a = (d + 1) % 3, b = (d + 2) % 3;
              std::vector<Point<3>> c(4);
              for (unsigned int k = 0; k < 4; ++k)
                {
                  c[k][d] = x;
                  c[k][a] = (k == 1 || k == 2) ? hi[a] : lo[a];
                  c[k][b] = (k >= 2) ? hi[b] : lo[b];
                }
              faces.emplace_back(c, Tensor<1, 3>());
            }
        return faces;
      }

      /// Intersection segments accepted so far, per fracture (network order).
      using Segments = std::vector<std::vector<std::array<Point<3>, 2>>>;

      /**
       * Why @p c cannot join @p network (an empty string if it can); @p mine returns its
       * intersection segments with the network's fractures.
       */
      std::string
      rejection(const PlanarPolygon                                           &c,
                const PolygonNetwork                                          &network,
                const std::vector<PlanarPolygon>                              &faces,
                const Segments                                                &segments,
                const double                                                   h,
                const double                                                   min_sine,
                std::vector<std::pair<unsigned int, std::array<Point<3>, 2>>> &mine)
      {
        const double tol = network.tolerance();
        if (area_inside_box(c, network.lo, network.hi) <= 1e-9 * c.area())
          return "outside the domain";
        for (const auto &f : network.fractures)
          if (coplanar_overlap(c, f.polygon, tol))
            return "in one plane with a fracture it overlaps";
        if (h <= 0)
          return "";
        // A corner just beside a polygon it does not touch leaves a sliver between them.
        auto corner_near = [&](const PlanarPolygon &p, const PlanarPolygon &q) {
          for (const auto &x : p.corners)
            {
              const double d = q.distance(x);
              if (d > tol && d < h)
                return true;
            }
          return false;
        };
        for (const auto &face : faces)
          {
            const double d = polygon_distance(c, face);
            if (d > tol && d < h)
              return "closer than h to the boundary";
            if (corner_near(c, face))
              return "a corner closer than h to the boundary";
            const auto s = intersection_segment(c, face, tol);
            if (s && (*s)[0].distance((*s)[1]) < h)
              return "cuts the boundary in a segment shorter than h";
            if (s && cross_product_3d(c.normal, face.normal).norm() < min_sine)
              return "cuts the boundary at less than the minimum angle";
          }
        for (unsigned int k = 0; k < network.fractures.size(); ++k)
          {
            const auto  &f = network.fractures[k].polygon;
            const double d = polygon_distance(c, f);
            if (d > tol && d < h)
              return "closer than h to a fracture it does not meet";
            if (corner_near(c, f) || corner_near(f, c))
              return "a corner closer than h to a fracture";
            const auto s = intersection_segment(c, f, tol);
            if (!s)
              continue;
            if ((*s)[0].distance((*s)[1]) < h)
              return "meets a fracture in a segment shorter than h";
            if (cross_product_3d(c.normal, f.normal).norm() < min_sine)
              return "meets a fracture at less than the minimum angle";
            for (const auto &other : segments[k])
              {
                const double e = segment_distance((*s)[0], (*s)[1], other[0], other[1]);
                if (e > tol && e < h)
                  return "intersections closer than h on one fracture";
              }
            for (const auto &[j, other] : mine)
              {
                const double e = segment_distance((*s)[0], (*s)[1], other[0], other[1]);
                if (e > tol && e < h)
                  return "intersections closer than h on one fracture";
              }
            mine.emplace_back(k, *s);
          }
        return "";
      }
    } // namespace



    void
    RandomDiscParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Random discs");
      prm.declare_entry("Count",
                        "0",
                        Patterns::Integer(0, 100000),
                        "Number of random disc fractures added to Geometry/Fractures (3D).");
      prm.declare_entry("Seed", "1", Patterns::Integer(0), "Seed of the random generator.");
      prm.declare_entry("First id",
                        "1",
                        Patterns::Integer(0, 999999),
                        "Fracture id of the first disc; the others follow.");
      prm.declare_entry("Radius min", "0.1", Patterns::Double(0), "Smallest radius, in m.");
      prm.declare_entry("Radius max", "0.3", Patterns::Double(0), "Largest radius, in m.");
      prm.declare_entry("Radius distribution",
                        "uniform",
                        Patterns::Selection("uniform|power law"),
                        "Radii uniform in [min, max], or with density proportional to r^-a "
                        "(a = Power law exponent) on [min, max].");
      prm.declare_entry("Power law exponent", "2.5", Patterns::Double(0), "a of the power law.");
      prm.declare_entry("Orientation",
                        "uniform",
                        Patterns::Selection("uniform|fisher"),
                        "Normals uniform on the sphere, or Fisher-distributed about Mean normal "
                        "with concentration kappa = Fisher concentration.");
      prm.declare_entry("Mean normal",
                        "(0, 0, 1)",
                        Patterns::Anything(),
                        "Mean pole of the Fisher distribution, '(x, y, z)'.");
      prm.declare_entry("Fisher concentration",
                        "10",
                        Patterns::Double(0.001),
                        "kappa of the Fisher distribution (-): the larger, the tighter.");
      prm.declare_entry("Sides", "12", Patterns::Integer(3, 1000), "Sides of each disc polygon.");
      prm.declare_entry("Centre region",
                        "",
                        Patterns::Anything(),
                        "Box from which the centres are drawn uniformly, "
                        "'(x0, y0, z0) (x1, y1, z1)', in m; empty: the domain.");
      prm.declare_entry(
        "Minimum feature size",
        "0",
        Patterns::Double(0),
        "h, in m. 0: a candidate disc is redrawn only when it would be invalid input (outside "
        "the domain, or overlapping a fracture in its plane). h > 0: also when it would make a "
        "feature smaller than h (it, or one of its corners, comes closer than h to a fracture or "
        "the boundary without touching it, a fracture's corner comes closer than h to it, it "
        "meets a fracture or the boundary in a segment shorter than h, or its intersections "
        "come closer than h to others on one fracture). Rejections are counted in the mesh "
        "report.");
      prm.declare_entry("Minimum angle",
                        "0",
                        Patterns::Double(0, 90),
                        "With a positive Minimum feature size: a candidate disc that meets a "
                        "fracture or cuts the boundary at an angle below this (degrees) is "
                        "redrawn too (thin wedges need tiny cells).");
      prm.declare_entry("Max attempts",
                        "100",
                        Patterns::Integer(1),
                        "Candidates drawn per disc before the generator gives up (an error).");
      prm.leave_subsection();
    }



    void
    RandomDiscParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Random discs");
      count                = prm.get_integer("Count");
      seed                 = prm.get_integer("Seed");
      first_id             = prm.get_integer("First id");
      radius_min           = prm.get_double("Radius min");
      radius_max           = prm.get_double("Radius max");
      radius_distribution  = prm.get("Radius distribution");
      power_law_exponent   = prm.get_double("Power law exponent");
      orientation          = prm.get("Orientation");
      mean_normal          = prm.get("Mean normal");
      fisher_concentration = prm.get_double("Fisher concentration");
      sides                = prm.get_integer("Sides");
      centre_region        = prm.get("Centre region");
      minimum_feature_size = prm.get_double("Minimum feature size");
      minimum_angle        = prm.get_double("Minimum angle");
      max_attempts         = prm.get_integer("Max attempts");
      prm.leave_subsection();
    }



    RandomDiscStatistics
    add_random_discs(const RandomDiscParameters &p, PolygonNetwork &network)
    {
      check_input(p.radius_min > 0 && p.radius_max >= p.radius_min,
                  section + "/Radius min",
                  "radii must satisfy 0 < Radius min <= Radius max");
      check_input(p.first_id + p.count <= 1000000,
                  section + "/First id",
                  "disc ids must stay below 1000000");
      std::set<unsigned int> ids;
      for (const auto &f : network.fractures)
        ids.insert(f.id);
      for (unsigned int k = 0; k < p.count; ++k)
        check_input(!ids.count(p.first_id + k),
                    section + "/First id",
                    "disc id " + std::to_string(p.first_id + k) + " is a Geometry/Fractures id");
      const auto mean_points =
        PolygonNetwork::parse_points(p.mean_normal, section + "/Mean normal");
      check_input(mean_points.size() == 1 && Tensor<1, 3>(mean_points[0]).norm() > 0,
                  section + "/Mean normal",
                  "needs one non-zero vector '(x, y, z)'");
      const Tensor<1, 3> mean = Tensor<1, 3>(mean_points[0]) / Tensor<1, 3>(mean_points[0]).norm();
      Point<3>           lo = network.lo, hi = network.hi;
      if (!p.centre_region.empty())
        {
          const auto r = PolygonNetwork::parse_points(p.centre_region, section + "/Centre region");
          check_input(r.size() == 2, section + "/Centre region", "needs two corners");
          lo = r[0];
          hi = r[1];
        }

      UniformSource        u(p.seed);
      const auto           faces = box_faces(network.lo, network.hi);
      Segments             segments(network.fractures.size());
      RandomDiscStatistics statistics;
      for (unsigned int attempt = 0; statistics.accepted < p.count; ++attempt)
        {
          check_input(attempt < p.max_attempts * p.count,
                      section + "/Max attempts",
                      "only " + std::to_string(statistics.accepted) + " of " +
                        std::to_string(p.count) + " discs found a place in " +
                        std::to_string(attempt) + " attempts");
          Point<3> centre;
          for (unsigned int d = 0; d < 3; ++d)
            centre[d] = lo[d] + u() * (hi[d] - lo[d]);
          const double       radius = draw_radius(p, u);
          const Tensor<1, 3> normal = draw_normal(p, mean, u);
          const double       turn   = 2 * M_PI * u();

          // The disc is the draw; its inscribed polygon may turn (eight tries within one side)
          // to keep its corners away from other fractures and the boundary.
          std::string                                                   why;
          std::vector<std::pair<unsigned int, std::array<Point<3>, 2>>> mine;
          std::optional<PlanarPolygon>                                  disc;
          for (unsigned int k = 0; k < 8; ++k)
            {
              const double       angle = turn + k * 2 * M_PI / p.sides / 8;
              const Tensor<1, 3> e     = default_tangent(normal);
              const Tensor<1, 3> t1 =
                std::cos(angle) * e + std::sin(angle) * cross_product_3d(normal, e);
              disc.emplace(
                PolygonNetwork::ellipse_corners(centre, normal, t1, radius, radius, p.sides), t1);
              mine.clear();
              why = rejection(*disc,
                              network,
                              faces,
                              segments,
                              p.minimum_feature_size,
                              std::sin(p.minimum_angle * M_PI / 180),
                              mine);
              if (why.rfind("a corner", 0) != 0)
                break;
            }
          if (!why.empty())
            {
              ++statistics.rejected[why];
              continue;
            }
          segments.emplace_back();
          for (const auto &[k, s] : mine)
            {
              segments[k].push_back(s);
              segments.back().push_back(s);
            }
          network.fractures.push_back({p.first_id + statistics.accepted, "disc", *disc});
          ++statistics.accepted;
        }
      return statistics;
    }
  } // namespace geometry
} // namespace porofrac
