// SPDX-License-Identifier: LGPL-2.1-or-later
// io::write_vtk_grid: the compressed binary VTU holds bit for bit the arrays of the ASCII VTU
// (decoded here with a base64 decoder and zlib's uncompress, block by block from the header),
// for arrays of 1, 2 and 3 bytes mod 3 (base64 padding) and one of several 1 MiB blocks; the
// legacy file lists the same cells and values; a field of the wrong size and a file that cannot
// be written are errors; the .pvtu record lists the pieces and the cell data.
#include <porofrac/base/exceptions.h>
#include <porofrac/io/vtk_grid.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

#include "../file_text.h"
#include <zlib.h>

namespace
{
  using porofrac_tests::text_of;

  std::vector<unsigned char>
  base64_decode(const std::string &text)
  {
    const std::string table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> out;
    unsigned int               bits = 0, n_bits = 0;
    for (const char c : text)
      {
        if (c == '=')
          break;
        bits = (bits << 6) | table.find(c);
        n_bits += 6;
        if (n_bits >= 8)
          {
            n_bits -= 8;
            out.push_back((bits >> n_bits) & 0xff);
          }
      }
    return out;
  }

  /// The bytes of a compressed DataArray text: header (its own base64), then the blocks.
  std::vector<unsigned char>
  decode_compressed(const std::string &text)
  {
    const auto    first    = base64_decode(text.substr(0, 8));
    std::uint32_t n_blocks = 0;
    std::memcpy(&n_blocks, first.data(), 4);
    const std::size_t          header_chars = ((4 * (3 + n_blocks) + 2) / 3) * 4;
    const auto                 header_bytes = base64_decode(text.substr(0, header_chars));
    std::vector<std::uint32_t> header(3 + n_blocks);
    std::memcpy(header.data(), header_bytes.data(), header.size() * 4);
    const auto                 data = base64_decode(text.substr(header_chars));
    std::vector<unsigned char> out;
    std::size_t                offset = 0;
    for (std::uint32_t b = 0; b < n_blocks; ++b)
      {
        uLongf                     size = (b + 1 == n_blocks) ? header[2] : header[1];
        std::vector<unsigned char> block(size);
        if (uncompress(block.data(), &size, data.data() + offset, header[3 + b]) != Z_OK)
          std::cout << "block " << b << " does not uncompress" << std::endl;
        offset += header[3 + b];
        out.insert(out.end(), block.begin(), block.begin() + size);
      }
    if (offset != data.size())
      std::cout << "compressed sizes " << offset << " of " << data.size() << " bytes" << std::endl;
    return out;
  }

  /// Name (or "points") → the text of each DataArray of a VTU file (found by hand: std::regex
  /// recurses once per character and overflows the stack on megabytes).
  std::vector<std::pair<std::string, std::string>>
  data_arrays(const std::string &file)
  {
    const std::string                                s = text_of(file);
    std::vector<std::pair<std::string, std::string>> arrays;
    for (std::size_t start = s.find("<DataArray"); start != std::string::npos;
         start             = s.find("<DataArray", start + 1))
      {
                    const std::size_t tag_end = s.find(">\n", start);
                    const std::string tag     = s.substr(start, tag_end - start);
                    const std::size_t name    = tag.find("Name=\"");
                    const std::string label   = name == std::string::npos ?
                                                  "points" :
                                                  tag.substr(name + 6, tag.find('"', name + 6) - name - 6);
                    const std::size_t end     = s.find("\n</DataArray>", tag_end);
                    arrays.emplace_back(label, s.substr(tag_end + 2, end - tag_end - 2));
      }
    return arrays;
  }

