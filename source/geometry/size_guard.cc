// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/fracture_band.h>
#include <porofrac/geometry/gmsh_model.h>
#include <porofrac/geometry/planar_polygon.h>
#include <porofrac/geometry/size_guard.h>
#include <porofrac/io/expression.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      /// Measure of a regular triangle (2D) or tetrahedron (3D) of edge h.
      double
      cell_measure(const double h, const unsigned int dim)
      {
        return dim == 2 ? std::sqrt(3.) / 4 * h * h : h * h * h / (6 * std::sqrt(2.));
      }

      /// Cells gmsh makes per regular cell of the asked size, measured on the decks of prm/
      /// and their refined variants (contrib/cell-estimate-check, doc/benchmarks/geometry_3d.md).
      double
      gmsh_cells_per_regular_cell(const unsigned int dim)
      {
        return dim == 2 ? 1.15 : 0.65;
      }

      /// The size parameters, in the order of RequestedSize::Part.
      const std::array<const char *, 4> part_names{{"Geometry/Mesh size",
                                                    "Geometry/Fracture mesh size",
                                                    "Geometry/Refinement regions",
                                                    "Geometry/Mesh size expression"}};

      /**
       * The size gmsh is asked for at a point: the smallest of Mesh size, the fracture band,
       * the refinement boxes that hold the point and the Mesh size expression (gmsh's Min
       * field, gmsh_model.cc and the 3D size callback).
       */
      class RequestedSize
      {
      public:
        enum Part
        {
          mesh_size,
          fracture_band,
          region,
          expression
        };

        using Distance = std::function<double(const Point<3> &, double)>;

        RequestedSize(const GeometryParameters &prm, const unsigned int dim, Distance distance)
            : prm(prm)
            , dim(dim)
            , band(prm)
            , regions(parse_refinement_regions(prm.refinement_regions, dim))
            , distance(std::move(distance))
        {
          // An expression that muparser cannot read is left to gmsh (the dialects differ).
          if (!prm.size_expression.empty())
            try
              {
                function =
                  io::parse_expressions<3>({prm.size_expression}, "Geometry/Mesh size expression");
              }
            catch (const InputError &)
              {
              }
        }

        /// The size at @p x and the part that sets it. An expression that is not finite and
        /// positive is refused here: gmsh would either fail or mesh without end.
        std::pair<double, Part>
        at(const Point<3> &x) const
        {
          std::pair<double, Part> h{prm.mesh_size, mesh_size};
          const double            d = distance(x, band.transition);
          if (d < band.transition && band.size(d) < h.first)
            h = {band.size(d), fracture_band};
          for (const auto &r : regions)
            if (r.h < h.first && inside(x, r.lo, r.hi))
              h = {r.h, region};
          if (function)
            {
              const double e = function->value(x);
              if (!(e > 0))
                throw InputError("Geometry/Mesh size expression",
                                 "'" + prm.size_expression +
                                   "' is not a valid positive size field: it is " + io::to_text(e) +
                                   " at " + io::to_text(x));
              if (e < h.first)
                h = {e, expression};
            }
          return h;
        }

        /// A lower bound of the size over the box [lo, hi] from the parts known in closed form
        /// (the expression is only sampled).
        double
        lower_bound(const Point<3> &lo, const Point<3> &hi) const
        {
          const Point<3> centre = 0.5 * (lo + hi);
          const double   radius = 0.5 * lo.distance(hi);
          double         h =
            std::min(prm.mesh_size,
                     band.size(std::max(0., distance(centre, band.transition + radius) - radius)));
          for (const auto &r : regions)
            if (r.h < h && overlaps(lo, hi, r.lo, r.hi))
              h = r.h;
          return h;
        }

      private:
        bool
        inside(const Point<3> &x, const Point<3> &lo, const Point<3> &hi) const
        {
          for (unsigned int d = 0; d < dim; ++d)
            if (x[d] < lo[d] || x[d] > hi[d])
              return false;
          return true;
        }

        bool
        overlaps(const Point<3> &a_lo,
                 const Point<3> &a_hi,
                 const Point<3> &b_lo,
                 const Point<3> &b_hi) const
        {
          for (unsigned int d = 0; d < dim; ++d)
            if (a_hi[d] < b_lo[d] || b_hi[d] < a_lo[d])
              return false;
          return true;
        }

        const GeometryParameters                  &prm;
        const unsigned int                         dim;
        const FractureBand                         band;
        const std::vector<RefinementRegion>        regions;
        const Distance                             distance;
        std::unique_ptr<dealii::FunctionParser<3>> function;
      };

      /// The domain: its bounding box and a test for points inside it.
      struct SampledDomain
      {
        Point<3>                              lo, hi;
        std::function<bool(const Point<3> &)> inside;
      };

      struct Box
      {
        Point<3> lo, hi;
      };

      /// What the samples of one box say: its cells per unit measure by the part that sets the
      /// size, the extremes of the size, and how many samples are inside the domain.
      struct BoxSamples
      {
        std::array<double, 4> density{};
        double                h_min = std::numeric_limits<double>::infinity(), h_max = 0;
        unsigned int          n_inside = 0;
      };

      /**
       * Samples the size at the corners and the centre of @p box, with Simpson's weights along
       * a direction in which h varies: 1/3 the corners' mean, 2/3 the centre (the corners alone
       * overestimate a convex density, the centre underestimates). Points outside the domain
       * count as no cells.
       */
      BoxSamples
      sample(const Box           &box,
             const RequestedSize &size,
             const SampledDomain &domain,
             const unsigned int   dim)
      {
        const unsigned int n_corners = 1u << dim;
        BoxSamples         result;
        for (unsigned int k = 0; k <= n_corners; ++k)
          {
            Point<3> p = 0.5 * (box.lo + box.hi);
            if (k < n_corners)
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = (k >> d) & 1 ? box.hi[d] : box.lo[d];
            if (!domain.inside(p))
              continue;
            ++result.n_inside;
            const auto [h, part] = size.at(p);
            result.h_min         = std::min(result.h_min, h);
            result.h_max         = std::max(result.h_max, h);
            result.density[part] +=
              (k < n_corners ? 1. / (3 * n_corners) : 2. / 3) / cell_measure(h, dim);
          }
        return result;
      }

      /**
       * Integrates 1 / v(h(x)) over the domain, v the measure of a regular cell of edge h,
       * on boxes split in 2^dim until h varies by less than 3/2 over a box or the box is
       * smaller than the cells in it, or its samples are all inside or all outside the domain
       * (and at least min_depth times). Splitting stops after `budget` boxes.
       */
      CellEstimate
      integrate(const RequestedSize &size, const SampledDomain &domain, const unsigned int dim)
      {
        const unsigned int    min_depth = dim == 2 ? 5 : 3, budget = dim == 2 ? 40000 : 60000;
        const unsigned int    n_children = 1u << dim;
        std::array<double, 4> cells{};
        std::vector<Box>      level{{domain.lo, domain.hi}};
        unsigned int          evaluated = 0;
        for (unsigned int depth = 0; !level.empty(); ++depth)
          {
            std::vector<Box> next;
            for (const Box &b : level)
              {
                ++evaluated;
                const BoxSamples samples = sample(b, size, domain, dim);
                double           extent = 0, measure = 1;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    extent = std::max(extent, b.hi[d] - b.lo[d]);
                    measure *= b.hi[d] - b.lo[d];
                  }
                const double h_low   = std::min(samples.h_min, size.lower_bound(b.lo, b.hi));
                const bool   partial = samples.n_inside > 0 && samples.n_inside <= n_children;
                const bool   split =
                  depth < min_depth || (extent > h_low && (samples.h_max > 1.5 * h_low || partial));
                if (split && evaluated + next.size() + n_children <= budget)
                  for (unsigned int k = 0; k < n_children; ++k)
                    {
                      Box            child = b;
                      const Point<3> mid   = 0.5 * (b.lo + b.hi);
                      for (unsigned int d = 0; d < dim; ++d)
                        ((k >> d) & 1 ? child.lo[d] : child.hi[d]) = mid[d];
                      next.push_back(child);
                    }
                else
                  for (unsigned int part = 0; part < cells.size(); ++part)
                    cells[part] += measure * samples.density[part];
              }
            level.swap(next);
          }
        const unsigned int largest = std::max_element(cells.begin(), cells.end()) - cells.begin();
        return {gmsh_cells_per_regular_cell(dim) * (cells[0] + cells[1] + cells[2] + cells[3]),
                part_names[largest]};
      }
    } // namespace



    CellEstimate
    estimate_cells(const FractureNetwork &network, const GeometryParameters &prm)
    {
      const auto   &c = network.domain.corners;
      SampledDomain domain{{c[0][0], c[0][1], 0}, {c[0][0], c[0][1], 0}, [&c](const Point<3> &p) {
                             // Even-odd rule: a ray in +x crosses the boundary an odd number
                             // of times from a point inside (points on it count as inside).
                             bool inside = false;
                             for (unsigned int i = 0, j = c.size() - 1; i < c.size(); j = i++)
                               {
                                 if (distance_to_segment<2>(Point<2>(p[0], p[1]), c[i], c[j]) <
                                     1e-12 * (std::abs(p[0]) + std::abs(p[1]) + 1))
                                   return true;
                                 if ((c[i][1] > p[1]) != (c[j][1] > p[1]) &&
                                     p[0] < c[j][0] + (c[i][0] - c[j][0]) * (p[1] - c[j][1]) /
                                                        (c[i][1] - c[j][1]))
                                   inside = !inside;
                               }
                             return inside;
                           }};
      for (const auto &corner : c)
        for (unsigned int d = 0; d < 2; ++d)
          {
            domain.lo[d] = std::min(domain.lo[d], corner[d]);
            domain.hi[d] = std::max(domain.hi[d], corner[d]);
          }
      const RequestedSize size(prm, 2, [&network](const Point<3> &x, const double cap) {
        return distance_to_fractures(network, x, cap);
      });
      return integrate(size, domain, 2);
    }



    CellEstimate
    estimate_cells(const PolygonNetwork &network, const GeometryParameters &prm)
    {
      const SampledDomain box{network.lo, network.hi, [](const Point<3> &) { return true; }};
      const RequestedSize size(prm, 3, [&network](const Point<3> &x, const double cap) {
        return distance_to_fractures(network, x, cap);
      });
      return integrate(size, box, 3);
    }



    void
    check_cell_count(const double              cells,
                     const GeometryParameters &prm,
                     const std::string        &parameter,
                     const std::string        &how)
    {
      if (cells <= prm.maximum_cells)
        return;
      std::ostringstream message;
      message.precision(3);
      message << "the mesh would have ";
      if (std::isfinite(cells))
        message << how << " " << cells;
      else
        message << "more than 1e+308";
      message << " cells, more than Geometry/Maximum cells = " << prm.maximum_cells
              << "; coarsen the mesh, or raise Geometry/Maximum cells if the machine has the "
                 "memory";
      throw InputError(parameter, message.str());
    }
  } // namespace geometry
} // namespace porofrac
