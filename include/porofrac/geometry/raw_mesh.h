// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_RAW_MESH_H
#define POROFRAC_GEOMETRY_RAW_MESH_H

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <map>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * A simplex mesh as plain arrays, before it becomes a deal.II Triangulation: the form in which
     * the mesh is generated (gmsh), refined and cut along the fractures. Faces (edges in 2D,
     * triangles in 3D) that lie on the outer boundary or on a fracture are listed with their tag.
     */
    template <int dim>
    struct RawMesh
    {
      /// A codimension-one simplex given by its dim vertex indices and a tag.
      struct TaggedFace
      {
        std::array<unsigned int, dim> vertices;
        unsigned int                  tag;
      };

      std::vector<Point<dim>>                        vertices;
      std::vector<std::array<unsigned int, dim + 1>> cells;
      std::vector<types::material_id>                cell_material;
      /// Faces on the outer boundary; tag = boundary id.
      std::vector<TaggedFace> boundary_faces;
      /// Faces on a fracture; tag = fracture id (each listed once, before cutting).
      std::vector<TaggedFace> fracture_faces;
      /**
       * Optional orientation hint per fracture id (2D): the polyline's first point. The fracture's
       * curvilinear abscissa starts there and n+ is the left normal of the direction of travel.
       */
      std::map<unsigned int, Point<dim>> fracture_start;
      /**
       * Optional orientation hints per fracture id (3D): n+ (the right-hand rule of the polygon's
       * corners) and the first tangent t1 of the fracture's frame.
       */
      std::map<unsigned int, Tensor<1, dim>> fracture_normal, fracture_tangent;

      /// Makes every cell positively oriented (counter-clockwise in 2D).
      void
      orient_cells();

      /**
       * Red refinement: each triangle into four (2D); each tetrahedron into eight by Bey's rule,
       * and each tagged triangle into four (3D). Tags and hints are kept; cells keep the
       * orientation of their parent in 2D (Bey's children do not, orient_cells() fixes that).
       */
      void
      refine_uniformly();

      /**
       * Lawson edge flips (2D) until every edge that is not on the boundary, on a fracture or
       * between two materials satisfies the Delaunay condition: makes TPFA with circumcentres
       * admissible again after red refinement. Returns the number of flips.
       */
      unsigned int
      make_delaunay();

      /// Total measure (area in 2D) of the cells.
      double
      measure() const;
    };
  } // namespace geometry
} // namespace porofrac

#endif