  /// The bytes of the ASCII values @p text stored as @p type.
  std::vector<unsigned char>
  ascii_bytes(const std::string &text, const std::string &name)
  {
    std::istringstream         in(text);
    std::vector<unsigned char> out;
    double                     v;
    while (in >> v)
      {
        unsigned char buffer[8];
        std::size_t   size = 8;
        if (name == "connectivity" || name == "offsets")
          {
            const std::int32_t i = static_cast<std::int32_t>(v);
            std::memcpy(buffer, &i, size = 4);
          }
        else if (name == "types")
          buffer[0] = static_cast<unsigned char>(v), size = 1;
        else
          std::memcpy(buffer, &v, size);
        out.insert(out.end(), buffer, buffer + size);
      }
    return out;
  }

  /// A strip of @p n_cells triangles with the cell field "x" (irrational values, so that
  /// ASCII needs all 17 digits).
  porofrac::io::VtkGrid
  triangles(const unsigned int n_cells)
  {
    porofrac::io::VtkGrid grid;
    for (unsigned int i = 0; i < n_cells + 2; ++i)
      grid.add_point(std::sqrt(2.) * i, i % 2, 0.);
    std::vector<double> x;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        grid.add_cell(5, {std::int32_t(c), std::int32_t(c + 1), std::int32_t(c + 2)});
        x.push_back(std::sqrt(2.) * (c + 1) / 3.);
      }
    grid.cell_data = {{"x", x}};
    return grid;
  }

  void
  compare_encodings(const porofrac::io::VtkGrid &grid, const std::string &label)
  {
    porofrac::io::write_vtk_grid(grid, "ascii.vtu", "vtu", porofrac::io::VtuEncoding::ascii);
    porofrac::io::write_vtk_grid(grid, "binary.vtu", "vtu", porofrac::io::VtuEncoding::compressed);
    const auto   ascii = data_arrays("ascii.vtu"), binary = data_arrays("binary.vtu");
    unsigned int same = 0;
    for (unsigned int i = 0; i < ascii.size() && i < binary.size(); ++i)
      same += ascii_bytes(ascii[i].second, ascii[i].first) == decode_compressed(binary[i].second);
    std::cout << label << ": " << grid.n_cells() << " cells, " << ascii.size()
              << " arrays, identical after decoding: " << same << std::endl;
  }
} // namespace

int
main()
{
  for (const unsigned int n : {1, 2, 3, 5})
    compare_encodings(triangles(n), "triangles");
  // 150,000 cells: the cell field (1.2 MB) and the points (3.6 MB) take several blocks.
  compare_encodings(triangles(150000), "many blocks");

  auto grid = triangles(2);
  porofrac::io::write_vtk_grid(grid, "legacy.vtk", "vtk", porofrac::io::VtuEncoding::ascii);
  const std::string legacy = text_of("legacy.vtk");
  std::cout << "legacy: "
            << std::regex_replace(legacy.substr(legacy.find("CELLS")), std::regex("\n"), " | ")
            << std::endl;

  grid.cell_data.push_back({"short", {1.}});
  try
    {
      porofrac::io::write_vtk_grid(grid, "short.vtu", "vtu", porofrac::io::VtuEncoding::ascii);
      std::cout << "a field of the wrong size was written" << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cout << "wrong size: "
                << (std::string(e.what()).find("'short' has the wrong size") != std::string::npos ?
                      "refused with its name" :
                      e.what())
                << std::endl;
    }
  std::filesystem::create_directories("blocked.vtu");
  try
    {
      porofrac::io::write_vtk_grid(triangles(1),
                                   "blocked.vtu",
                                   "vtu",
                                   porofrac::io::VtuEncoding::compressed);
      std::cout << "a directory was written over" << std::endl;
    }
  catch (const porofrac::InputError &e)
    {
      std::cout << "blocked: " << e.what() << std::endl;
    }
  std::filesystem::remove_all("blocked.vtu");

  porofrac::io::write_pvtu_record("record.pvtu", {"a_0000.vtu", "a_0001.vtu"}, {"p", "subdomain"});
  std::cout << text_of("record.pvtu");
}
