// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_MESH_GENERATOR_H
#define POROFRAC_GEOMETRY_MESH_GENERATOR_H

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/geometry/fracture_network.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/geometry/raw_mesh.h>

#include <memory>

namespace porofrac
{
  namespace geometry
  {
    /// The fracture network a deck describes (2D box or polygon domains).
    FractureNetwork
    network_from_parameters(const GeometryParameters &parameters);

    /// Meshes a validated 2D network with gmsh: fractures are embedded edges, their segments
    /// get round(length / fracture mesh size) faces each.
    RawMesh<2>
    mesh_network(const FractureNetwork &network, const GeometryParameters &parameters);

    /**
     * Reads a gmsh .msh file, or meshes a .geo file. Physical curves (2D) or surfaces (3D) named
     * "fracture N" become fracture N; other physical groups of codimension one give boundary ids
     * (their physical tag); physical groups of full dimension give material ids.
     */
    template <int dim>
    RawMesh<dim>
    read_gmsh_file(const std::string &filename, const std::string &parameter_name);

    /// Everything: network or file, gmsh, global refinements, cut.
    template <int dim>
    std::unique_ptr<CutMesh<dim>>
    make_cut_mesh(const GeometryParameters &parameters);
  } // namespace geometry
} // namespace porofrac

#endif
