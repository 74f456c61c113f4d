// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_POLYGON_MESHER_H
#define POROFRAC_GEOMETRY_POLYGON_MESHER_H

#include <porofrac/geometry/parameters.h>
#include <porofrac/geometry/polygon_network.h>
#include <porofrac/geometry/random_discs.h>
#include <porofrac/geometry/raw_mesh.h>

namespace porofrac
{
  namespace geometry
  {
    /// The 3D fracture network a deck describes (box domain, Geometry/Fractures and the
    /// Geometry/Random discs), validated; what the disc generator did goes to @p statistics.
    PolygonNetwork
    polygon_network_from_parameters(const GeometryParameters &parameters,
                                    RandomDiscStatistics     *statistics = nullptr);

    /**
     * Meshes a validated 3D network with gmsh's OpenCASCADE kernel: the fracture polygons and the
     * box are fragmented, so that intersection lines, T lines and the lines where fractures meet
     * the boundary are edges of the mesh, and parts of fractures outside the box are dropped.
     * Cells are sized by the distance to the nearest fracture (Geometry/Fracture mesh size on
     * the fractures, growing linearly to Geometry/Mesh size over Geometry/Transition distance),
     * the refinement regions and the size expression. The fracture orientation (n+ by the
     * right-hand rule, t1) is passed on as hints.
     */
    RawMesh<3>
    mesh_polygon_network(const PolygonNetwork &network, const GeometryParameters &parameters);
  } // namespace geometry
} // namespace porofrac

#endif
