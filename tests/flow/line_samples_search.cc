// SPDX-License-Identifier: LGPL-2.1-or-later
// flow::cells_along_line finds, for every point of a sample line, the cell a walk from the
// previous point's cell and its neighbours finds, else the first active cell containing the
// point, through a tree of cell bounding boxes. Checked against the same walk with a scan over
// all cells, on a Kuhn-split 8^3 grid cut by three crossing fractures (the diagonal runs along
// the cubes' shared edges, where the walk fails at every cube; lines in a fracture plane and
// along a grid line; a line leaving the box) and on a 2D gmsh mesh with a T: the same cell at
// every point, each containing its point, and the same points outside.

#include <porofrac/flow/line_samples.h>
#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/simplex_tools.h>

#include <array>
#include <iostream>
#include <string>
#include <vector>

using namespace porofrac;
using namespace dealii;

namespace
{
  /// Whether @p p lies in the simplex @p cell (barycentric coordinates >= -1e-10).
  template <int dim, typename Cell>
  bool
  contains(const Cell &cell, const Point<dim> &p)
  {
    std::array<Point<dim>, dim + 1> vertices;
    for (unsigned int i = 0; i <= dim; ++i)
      vertices[i] = cell->vertex(i);
    return geometry::contains<dim>(vertices, p, 1e-10);
  }

  /// The walk of cells_along_line with a scan over all cells where it fails.
  template <int dim>
  std::vector<unsigned int>
  by_scan(const geometry::CutMesh<dim> &mesh, const flow::SampleLine<dim> &line)
  {
    const auto               &tria = mesh.triangulation;
    std::vector<unsigned int> cells(line.n_points, numbers::invalid_unsigned_int);
    auto                      hint = tria.end();
    for (unsigned int k = 0; k < line.n_points; ++k)
      {
        const Point<dim> p =
          line.start + (double(k) / (line.n_points - 1)) * (line.end - line.start);
        auto found = tria.end();
        if (hint != tria.end())
          {
            if (contains<dim>(hint, p))
              found = hint;
            else
              for (const unsigned int f : hint->face_indices())
                if (!hint->at_boundary(f) && contains<dim>(hint->neighbor(f), p))
                  {
                    found = hint->neighbor(f);
                    break;
                  }
          }
        if (found == tria.end())
          for (const auto &cell : tria.active_cell_iterators())
            if (contains<dim>(cell, p))
              {
                found = cell;
                break;
              }
        if (found != tria.end())
          {
            cells[k] = found->active_cell_index();
            hint     = found;
          }
      }
    return cells;
  }

  template <int dim>
  void
  check(const geometry::CutMesh<dim> &mesh, const std::vector<flow::SampleLine<dim>> &lines)
  {
    for (const auto &line : lines)
      {
        const auto   found  = flow::cells_along_line(mesh, line);
        const auto   scan   = by_scan(mesh, line);
        unsigned int differ = 0, outside = 0, not_containing = 0;
        for (unsigned int k = 0; k < line.n_points; ++k)
          {
            differ += found[k] != scan[k];
            if (found[k] == numbers::invalid_unsigned_int)
              {
                ++outside;
                continue;
              }
            const Point<dim> p =
              line.start + (double(k) / (line.n_points - 1)) * (line.end - line.start);
            const typename Triangulation<dim>::active_cell_iterator cell(&mesh.triangulation,
                                                                         0,
                                                                         found[k]);
            not_containing += !contains<dim>(cell, p);
          }
        std::cout << dim << "D line " << line.name << ": " << line.n_points << " points, "
                  << outside << " outside, cells differing from the scan: " << differ
                  << ", cells not containing their point: " << not_containing << std::endl;
      }
  }
} // namespace

int
main()
{
  {
    geometry::GeometryParameters g;
    g.domain           = "box";
    g.box              = "(0, 0, 0) (1, 1, 1)";
    g.structured_cells = "8, 8, 8";
    g.fractures        = "1: (0.5, 0, 0) (0.5, 1, 0) (0.5, 1, 1) (0.5, 0, 1); "
                         "2: (0, 0.5, 0) (1, 0.5, 0) (1, 0.5, 1) (0, 0.5, 1); "
                         "3: (0, 0, 0.5) (1, 0, 0.5) (1, 1, 0.5) (0, 1, 0.5)";
    const auto mesh    = geometry::make_cut_mesh<3>(g);
    check<3>(*mesh,
             {{"diagonal", Point<3>(0, 0, 0), Point<3>(1, 1, 1), 1000},
              {"in_fracture", Point<3>(0.5, 0.1, 0.05), Point<3>(0.5, 0.93, 0.71), 300},
              {"grid_line", Point<3>(0, 0.25, 0.75), Point<3>(1, 0.25, 0.75), 200},
              {"leaving", Point<3>(0.3, 0.2, 0.1), Point<3>(1.4, 0.9, 0.6), 200}});
  }
  {
    geometry::GeometryParameters g;
    g.domain              = "box";
    g.box                 = "(0, 0) (1, 1)";
    g.fractures           = "1: (0.2, 0.5) (0.8, 0.5); 2: (0.5, 0.2) (0.5, 0.5)";
    g.mesh_size           = 0.05;
    g.fracture_mesh_size  = 0.05;
    g.transition_distance = 0.1;
    g.delaunay_flips      = false;
    const auto mesh       = geometry::make_cut_mesh<2>(g);
    check<2>(*mesh,
             {{"diagonal", Point<2>(0, 0), Point<2>(1, 1), 1000},
              {"along_fracture", Point<2>(0.1, 0.5), Point<2>(0.9, 0.5), 500},
              {"leaving", Point<2>(0.5, 0.7), Point<2>(1.5, 0.9), 200}});
  }
}
