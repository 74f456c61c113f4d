// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_MESH_OUTPUT_H
#define POROFRAC_GEOMETRY_MESH_OUTPUT_H

#include <deal.II/base/mpi.h>

#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
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

    /**
     * How the processes of a run share a field file. One process, or format "vtk" on a
     * replicated mesh: rank 0 writes the whole file. Otherwise every process writes its own
     * cells as the piece BASENAME_RRRR.vtu (or .vtk) with a `subdomain` field, and rank 0 writes
     * the record BASENAME.pvtu listing the pieces (format "vtu").
     */
    struct OutputPieces
    {
      /// The process of each active cell of a replicated mesh (by active cell index).
      std::vector<unsigned int> cell_owner;
      /// Whether the triangulation holds this process's cells only (a distributed
      /// triangulation, whose DataOut skips the ghost cells itself).
      bool         own_cells_only = false;
      unsigned int rank           = 0;
      unsigned int n_ranks        = 1;

      /// Whether each process writes a piece of a file in @p format.
      bool
      split(const std::string &format) const
      {
        return n_ranks > 1 && (format == "vtu" || own_cells_only);
      }

      /// Whether this process writes the cell of active index @p cell in a file in @p format.
      bool
      writes(const unsigned int cell, const std::string &format) const
      {
        if (!split(format))
          return rank == 0;
        return own_cells_only || cell_owner[cell] == rank;
      }
    };

    /// The pieces of a run on @p communicator whose processes each hold the whole mesh,
    /// partitioned by @p cell_owner (empty on one process).
    OutputPieces
    replicated_mesh_pieces(const std::vector<unsigned int> &cell_owner,
                           const MPI_Comm                   communicator);

    /**
     * Builds the patches of @p data_out (its data vectors attached; @p n_subdivisions per cell,
     * curved by @p mapping) and writes the field file @p basename (a path without extension)
     * in @p format ("vtu" or "vtk") as @p pieces says. Every process of the run calls it.
     * Returns the file a .pvd lists: basename's file name with .vtu, .vtk or .pvtu.
     */
    template <int dim>
    std::string
    write_field_file(DataOut<dim>             &data_out,
                     const Triangulation<dim> &triangulation,
                     const Mapping<dim>       &mapping,
                     const unsigned int        n_subdivisions,
                     const std::string        &basename,
                     const std::string        &format,
                     const OutputPieces       &pieces);

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

    /**
     * Writes per-cell fields on the cut mesh as the field file @p basename, whole or in pieces
     * as @p pieces says (see write_field_file), without DataOut: the mesh vertices as points and
     * each field as Float64 cell data (VTU: zlib-compressed binary; legacy VTK: ASCII). Every
     * process of the run calls it. Returns the file a .pvd lists.
     */
    template <int dim>
    std::string
    write_cell_fields(const CutMesh<dim> &mesh,
                      const std::string  &basename,
                      const std::string  &format,
                      const CellFields   &fields,
                      const OutputPieces &pieces = OutputPieces());

    /// Writes the cut mesh (material id and circumcentre-inside flag per cell) as the field file
    /// @p basename (write_field_file: whole, or one piece per process), its fracture faces to
    /// @p basename_fractures.vtu/.vtk and, in 3D, its fracture edges to
    /// @p basename_fracture_edges.vtu/.vtk (these two by rank 0). Every process of the run
    /// calls it.
    template <int dim>
    void
    write_mesh(const CutMesh<dim> &mesh,
               const std::string  &basename,
               const std::string  &format,
               const OutputPieces &pieces = OutputPieces());
  } // namespace geometry
} // namespace porofrac

#endif
