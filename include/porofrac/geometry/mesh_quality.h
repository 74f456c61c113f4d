// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_MESH_QUALITY_H
#define POROFRAC_GEOMETRY_MESH_QUALITY_H

#include <porofrac/geometry/cut_mesh.h>

namespace porofrac
{
  namespace geometry
  {
    /**
     * Mesh statistics and TPFA admissibility with circumcentres as cell centres. A connection is
     * an interior face between two cells; for it to be admissible the segment joining the two
     * centres must be orthogonal to the face and cross it in the direction of the normal
     * (positive distance). Boundary and fracture faces need a positive distance from the centre.
     */
    struct MeshQuality
    {
      unsigned int n_cells           = 0;
      unsigned int n_vertices        = 0;
      unsigned int n_fracture_faces  = 0;
      double       min_angle_degrees = 0;
      double       max_angle_degrees = 0;
      /// 3D: smallest and largest dihedral angle between two faces of a tetrahedron.
      double       min_dihedral_degrees = 0;
      double       max_dihedral_degrees = 0;
      unsigned int n_connections        = 0;
      /// Connections whose centre segment deviates from the face normal by more than 1e-8 rad.
      unsigned int n_non_orthogonal = 0;
      /// Connections with (x_L - x_K) . n_KL <= 0 (non-Delaunay pairs).
      unsigned int n_non_positive_distance = 0;
      /// Cells whose circumcentre lies outside the cell (obtuse triangles).
      unsigned int n_centres_outside = 0;
      /// Boundary or fracture faces with (x_sigma - x_K) . n <= 0.
      unsigned int n_boundary_non_positive_distance = 0;
      /// Connections that are not admissible (non-orthogonal or non-positive distance).
      unsigned int
      n_inadmissible() const
      {
        return n_non_orthogonal + n_non_positive_distance;
      }
    };

    template <int dim>
    MeshQuality
    assess_mesh(const CutMesh<dim> &mesh);

    /// Circumcentre of each active cell, by active cell index (the TPFA cell centres).
    template <int dim>
    std::vector<Point<dim>>
    cell_circumcentres(const Triangulation<dim> &triangulation);
  } // namespace geometry
} // namespace porofrac

#endif
