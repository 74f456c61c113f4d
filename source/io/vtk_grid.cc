// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/exceptions.h>

#include <porofrac/io/output_file.h>
#include <porofrac/io/vtk_grid.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <type_traits>

#include <zlib.h>

namespace porofrac
{
  namespace io
  {
    std::int32_t
    VtkGrid::add_point(const double x, const double y, const double z)
    {
      points.insert(points.end(), {x, y, z});
      return static_cast<std::int32_t>(n_points() - 1);
    }



    void
    VtkGrid::add_cell(const std::uint8_t type, const std::vector<std::int32_t> &point_indices)
    {
      connectivity.insert(connectivity.end(), point_indices.begin(), point_indices.end());
      offsets.push_back(static_cast<std::int32_t>(connectivity.size()));
      types.push_back(type);
    }



    namespace
    {
      /// Base64 (RFC 4648, with padding) of @p n bytes at @p data, appended to @p out.
      void
      append_base64(const unsigned char *data, const std::size_t n, std::string &out)
      {
        static const char table[] =
          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        out.reserve(out.size() + 4 * ((n + 2) / 3));
        std::size_t i = 0;
        for (; i + 2 < n; i += 3)
          {
            const unsigned int v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
            out += {table[v >> 18], table[(v >> 12) & 63], table[(v >> 6) & 63], table[v & 63]};
          }
        if (i + 1 == n)
          {
            const unsigned int v = data[i] << 16;
            out += {table[v >> 18], table[(v >> 12) & 63], '=', '='};
          }
        else if (i + 2 == n)
          {
            const unsigned int v = (data[i] << 16) | (data[i + 1] << 8);
            out += {table[v >> 18], table[(v >> 12) & 63], table[(v >> 6) & 63], '='};
          }
      }

      /**
       * The text of a compressed binary DataArray of @p n_bytes at @p data, as VTK's
       * vtkZLibDataCompressor writes it: the UInt32 header (number of blocks, block size, size
       * of the last block, compressed size of each block) in base64, then the base64 of the
       * compressed blocks one after the other.
       */
      std::string
      compressed_base64(const void *data, const std::size_t n_bytes)
      {
        constexpr std::size_t block_size = std::size_t(1) << 20;
        const auto           *bytes      = static_cast<const unsigned char *>(data);
        const std::size_t     n_blocks   = (n_bytes + block_size - 1) / block_size;
        const std::size_t last_block = n_blocks == 0 ? 0 : n_bytes - (n_blocks - 1) * block_size;
        std::vector<std::uint32_t> header = {static_cast<std::uint32_t>(n_blocks),
                                             static_cast<std::uint32_t>(block_size),
                                             static_cast<std::uint32_t>(last_block)};
        std::vector<unsigned char> compressed;
        for (std::size_t b = 0; b < n_blocks; ++b)
          {
            const std::size_t length = std::min(block_size, n_bytes - b * block_size);
            uLongf            size   = compressBound(length);
            const std::size_t start  = compressed.size();
            compressed.resize(start + size);
            const int status =
              compress2(compressed.data() + start, &size, bytes + b * block_size, length, 1);
            AssertThrow(status == Z_OK, dealii::ExcMessage("zlib could not compress an array"));
            compressed.resize(start + size);
            header.push_back(static_cast<std::uint32_t>(size));
          }
        std::string text;
        append_base64(reinterpret_cast<const unsigned char *>(header.data()),
                      header.size() * sizeof(std::uint32_t),
                      text);
        append_base64(compressed.data(), compressed.size(), text);
        return text;
      }

      template <typename T>
      const char *
      vtk_type_name()
      {
        if (std::is_same_v<T, double>)
          return "Float64";
        if (std::is_same_v<T, std::int32_t>)
          return "Int32";
        return "UInt8";
      }

      /// Writes @p values as ASCII text, @p separator after each; doubles with every digit.
      template <typename T>
      void
      write_ascii(std::ostream &out, const std::vector<T> &values, const char separator)
      {
        for (const T v : values)
          {
            if constexpr (std::is_same_v<T, std::uint8_t>)
              out << static_cast<int>(v) << separator;
            else
              out << v << separator;
          }
      }

