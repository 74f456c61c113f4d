// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_MESH_OUTPUT_H
#define POROFRAC_GEOMETRY_MESH_OUTPUT_H

#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <porofrac/geometry/cut_mesh.h>

#include <string>
#include <utility>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    /**
     * Writes @p data_out (patches built) to @p filename as "vtu" or "vtk". VTU is zlib-compressed
     * at the fastest level: deal.II's default (best compression) made output 6 % of the 5.3
     * coupled run (1.2 s per snapshot on the paper mesh).
     */
    template <int dim>
    void
    write_data_out(DataOut<dim> &data_out, const std::string &filename, const std::string &format);

    /// Named per-fracture-face values (one per entry of CutMesh::fracture_faces).
    using FractureFields = std::vector<std::pair<std::string, std::vector<double>>>;

    /**
     * Writes the fracture faces as line (2D) or triangle (3D) cells to @p filename (format "vtu":
     * XML VTK, "vtk": legacy VTK, both ASCII), with fracture_id, face_id, abscissa and
     * distance_to_tip, plus @p fields.
     */
    template <int dim>
    void
    write_fracture_cells(const CutMesh<dim>   &mesh,
                         const std::string    &filename,
                         const std::string    &format,
                         const FractureFields &fields = {});

    /**
     * Writes the fracture edges (3D) as line cells to @p filename with edge_type (0 tip,
     * 1 intersection, 2 boundary), n_faces and the smallest and largest fracture id meeting there.
     */
    template <int dim>
    void
    write_fracture_edges(const CutMesh<dim> &mesh,
                         const std::string  &filename,
                         const std::string  &format);

    /// Named per-cell values (indexed by active cell index).
    using CellFields = std::vector<std::pair<std::string, Vector<double>>>;

    /// Writes per-cell fields on the cut mesh to @p basename.vtu (or .vtk, by @p format).
    template <int dim>
    void
    write_cell_fields(const CutMesh<dim> &mesh,
                      const std::string  &basename,
                      const std::string  &format,
                      const CellFields   &fields);

    /// Writes the cut mesh (material id and circumcentre-inside flag per cell) to
    /// @p basename.vtu/.vtk, its fracture faces to @p basename_fractures.vtu/.vtk and, in 3D,
    /// its fracture edges to @p basename_fracture_edges.vtu/.vtk.
    template <int dim>
    void
    write_mesh(const CutMesh<dim> &mesh, const std::string &basename, const std::string &format);
  } // namespace geometry
} // namespace porofrac

#endif
