// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_PARAMETERS_H
#define POROFRAC_GEOMETRY_PARAMETERS_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/geometry/random_discs.h>

#include <string>

namespace porofrac
{
  namespace geometry
  {
    using namespace dealii;

    /// The deck's "Geometry" subsection: domain, fractures, mesh sizes, refinement. The member
    /// defaults equal the declared ones, for code that fills the struct without a deck.
    struct GeometryParameters
    {
      static void
      declare_parameters(ParameterHandler &prm);
      /// Reads the subsection; @p deck_directory resolves relative mesh-file paths.
      void
      parse_parameters(ParameterHandler &prm, const std::string &deck_directory);
      /// Resolves Delaunay flips = auto for a scene of @p physics in @p dim dimensions: TPFA
      /// (Eq. (13)) needs ordered circumcentres, the mechanics' convergence studies nested meshes.
      void
      resolve_delaunay_flips(const std::string &physics, const unsigned int dim);

      std::string  domain = "box";           ///< box | polygon | mesh file
      std::string  box    = "(0, 0) (1, 1)"; ///< "(x0, y0) (x1, y1)" (3D: with z)
      std::string  polygon;                  ///< "(x, y) (x, y) ..." counter-clockwise
      std::string  polygon_ids;              ///< one boundary id per polygon edge, or empty
      std::string  fractures; ///< "id: (x, y) (x, y) ...; id: ..." (3D: polygons, discs)
      std::string  mesh_file; ///< .geo or .msh (domain = mesh file), resolved path
      double       mesh_size           = 0.1;  ///< far from fractures (m)
      double       fracture_mesh_size  = 0.02; ///< along fractures (m)
      double       transition_distance = 0.;   ///< distance over which the size grows (m)
      std::string  size_expression;            ///< optional gmsh MathEval size field in x, y, z
      std::string  refinement_regions;         ///< "(x0, y0) (x1, y1): h; ..."
      std::string  boundary_regions;           ///< "id: condition; ..." relabels outer faces
      std::string  structured_cells; ///< 3D box: "nx, ny, nz" Kuhn-split Cartesian grid, or empty
      unsigned int global_refinements = 0;
      double       maximum_cells      = 5e6; ///< larger meshes are refused before they are made
      /// "auto", "true" or "false"; auto = flips in 2D where two-phase flow runs on the mesh.
      std::string delaunay_flips_mode = "auto";
      bool delaunay_flips   = false; ///< resolved: restore the Delaunay property after refinement
      std::string algorithm = "delaunay";   ///< delaunay | frontal-delaunay
      bool        mesh_optimization = true; ///< 3D: gmsh's tetrahedron optimization after Delaunay
      RandomDiscParameters random_discs;    ///< 3D: the "Random discs" subsection
    };
  } // namespace geometry
} // namespace porofrac

#endif
