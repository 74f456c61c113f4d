// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/point.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/gmsh_model.h>
#include <porofrac/geometry/size_guard.h>
#include <porofrac/io/expression.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <cmath>
#include <functional>
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

      /// Cells on both sides of a fracture of measure @p measure (length or area), in the band
      /// of width D where the size grows linearly from h_f to h: 2 |f| int_0^D dd / v(h(d)).
      double
      fracture_band_cells(const double              measure,
                          const GeometryParameters &prm,
                          const unsigned int        dim)
      {
        const double h_f = prm.fracture_mesh_size, h = std::max(prm.mesh_size, h_f);
        const double D = prm.transition_distance > 0 ? prm.transition_distance : 5 * prm.mesh_size;
        const double per_measure = dim == 2 ?
                                     D / (h_f * h) / cell_measure(1., 2) :
                                     D * (h + h_f) / (2 * h_f * h_f * h * h) / cell_measure(1., 3);
        return 2 * measure * per_measure;
      }

      /// The domain for sampling: its bounding box and a test for points inside it.
      struct SampledDomain
      {
        dealii::Point<3>                              lo, hi;
        std::function<bool(const dealii::Point<3> &)> inside;
      };

      /// Cells of the bulk at Mesh size or, where the Mesh size expression is smaller, at the
      /// expression: the domain measure times the mean of 1 / v(min(h, h_e)) over a regular
      /// grid of points inside the domain. An expression that muparser cannot read is left
      /// to gmsh (the two dialects differ); one that is not finite and positive at a sample
      /// point is refused here, since gmsh would either fail or mesh without end.
      double
      bulk_cells(const double              domain_measure,
                 const double              plain,
                 const SampledDomain      &domain,
                 const GeometryParameters &prm,
                 const unsigned int        dim)
      {
        if (prm.size_expression.empty())
          return plain;
        std::unique_ptr<dealii::FunctionParser<3>> h_e;
        try
          {
            h_e = io::parse_expressions<3>({prm.size_expression}, "Geometry/Mesh size expression");
          }
        catch (const InputError &)
          {
            return plain;
          }
        const unsigned int n       = dim == 2 ? 64 : 24;
        const unsigned int samples = dim == 2 ? (n + 1) * (n + 1) : (n + 1) * (n + 1) * (n + 1);
        double             sum     = 0;
        unsigned int       count   = 0;
        for (unsigned int i = 0; i < samples; ++i)
          {
            dealii::Point<3> p;
            for (unsigned int d = 0, k = i; d < dim; ++d, k /= n + 1)
              p[d] = domain.lo[d] + (domain.hi[d] - domain.lo[d]) * (k % (n + 1)) / n;
            if (!domain.inside(p))
              continue;
            const double h = h_e->value(p);
            if (!(h > 0))
              throw InputError("Geometry/Mesh size expression",
                               "'" + prm.size_expression +
                                 "' is not a valid positive size "
                                 "field: it is " +
                                 io::to_text(h) + " at " + io::to_text(p));
            sum += 1 / cell_measure(std::min(h, prm.mesh_size), dim);
            ++count;
          }
        return count == 0 ? plain : std::max(plain, domain_measure * sum / count);
      }

      /// The sum of the three parts, blamed on the parameter of the largest.
      CellEstimate
      total(const double              domain_measure,
            const SampledDomain      &domain,
            const double              fracture_measure,
            const GeometryParameters &prm,
            const unsigned int        dim)
      {
        const double plain  = domain_measure / cell_measure(prm.mesh_size, dim);
        const double bulk   = bulk_cells(domain_measure, plain, domain, prm, dim);
        double       region = 0;
        for (const auto &r : parse_refinement_regions(prm.refinement_regions, dim))
          {
            double box = 1;
            for (unsigned int d = 0; d < dim; ++d)
              box *= r.hi[d] - r.lo[d];
            region += std::min(box, domain_measure) / cell_measure(r.h, dim);
          }
        const double fracture = fracture_band_cells(fracture_measure, prm, dim);
        const double largest  = std::max({bulk, region, fracture});
        return {bulk + region + fracture,
                largest == bulk ?
                  (bulk > 1.01 * plain ? "Geometry/Mesh size expression" : "Geometry/Mesh size") :
                largest == fracture ? "Geometry/Fracture mesh size" :
                                      "Geometry/Refinement regions"};
      }
    } // namespace



    CellEstimate
    estimate_cells(const FractureNetwork &network, const GeometryParameters &prm)
    {
      const auto &c    = network.domain.corners;
      double      area = 0;
      for (unsigned int i = 0; i < c.size(); ++i)
        area += (c[i][0] * c[(i + 1) % c.size()][1] - c[(i + 1) % c.size()][0] * c[i][1]) / 2;
      double length = 0;
      for (const auto &f : network.fractures)
        for (unsigned int i = 0; i + 1 < f.points.size(); ++i)
          length += f.points[i].distance(f.points[i + 1]);
      SampledDomain domain{
        {c[0][0], c[0][1], 0}, {c[0][0], c[0][1], 0}, [&c](const dealii::Point<3> &p) {
          // Even-odd rule: a ray in +x crosses the boundary an odd number
          // of times from a point inside.
          bool inside = false;
          for (unsigned int i = 0, j = c.size() - 1; i < c.size(); j = i++)
            if ((c[i][1] > p[1]) != (c[j][1] > p[1]) &&
                p[0] < c[j][0] + (c[i][0] - c[j][0]) * (p[1] - c[j][1]) / (c[i][1] - c[j][1]))
              inside = !inside;
          return inside;
        }};
      for (const auto &corner : c)
        for (unsigned int d = 0; d < 2; ++d)
          {
            domain.lo[d] = std::min(domain.lo[d], corner[d]);
            domain.hi[d] = std::max(domain.hi[d], corner[d]);
          }
      return total(area, domain, length, prm, 2);
    }



    CellEstimate
    estimate_cells(const PolygonNetwork &network, const GeometryParameters &prm)
    {
      double volume = 1;
      for (unsigned int d = 0; d < 3; ++d)
        volume *= network.hi[d] - network.lo[d];
      double area = 0;
      for (const auto &f : network.fractures)
        area += f.polygon.area();
      const SampledDomain box{network.lo, network.hi, [](const dealii::Point<3> &) {
                                return true;
                              }};
      return total(volume, box, area, prm, 3);
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
