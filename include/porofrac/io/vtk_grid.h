// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_VTK_GRID_H
#define POROFRAC_IO_VTK_GRID_H

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace porofrac
{
  namespace io
  {
    /// Named values, one per cell of a VtkGrid.
    using VtkCellData = std::vector<std::pair<std::string, std::vector<double>>>;

    /**
     * An unstructured grid of linear cells with per-cell data, held as VTK stores it. Field files
     * of piecewise-constant fields are written from it directly: one point per mesh vertex and
     * one value per cell, instead of DataOut's patch per cell with its own points and point data
     * (8 times fewer point records on tetrahedra, and no patches to build).
     */
    struct VtkGrid
    {
      /// Coordinates, three per point (z = 0 in 2D).
      std::vector<double> points;
      /// The point indices of every cell, one cell after the other.
      std::vector<std::int32_t> connectivity;
      /// Where each cell's indices end in connectivity.
      std::vector<std::int32_t> offsets;
      /// The VTK cell type of each cell (VTK_LINE 3, VTK_TRIANGLE 5, VTK_TETRA 10, ...).
      std::vector<std::uint8_t> types;
      VtkCellData               cell_data;

      std::size_t
      n_points() const
      {
        return points.size() / 3;
      }

      std::size_t
      n_cells() const
      {
        return types.size();
      }

      /// Appends a point (@p z = 0 in 2D); returns its index.
      std::int32_t
      add_point(const double x, const double y, const double z);

      /// Appends a cell of VTK type @p type on the points @p point_indices (VTK's vertex order).
      void
      add_cell(const std::uint8_t type, const std::vector<std::int32_t> &point_indices);
    };

    /// How a VTU file stores its arrays: ASCII text, or zlib-compressed binary in base64.
    enum class VtuEncoding
    {
      ascii,
      compressed
    };

    /**
     * Writes @p grid to @p filename as @p format "vtu" (XML, in @p encoding) or "vtk" (legacy,
     * ASCII). Doubles are written with every digit (ASCII) or bit (binary). A file that cannot be
     * written is an InputError of Output/Directory (io::OutputFile).
     */
    void
    write_vtk_grid(const VtkGrid     &grid,
                   const std::string &filename,
                   const std::string &format,
                   const VtuEncoding  encoding);

    /// Writes the record @p filename (.pvtu) of the VTU @p pieces (paths relative to the record),
    /// whose cell data are the Float64 arrays @p cell_data_names.
    void
    write_pvtu_record(const std::string              &filename,
                      const std::vector<std::string> &pieces,
                      const std::vector<std::string> &cell_data_names);
  } // namespace io
} // namespace porofrac

#endif
