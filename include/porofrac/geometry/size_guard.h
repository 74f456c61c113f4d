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
     * domain at Mesh size (or at the Mesh size expression where that is smaller, sampled on a
     * regular grid), the refinement boxes at their sizes, and a band of Transition distance
     * around each fracture in which the size grows linearly from Fracture mesh size, all with
     * cells of regular shape (area sqrt(3)/4 h^2, volume h^3/(6 sqrt(2))). Good to a small
     * factor: it guards against sizes that are orders of magnitude off, it does not predict.
     * Throws an InputError if the Mesh size expression is not positive and finite at a sample
     * point inside the domain.
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
