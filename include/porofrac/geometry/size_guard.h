// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_SIZE_GUARD_H
#define POROFRAC_GEOMETRY_SIZE_GUARD_H

#include <porofrac/geometry/fracture_network.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/geometry/polygon_network.h>

#include <string>

namespace porofrac
{
  namespace geometry
  {
    /// Estimated cells, and the size parameter of the largest part of them.
    struct CellEstimate
    {
      double      cells;
      std::string parameter;
    };

    /**
     * Estimates the number of cells gmsh makes for a generated domain, before meshing: the
     * integral over the domain of 1 / v(h(x)), h(x) the size gmsh is asked for (the smallest of
     * Mesh size, the fracture band of fracture_band.h, the refinement boxes and the Mesh size
     * expression) and v(h) the measure of a regular cell of edge h, times the cells gmsh makes
     * per such cell (measured). The integral is taken on boxes split where h varies, h sampled
     * at their corners and centres, so a size expression with features finer than those boxes
     * may be missed. Within a factor of 2 on the decks of prm/ and their refined variants,
     * except meshes of about a thousand cells and fewer (underestimated). Throws an InputError if
     * the Mesh size expression is not positive and finite at a sample point inside the domain.
     */
    CellEstimate
    estimate_cells(const FractureNetwork &network, const GeometryParameters &parameters);

    CellEstimate
    estimate_cells(const PolygonNetwork &network, const GeometryParameters &parameters);

    /**
     * Refuses a mesh of @p cells cells (estimated or counted, as @p how says) above
     * Geometry/Maximum cells, with an InputError naming @p parameter, the parameter that
     * makes the mesh that large.
     */
    void
    check_cell_count(const double              cells,
                     const GeometryParameters &parameters,
                     const std::string        &parameter,
                     const std::string        &how);
  } // namespace geometry
} // namespace porofrac

#endif
