// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_CUT_MESH_H
#define POROFRAC_GEOMETRY_CUT_MESH_H

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/tria.h>

#include <porofrac/geometry/mesh_build_log.h>
#include <porofrac/geometry/raw_mesh.h>

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    using namespace dealii;

    /// The two sides of a fracture face. n+ points out of the plus side (paper, Section 2).
    enum Side : unsigned int
    {
      plus  = 0,
      minus = 1
    };

    /**
     * Boundary id carried by the faces of fracture @p fracture_id on side @p side in the cut
     * Triangulation. Outer boundary ids must stay below first_fracture_boundary_id.
     */
    constexpr types::boundary_id first_fracture_boundary_id = 1000;
    inline types::boundary_id
    fracture_boundary_id(const unsigned int fracture_id, const Side side)
    {
      return first_fracture_boundary_id + 2 * fracture_id + side;
    }

    /**
     * One fracture face sigma of the paper: a pair of coincident faces of the cut mesh, one on
     * each side. Fields are geometric facts computed once per mesh.
     */
    template <int dim>
    struct FractureFace
    {
      /// Index in CutMesh::fracture_faces (faces sorted by fracture id, then by abscissa).
      unsigned int index;
      /// The user's fracture id.
      unsigned int fracture_id;
      /// The bulk cells on the plus and minus sides, and the local face numbers there.
      std::array<typename Triangulation<dim>::active_cell_iterator, 2> cell;
      std::array<unsigned int, 2>                                      face_no;
      /// Unit normal n+ (outward from the plus side), constant on the face. 3D fractures from a
      /// deck: the right-hand rule of the polygon's corner order (discs: the given normal).
      Tensor<1, dim> normal;
      /// 2D: unit tangent in the direction of increasing abscissa (n+ = its left normal rotated
      /// so that normal = (-t_y, t_x)). 3D: t1 of the fracture's frame (t1, t2, n+), the same
      /// on every face of a planar fracture: the polygon's first edge or the disc's first axis.
      Tensor<1, dim> tangent;
      /// 3D: t2 = n+ x t1 (zero in 2D).
      Tensor<1, dim> tangent2;
      /// |sigma| (length in 2D, area in 3D) and centre of mass.
      double     measure;
      Point<dim> centre;
      /// Curvilinear abscissa along the fracture from its first point: at the centre, and at the
      /// two ends (2D; polylines continue through corners and intersections).
      double abscissa;
      double abscissa_begin;
      double abscissa_end;
      /// Euclidean distance from the centre to the nearest tip of the same fracture (2D: a
      /// corner, an intersection or a point on the outer boundary is not a tip; 3D: the nearest
      /// tip edge, an edge on the outer boundary or on another fracture is not one); +infinity
      /// if none.
      double distance_to_tip;
      /// Uncut vertices of the face as indices into CutMesh::fracture_nodes (2D: in abscissa
      /// order).
      std::array<unsigned int, dim> nodes;
    };

    /// What a fracture node is, from the number and ids of the fracture faces meeting there.
    enum class NodeType
    {
      tip,          ///< end of one fracture inside the domain (one face)
      interior,     ///< two collinear faces of one fracture
      corner,       ///< two non-collinear faces of one fracture
      junction,     ///< two faces of different fractures (an L meeting)
      intersection, ///< three or more faces (X or T)
      boundary      ///< on the outer boundary
    };

    /// A vertex of the uncut mesh that lies on a fracture.
    template <int dim>
    struct FractureNode
    {
      Point<dim> location;
      NodeType   type;
      bool       on_boundary;
      /// Fracture faces having this node as a vertex.
      std::vector<unsigned int> faces;
      /// Vertex indices in the cut Triangulation: one per side region (1 at an interior tip).
      std::vector<unsigned int> copies;
    };

    /// What a fracture edge is (3D).
    enum class EdgeType
    {
      tip,          ///< a fracture ends inside the domain (one face)
      intersection, ///< fractures meet: X, T and L lines (faces of two or more fractures)
      boundary      ///< a fracture meets the outer boundary
    };

    /**
     * A mesh edge of the fracture surfaces (3D) that is not inside a single fracture. The
     * intersection edges are where the flow's intersection unknowns live.
     */
    template <int dim>
    struct FractureEdge
    {
      EdgeType type;
      /// End points as indices into CutMesh::fracture_nodes.
      std::array<unsigned int, 2> nodes;
      /// Fracture faces having this edge, and their distinct fracture ids (increasing).
      std::vector<unsigned int> faces;
      std::vector<unsigned int> fracture_ids;
      double                    length;
      Point<dim>                centre;
    };

    /**
     * A Triangulation cut along the fractures, with the fracture-face table and the fracture
     * nodes. Fracture faces are boundary faces of the Triangulation; both sides of a face carry
     * fracture_boundary_id(fracture id, side).
     */
    template <int dim>
    class CutMesh
    {
    public:
      /// Cuts @p raw along its fracture faces and builds the Triangulation and tables.
      explicit CutMesh(const RawMesh<dim> &raw);

      Triangulation<dim>             triangulation;
      std::vector<FractureFace<dim>> fracture_faces;
      std::vector<FractureNode<dim>> fracture_nodes;
      /// 3D: tip, intersection and boundary edges of the fractures (empty in 2D).
      std::vector<FractureEdge<dim>> fracture_edges;
      /// Fracture ids in increasing order, and the faces of each (ordered by abscissa).
      std::vector<unsigned int>                         fracture_ids;
      std::map<unsigned int, std::vector<unsigned int>> faces_of_fracture;
      /// Outer boundary ids present in the mesh.
      std::vector<types::boundary_id> outer_boundary_ids;
      /// Number of vertices before cutting.
      unsigned int n_uncut_vertices;
      /**
       * Fracture faces the cut would have left joined because all their vertices lie on tips (a
       * face spanning a corner of a fracture): each was split at its centre, with its two cells,
       * before the cut.
       */
      unsigned int n_split_fracture_faces = 0;
      /// Timings and peak memory of the phases that built the mesh (make_cut_mesh adds the
      /// meshing and refinement before the cut).
      MeshBuildLog build_log;

      /// Linear simplex mapping to use with FE_SimplexP on this mesh.
      const Mapping<dim> &
      mapping() const
      {
        return *simplex_mapping;
      }

      /**
       * If face @p face_no of @p cell is a fracture face, returns its index in fracture_faces and
       * the side; returns {numbers::invalid_unsigned_int, plus} otherwise.
       */
      std::pair<unsigned int, Side>
      fracture_face(const typename Triangulation<dim>::active_cell_iterator &cell,
                    const unsigned int                                       face_no) const;

      /// Fracture nodes where three or more fracture faces meet, or where a fracture meets the
      /// outer boundary (the special nodes the flow needs in 2D; in 3D see fracture_edges).
      std::vector<unsigned int>
      special_nodes() const;

      /// Geometric length (2D) or area (3D) of fracture @p fracture_id.
      double
      fracture_measure(const unsigned int fracture_id) const;

    private:
      std::unique_ptr<Mapping<dim>> simplex_mapping;
      /// (active cell index * faces_per_cell + face_no) -> (fracture face, side)
      std::map<unsigned int, std::pair<unsigned int, Side>> face_lookup;
    };
  } // namespace geometry
} // namespace porofrac

#endif
