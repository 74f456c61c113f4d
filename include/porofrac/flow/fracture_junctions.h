// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_FRACTURE_JUNCTIONS_H
#define POROFRAC_FLOW_FRACTURE_JUNCTIONS_H

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <porofrac/geometry/cut_mesh.h>

#include <array>
#include <vector>

namespace porofrac
{
  namespace flow
  {
    using namespace dealii;

    /**
     * Where fracture cells exchange flux with each other: in 2D a fracture node (a point), in 3D
     * an edge of the fracture triangles (a segment). The two-point fracture fluxes of the paper
     * (Section 4.1) pass through these: a junction with one face is a tip (no flux) or a boundary
     * point/edge, one with two faces joins them directly, one with three or more faces carries an
     * intersection unknown.
     */
    template <int dim>
    struct FractureJunction
    {
      /// Node location (2D) or edge midpoint (3D).
      Point<dim> location;
      /// Measure of the junction without the axisymmetric weight: 1 (2D) or the edge length.
      double measure;
      /// Fracture faces that have this node (2D) or edge (3D).
      std::vector<unsigned int> faces;
      /// Outer boundary id of the junction, numbers::invalid_boundary_id if it is inside.
      types::boundary_id boundary_id = numbers::invalid_boundary_id;
      /// 3D: end points (indices into CutMesh::fracture_nodes).
      std::array<unsigned int, 2> ends{{0, 0}};
    };

    /// Every fracture node (2D) or every fracture-triangle edge (3D) of @p mesh.
    template <int dim>
    std::vector<FractureJunction<dim>>
    fracture_junctions(const geometry::CutMesh<dim> &mesh);

    /**
     * Half-transmissibility distance from the flow centre of fracture face @p face to the
     * junction @p j: 2D the distance from the face centre to the node; 3D, in the face's plane,
     * from the face's circumcentre (the TPFA-admissible centre of a Delaunay triangle) normal to
     * the edge, negative when the circumcentre lies beyond the edge, or with @p centroid from
     * the centroid c, |m - c|^2 / (nu . (m - c)) (m the edge midpoint, nu the in-plane edge
     * normal; TpfaGrid::half_distance).
     */
    template <int dim>
    double
    distance_to_junction(const geometry::CutMesh<dim> &mesh,
                         const unsigned int            face,
                         const FractureJunction<dim>  &j,
                         const bool                    centroid = false);
  } // namespace flow
} // namespace porofrac

#endif
