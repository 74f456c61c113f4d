// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_FRACTURE_EDGES_H
#define POROFRAC_GEOMETRY_FRACTURE_EDGES_H

#include <porofrac/geometry/cut_mesh.h>

#include <array>
#include <functional>
#include <map>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    /// Every edge of the fracture triangles (3D), as its sorted pair of fracture-node indices,
    /// with the faces that have it (in face order).
    template <int dim>
    std::map<std::array<unsigned int, 2>, std::vector<unsigned int>>
    faces_of_edges(const std::vector<FractureFace<dim>> &faces);

    /**
     * The fracture edges (3D) of a fracture-face table: every edge of a fracture face except
     * those shared by exactly two faces of one fracture. An edge is a boundary edge when
     * @p on_outer_boundary(node a, node b) says so, a tip edge when it has one face, an
     * intersection edge otherwise. Ordered by type, then by their end nodes.
     */
    template <int dim>
    std::vector<FractureEdge<dim>>
    find_fracture_edges(
      const std::vector<FractureFace<dim>>                              &faces,
      const std::vector<FractureNode<dim>>                              &nodes,
      const std::function<bool(const unsigned int, const unsigned int)> &on_outer_boundary);

    /// Sets FractureFace::distance_to_tip (3D): from the face centre to the nearest tip edge of
    /// the same fracture (+infinity without tip edges).
    template <int dim>
    void
    set_distances_to_tip_edges(std::vector<FractureFace<dim>>       &faces,
                               const std::vector<FractureEdge<dim>> &edges,
                               const std::vector<FractureNode<dim>> &nodes);
  } // namespace geometry
} // namespace porofrac

#endif