      /// A DataArray element of a VTU file.
      template <typename T>
      void
      write_data_array(std::ostream         &out,
                       const std::vector<T> &values,
                       const std::string    &name,
                       const unsigned int    n_components,
                       const VtuEncoding     encoding)
      {
        out << "<DataArray type=\"" << vtk_type_name<T>() << "\"";
        if (!name.empty())
          out << " Name=\"" << name << "\"";
        if (n_components > 1)
          out << " NumberOfComponents=\"" << n_components << "\"";
        if (encoding == VtuEncoding::ascii)
          {
            out << " format=\"ascii\">\n";
            write_ascii(out, values, ' ');
          }
        else
          out << " format=\"binary\">\n"
              << compressed_base64(values.data(), values.size() * sizeof(T));
        out << "\n</DataArray>\n";
      }

      void
      write_vtu(std::ostream &out, const VtkGrid &grid, const VtuEncoding encoding)
      {
        out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
            << "byte_order=\"LittleEndian\" header_type=\"UInt32\"";
        if (encoding == VtuEncoding::compressed)
          out << " compressor=\"vtkZLibDataCompressor\"";
        out << ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << grid.n_points()
            << "\" NumberOfCells=\"" << grid.n_cells() << "\">\n<Points>\n";
        write_data_array(out, grid.points, "", 3, encoding);
        out << "</Points>\n<Cells>\n";
        write_data_array(out, grid.connectivity, "connectivity", 1, encoding);
        write_data_array(out, grid.offsets, "offsets", 1, encoding);
        write_data_array(out, grid.types, "types", 1, encoding);
        out << "</Cells>\n<CellData>\n";
        for (const auto &[name, values] : grid.cell_data)
          write_data_array(out, values, name, 1, encoding);
        out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
      }

      void
      write_legacy_vtk(std::ostream &out, const VtkGrid &grid)
      {
        out << "# vtk DataFile Version 3.0\nPoroFrac\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS "
            << grid.n_points() << " double\n";
        for (std::size_t i = 0; i < grid.n_points(); ++i)
          out << grid.points[3 * i] << ' ' << grid.points[3 * i + 1] << ' '
              << grid.points[3 * i + 2] << '\n';
        out << "CELLS " << grid.n_cells() << ' ' << grid.n_cells() + grid.connectivity.size()
            << '\n';
        std::int32_t start = 0;
        for (const std::int32_t end : grid.offsets)
          {
            out << end - start;
            for (std::int32_t k = start; k < end; ++k)
              out << ' ' << grid.connectivity[k];
            out << '\n';
            start = end;
          }
        out << "CELL_TYPES " << grid.n_cells() << '\n';
        write_ascii(out, grid.types, '\n');
        out << "CELL_DATA " << grid.n_cells() << '\n';
        for (const auto &[name, values] : grid.cell_data)
          {
            out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
            write_ascii(out, values, '\n');
          }
      }
    } // namespace



    void
    write_vtk_grid(const VtkGrid     &grid,
                   const std::string &filename,
                   const std::string &format,
                   const VtuEncoding  encoding)
    {
      AssertThrow(grid.connectivity.size() <
                    static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()),
                  dealii::ExcMessage("'" + filename + "' has too many cells for Int32 offsets"));
      for (const auto &[name, values] : grid.cell_data)
        AssertThrow(values.size() == grid.n_cells(),
                    dealii::ExcMessage("cell field '" + name + "' has the wrong size"));
      OutputFile file(filename);
      file.stream() << std::setprecision(17);
      if (format == "vtk")
        write_legacy_vtk(file.stream(), grid);
      else
        write_vtu(file.stream(), grid, encoding);
      file.close();
    }



    void
    write_pvtu_record(const std::string              &filename,
                      const std::vector<std::string> &pieces,
                      const std::vector<std::string> &cell_data_names)
    {
      OutputFile    file(filename);
      std::ostream &out = file.stream();
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
          << "byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
          << "<PUnstructuredGrid GhostLevel=\"0\">\n<PPoints>\n"
          << "<PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n</PPoints>\n<PCellData>\n";
      for (const auto &name : cell_data_names)
        out << "<PDataArray type=\"Float64\" Name=\"" << name << "\"/>\n";
      out << "</PCellData>\n";
      for (const auto &piece : pieces)
        out << "<Piece Source=\"" << piece << "\"/>\n";
      out << "</PUnstructuredGrid>\n</VTKFile>\n";
      file.close();
    }
  } // namespace io
} // namespace porofrac
