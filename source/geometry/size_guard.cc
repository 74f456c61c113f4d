// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/gmsh_model.h>
#include <porofrac/geometry/size_guard.h>

#include <algorithm>
#include <cmath>
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

      /// The sum of the three parts, blamed on the parameter of the largest.
      CellEstimate
      total(const double              domain_measure,
            const double              fracture_measure,
            const GeometryParameters &prm,
            const unsigned int        dim)
      {
        const double bulk   = domain_measure / cell_measure(prm.mesh_size, dim);
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
                largest == bulk     ? "Geometry/Mesh size" :
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
      return total(area, length, prm, 2);
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
      return total(volume, area, prm, 3);
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
      message << "the mesh would have " << how << " " << cells
              << " cells, more than Geometry/Maximum cells = " << prm.maximum_cells
              << "; coarsen the mesh, or raise Geometry/Maximum cells if the machine has the "
                 "memory";
      throw InputError(parameter, message.str());
    }
  } // namespace geometry
} // namespace porofrac
