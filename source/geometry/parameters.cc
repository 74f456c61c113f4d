// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/geometry/parameters.h>
#include <porofrac/geometry/random_discs.h>

namespace porofrac
{
  namespace geometry
  {
    void
    GeometryParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Domain",
                        "box",
                        Patterns::Selection("box|polygon|mesh file"),
                        "Kind of domain: an axis-aligned box (boundary ids 0: x min, 1: x max, "
                        "2: y min, 3: y max, and in 3D 4: z min, 5: z max), a polygon (2D), or a "
                        "gmsh mesh file.");
      prm.declare_entry("Box",
                        "(0, 0) (1, 1)",
                        Patterns::Anything(),
                        "Lower and upper corners of the box domain, in m: '(x0, y0) (x1, y1)', "
                        "in 3D '(x0, y0, z0) (x1, y1, z1)'.");
      prm.declare_entry("Polygon",
                        "",
                        Patterns::Anything(),
                        "Corners of a polygonal domain, counter-clockwise, in m: "
                        "'(x, y) (x, y) (x, y) ...'.");
      prm.declare_entry("Polygon boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, 999)),
                        "Boundary id of each polygon edge (edge k joins corners k and k+1); "
                        "empty: edge k gets id k.");
      prm.declare_entry("Fractures",
                        "",
                        Patterns::Anything(),
                        "Fractures with ids, in m, separated by ';'. 2D: polylines "
                        "'id: (x, y) (x, y) ...'; they may cross or meet (X, T, L), may end on "
                        "the outer boundary, and must not overlap or leave the domain. 3D: planar "
                        "polygons 'id: (x, y, z) (x, y, z) (x, y, z) ...' (n+ by the right-hand "
                        "rule of the corner order, t1 along the first edge), discs 'id: disc "
                        "centre (x, y, z) normal (x, y, z) radius r [sides n]' or with 'axes "
                        "(x, y, z) (x, y, z)' (n+ = axis 1 x axis 2, t1 = axis 1) instead of the "
                        "normal, and ellipses 'id: ellipse centre (x, y, z) axes (x, y, z) "
                        "(x, y, z) radii a b [sides n]' (16 sides by default); they may cross, "
                        "end on each other, touch or cut the boundary (the part outside is "
                        "dropped), and must be planar, simple, not in a boundary face, and not "
                        "overlap another fracture in its plane.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "gmsh .geo or .msh file (Domain = mesh file), relative to the deck. "
                        "Physical groups named 'fracture N' are fractures; other codimension-one "
                        "groups give boundary ids, full-dimensional groups material ids.");
      prm.declare_entry("Mesh size",
                        "0.1",
                        Patterns::Double(0),
                        "Target cell size far from the fractures, in m.");
      prm.declare_entry("Fracture mesh size",
                        "0.02",
                        Patterns::Double(0),
                        "Fracture face size, in m. 2D: each straight fracture segment gets "
                        "round(length / size) faces (at least one). 3D: the target edge length "
                        "of the fracture triangles.");
      prm.declare_entry("Transition distance",
                        "0",
                        Patterns::Double(0),
                        "Distance from the fractures over which the cell size grows linearly "
                        "from the fracture mesh size to the mesh size, in m (0: five times the "
                        "mesh size).");
      prm.declare_entry("Mesh size expression",
                        "",
                        Patterns::Anything(),
                        "Optional extra size field, a gmsh MathEval expression of x, y, z "
                        "(e.g. '0.03 + 0.03*(y-5)'); the smallest of all size fields wins.");
      prm.declare_entry("Refinement regions",
                        "",
                        Patterns::Anything(),
                        "Boxes with their own cell size: '(x0, y0) (x1, y1): h; ...', in 3D "
                        "'(x0, y0, z0) (x1, y1, z1): h; ...', in m.");
      prm.declare_entry("Boundary regions",
                        "",
                        Patterns::Anything(),
                        "Outer boundary faces that get another boundary id: 'id: condition; "
                        "...', a condition being a muparser expression of x, y (, z), true "
                        "(non-zero) at the face's centroid, e.g. '10: x < 1e-9 && z > 90'. The "
                        "first matching region wins; ids 0-999. Applied to the generated or read "
                        "mesh after the global refinements (a face is in or out as a whole: the "
                        "mesh need not follow the region's border).");
      prm.declare_entry("Structured cells",
                        "",
                        Patterns::Anything(),
                        "3D box domains: 'nx, ny, nz' meshes the box as a Cartesian grid of "
                        "nx x ny x nz cells, each split into six tetrahedra (Kuhn), instead of "
                        "gmsh's unstructured mesh; the fractures must be unions of grid faces "
                        "(polygons with corners on grid lines of a grid plane). Two-point fluxes "
                        "with circumcentres are those of the Cartesian grid there. Empty: gmsh.");
      prm.declare_entry("Global refinements",
                        "0",
                        Patterns::Integer(0, 8),
                        "Uniform refinements of the generated mesh before the cut. 2D: each "
                        "splits every triangle into four and every fracture face into two. 3D: "
                        "Bey's red refinement, every tetrahedron into eight and every fracture "
                        "face into four (nested meshes, fracture faces stay paired).");
      prm.declare_entry("Maximum cells",
                        "5e6",
                        Patterns::Double(1),
                        "Meshes with more cells are refused before they are made: the cells of "
                        "a generated mesh are estimated from the domain, the mesh sizes, the "
                        "size expression (sampled) and the fractures before gmsh runs (within "
                        "a factor of 2 on the decks of prm/ and their refined variants), and "
                        "counted before the global refinements. "
                        "Building a 3D mesh of 1.9 million cells takes 1.3 GB; solving on it "
                        "takes many times more. Raise it on machines with the memory.");
      prm.declare_entry(
        "Delaunay flips",
        "auto",
        Patterns::Selection("auto|true|false"),
        "Flip edges (never fracture, boundary or material-interface edges) after "
        "meshing and refinement until the mesh is Delaunay: TPFA with circumcentres "
        "then has no connection of non-positive distance (doc/algorithms.md). auto: "
        "flips in 2D scenes with two-phase flow (two-phase flow, poromechanics), none "
        "for contact mechanics, whose refined meshes stay nested for convergence "
        "studies. 2D only (3D flow keeps unsigned distances where centres are out of "
        "order, and reports them).");
      prm.declare_entry("Mesh algorithm",
                        "delaunay",
                        Patterns::Selection("delaunay|frontal-delaunay"),
                        "gmsh 2D meshing algorithm (in 3D for the boundary and fracture "
                        "surfaces; the volume is always meshed by gmsh's Delaunay algorithm); "
                        "Delaunay meshes suit TPFA best.");
      prm.declare_entry("Mesh optimization",
                        "true",
                        Patterns::Bool(),
                        "3D: let gmsh optimize the tetrahedra after its Delaunay meshing (edge "
                        "swaps and node moves by quality). It removes the slivers (dihedral "
                        "angles near 0 and 180 degrees) that Delaunay meshes have, at the price of "
                        "some connections that are no longer Delaunay (TPFA with circumcentres "
                        "then has non-positive distances); doc/geometry.md has the numbers.");
      RandomDiscParameters::declare_parameters(prm);
      prm.leave_subsection();
    }



    void
    GeometryParameters::parse_parameters(ParameterHandler &prm, const std::string &deck_directory)
    {
      prm.enter_subsection("Geometry");
      domain      = prm.get("Domain");
      box         = prm.get("Box");
      polygon     = prm.get("Polygon");
      polygon_ids = prm.get("Polygon boundary ids");
      fractures   = prm.get("Fractures");
      mesh_file   = prm.get("Mesh file");
      if (!mesh_file.empty() && mesh_file[0] != '/' && !deck_directory.empty())
        mesh_file = deck_directory + "/" + mesh_file;
      mesh_size           = prm.get_double("Mesh size");
      fracture_mesh_size  = prm.get_double("Fracture mesh size");
      transition_distance = prm.get_double("Transition distance");
      size_expression     = prm.get("Mesh size expression");
      refinement_regions  = prm.get("Refinement regions");
      boundary_regions    = prm.get("Boundary regions");
      structured_cells    = Utilities::trim(prm.get("Structured cells"));
      global_refinements  = prm.get_integer("Global refinements");
      maximum_cells       = prm.get_double("Maximum cells");
      delaunay_flips_mode = prm.get("Delaunay flips");
      delaunay_flips      = delaunay_flips_mode == "true";
      algorithm           = prm.get("Mesh algorithm");
      mesh_optimization   = prm.get_bool("Mesh optimization");
      random_discs.parse_parameters(prm);
      prm.leave_subsection();
    }



    void
    GeometryParameters::resolve_delaunay_flips(const std::string &physics, const unsigned int dim)
    {
      if (delaunay_flips_mode == "auto")
        delaunay_flips = dim == 2 && (physics == "two-phase flow" || physics == "poromechanics");
    }
  } // namespace geometry
} // namespace porofrac
