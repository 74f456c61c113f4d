// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_STRUCTURED_MESH_H
#define POROFRAC_GEOMETRY_STRUCTURED_MESH_H

#include <porofrac/geometry/polygon_network.h>
#include <porofrac/geometry/raw_mesh.h>

#include <array>
#include <string>

namespace porofrac
{
  namespace geometry
  {
    /// Parses "nx, ny, nz" (cells per axis, each >= 1); errors name @p parameter.
    std::array<unsigned int, 3>
    parse_structured_cells(const std::string &text, const std::string &parameter);

    /**
     * A Cartesian grid of @p cells cells in the box of @p network, each cell split into the six
     * tetrahedra of Kuhn's subdivision (every one contains the cell's main diagonal, so
     * neighbouring cells agree on their shared faces). All six are inscribed in the cell's
     * circumsphere: their circumcentres coincide at the cell centre, and the TPFA of the
     * tetrahedra is the TPFA of the Cartesian grid. Box faces get boundary ids 0-5 (x min, x
     * max, y min, ...). Each fracture is the set of grid-face triangles whose centroid lies
     * inside its polygon; a fracture that is not exactly a union of grid faces (area mismatch
     * above 1e-9 relative) is an InputError naming @p parameter.
     */
    RawMesh<3>
    structured_box_mesh(const PolygonNetwork              &network,
                        const std::array<unsigned int, 3> &cells,
                        const std::string                 &parameter);
  } // namespace geometry
} // namespace porofrac

#endif
