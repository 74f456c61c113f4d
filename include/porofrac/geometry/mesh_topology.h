// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_MESH_TOPOLOGY_H
#define POROFRAC_GEOMETRY_MESH_TOPOLOGY_H

#include <deal.II/base/array_view.h>

#include <porofrac/geometry/raw_mesh.h>

#include <array>
#include <map>
#include <set>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    /**
     * The adjacency of an uncut RawMesh that the cut needs: the cells around each vertex (built
     * in time linear in the number of cells, no global face table), the fracture faces by their
     * vertices, and the vertices on fractures and on the listed outer boundary faces.
     */
    template <int dim>
    class MeshTopology
    {
    public:
      /// Vertex indices of a face, sorted.
      using FaceKey = std::array<unsigned int, dim>;

      /// Rejects fracture faces that are not faces of the mesh, lie on its outer boundary or
      /// are listed twice (overlapping fractures), with an InputError.
      explicit MeshTopology(const RawMesh<dim> &raw);

      /// Cells having vertex @p v, in increasing order.
      ArrayView<const unsigned int>
      cells_of_vertex(const unsigned int v) const;

      /// Cells having the face @p key (one on the outer boundary, two inside).
      std::vector<unsigned int>
      cells_of_face(const FaceKey &key) const;

      /// Does the edge between vertices @p a and @p b lie on the outer boundary (on a face of a
      /// single cell)?
      bool
      on_outer_boundary(const unsigned int a, const unsigned int b) const;

      /// Raw fracture face index by its vertices.
      std::map<FaceKey, unsigned int> fracture_face_of_key;
      std::set<unsigned int>          boundary_vertices;
      std::set<unsigned int>          fracture_vertices;

    private:
      const RawMesh<dim>       &raw;
      std::vector<unsigned int> offsets, cells; ///< cells of vertex v: cells[offsets[v]...]
    };

    /**
     * The cut: around each fracture vertex, the cells connected through faces that are not
     * fracture faces form a side region; each region gets its own copy of the vertex (an
     * interior tip has one region, hence one shared vertex). Renumbers @p cut_cells in place and
     * appends the copies to @p cut_vertices; returns the copies of each fracture vertex (the
     * first is the vertex itself).
     */
    template <int dim>
    std::map<unsigned int, std::vector<unsigned int>>
    cut_along_fractures(const RawMesh<dim>                             &raw,
                        const MeshTopology<dim>                        &topology,
                        std::vector<std::array<unsigned int, dim + 1>> &cut_cells,
                        std::vector<Point<dim>>                        &cut_vertices);

    /**
     * The fracture faces (raw indices) whose two sides the cut left joined: every vertex of the
     * face has one side region (it lies on tip edges, or where a tip edge meets the boundary),
     * so the cells on both sides share all its vertices. This happens where one fracture face
     * spans a corner of a fracture.
     */
    template <int dim>
    std::vector<unsigned int>
    unseparated_fracture_faces(const RawMesh<dim>                                   &raw,
                               const MeshTopology<dim>                              &topology,
                               const std::vector<std::array<unsigned int, dim + 1>> &cut_cells);

    /**
     * Splits each of the fracture faces @p faces (raw indices) at its centre, and the two cells
     * on its sides with it (dim children each): the new vertex lies inside the fracture, so the
     * cut opens the pieces. Cells are oriented again afterwards. A face next to a cell that an
     * earlier face of the list split is left for the next call (the topology describes the
     * cells before the splits); returns the number of faces split.
     */
    template <int dim>
    unsigned int
    split_fracture_faces(RawMesh<dim>                    &raw,
                         const MeshTopology<dim>         &topology,
                         const std::vector<unsigned int> &faces);
  } // namespace geometry
} // namespace porofrac

#endif
