// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_GMSH_MODEL_H
#define POROFRAC_GEOMETRY_GMSH_MODEL_H

#include <porofrac/geometry/gmsh_session.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/geometry/raw_mesh.h>

#include <string>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    /**
     * Reads the mesh of the current gmsh model into a RawMesh. Physical curves (2D) or surfaces
     * (3D) named "fracture N" become fracture N; other physical groups of codimension one give
     * boundary ids (their physical tag); physical groups of full dimension give material ids.
     * Errors name @p parameter.
     */
    template <int dim>
    RawMesh<dim>
    extract_gmsh_mesh(const std::string &parameter);

    /// A box of Geometry/Refinement regions with its cell size h.
    struct RefinementRegion
    {
      Point<3> lo, hi;
      double   h;
    };

    /// Parses Geometry/Refinement regions, "(x0, y0) (x1, y1): h; ..." (3D: with z).
    std::vector<RefinementRegion>
    parse_refinement_regions(const std::string &text, const unsigned int dim);

    /**
     * Adds to the current gmsh model the size fields every generated mesh has: the refinement
     * boxes (Geometry/Refinement regions, in @p dim coordinates), the size expression and the
     * constant far-field size. Then sets the minimum of those and of @p extra_fields (field tags)
     * as the background mesh, with sizes from points, curvature and boundaries switched off.
     */
    void
    set_background_size(const GeometryParameters &parameters,
                        const unsigned int        dim,
                        std::vector<double>       extra_fields);

    /**
     * Meshes the current gmsh model in @p dim dimensions inside @p session. An error of the
     * size field (a MathEval syntax error, a size <= 0) names Geometry/Mesh size expression when
     * one is set; any other error names Geometry.
     */
    void
    generate_mesh(GmshSession &session, const GeometryParameters &parameters, const int dim);
  } // namespace geometry
} // namespace porofrac

#endif
