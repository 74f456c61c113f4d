// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/structured_mesh.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace porofrac
{
  namespace geometry
  {
    std::array<unsigned int, 3>
    parse_structured_cells(const std::string &text, const std::string &parameter)
    {
      const auto parts = Utilities::split_string_list(text, ',');
      check_input(parts.size() == 3,
                  parameter,
                  "expected three numbers of cells 'nx, ny, nz', got '" + text + "'");
      std::array<unsigned int, 3> cells;
      for (unsigned int d = 0; d < 3; ++d)
        {
          int n = 0;
          try
            {
              n = Utilities::string_to_int(parts[d]);
            }
          catch (...)
            {
            }
          check_input(n >= 1 && n <= 1000,
                      parameter,
                      "'" + parts[d] + "' is not a number of cells in [1, 1000]");
          cells[d] = n;
        }
      return cells;
    }

    namespace
    {
      /// Kuhn's six tetrahedra of the unit cube, as paths 0 -> e_a -> e_a + e_b -> (1, 1, 1).
      std::array<std::array<unsigned int, 3>, 6>
      kuhn_paths()
      {
        return {{{{0, 1, 2}}, {{0, 2, 1}}, {{1, 0, 2}}, {{1, 2, 0}}, {{2, 0, 1}}, {{2, 1, 0}}}};
      }

      double
      signed_volume(const std::vector<Point<3>> &v, const std::array<unsigned int, 4> &t)
      {
        return cross_product_3d(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]) * (v[t[3]] - v[t[0]]);
      }
    } // namespace



    RawMesh<3>
    structured_box_mesh(const PolygonNetwork              &network,
                        const std::array<unsigned int, 3> &cells,
                        const std::string                 &parameter)
    {
      RawMesh<3> raw;
      const auto index = [&cells](const std::array<unsigned int, 3> &i) {
        return i[0] + (cells[0] + 1) * (i[1] + (cells[1] + 1) * i[2]);
      };
      std::array<double, 3> h;
      for (unsigned int d = 0; d < 3; ++d)
        h[d] = (network.hi[d] - network.lo[d]) / cells[d];
      for (unsigned int k = 0; k <= cells[2]; ++k)
        for (unsigned int j = 0; j <= cells[1]; ++j)
          for (unsigned int i = 0; i <= cells[0]; ++i)
            raw.vertices.emplace_back(network.lo[0] + i * h[0],
                                      network.lo[1] + j * h[1],
                                      network.lo[2] + k * h[2]);
      for (unsigned int k = 0; k < cells[2]; ++k)
        for (unsigned int j = 0; j < cells[1]; ++j)
          for (unsigned int i = 0; i < cells[0]; ++i)
            for (const auto &path : kuhn_paths())
              {
                std::array<unsigned int, 3> corner = {{i, j, k}};
                std::array<unsigned int, 4> tet;
                tet[0] = index(corner);
                for (unsigned int s = 0; s < 3; ++s)
                  {
                    ++corner[path[s]];
                    tet[s + 1] = index(corner);
                  }
                if (signed_volume(raw.vertices, tet) < 0)
                  std::swap(tet[2], tet[3]);
                raw.cells.push_back(tet);
                raw.cell_material.push_back(0);
              }

      // Grid faces normal to axis a at layer l: two triangles split along the diagonal from the
      // low-low to the high-high corner (the diagonal Kuhn's tetrahedra share).
      std::map<unsigned int, double> fracture_area;
      for (unsigned int a = 0; a < 3; ++a)
        {
          const unsigned int b = (a + 1) % 3, c = (a + 2) % 3;
          for (unsigned int l = 0; l <= cells[a]; ++l)
            for (unsigned int m = 0; m < cells[b]; ++m)
              for (unsigned int n = 0; n < cells[c]; ++n)
                {
                  std::array<unsigned int, 3> i;
                  i[a] = l, i[b] = m, i[c] = n;
                  const unsigned int p00 = index(i);
                  ++i[b];
                  const unsigned int p10 = index(i);
                  ++i[c];
                  const unsigned int p11 = index(i);
                  --i[b];
                  const unsigned int p01 = index(i);
                  for (const std::array<unsigned int, 3> tri :
                       {std::array<unsigned int, 3>{{p00, p10, p11}},
                        std::array<unsigned int, 3>{{p00, p11, p01}}})
                    {
                      if (l == 0 || l == cells[a])
                        {
                          raw.boundary_faces.push_back({tri, 2 * a + (l == 0 ? 0u : 1u)});
                          continue;
                        }
                      const Point<3> centroid =
                        (raw.vertices[tri[0]] + raw.vertices[tri[1]] + raw.vertices[tri[2]]) / 3.;
                      for (const auto &f : network.fractures)
                        if (f.polygon.contains(centroid, 1e-9 * h[a]))
                          {
                            raw.fracture_faces.push_back({tri, f.id});
                            fracture_area[f.id] += 0.5 * h[b] * h[c];
                            break;
                          }
                    }
                }
        }
      for (const auto &f : network.fractures)
        {
          check_input(std::abs(fracture_area[f.id] - f.polygon.area()) <= 1e-9 * f.polygon.area(),
                      parameter,
                      "fracture " + std::to_string(f.id) +
                        " is not a union of faces of the structured grid (its grid faces cover " +
                        std::to_string(fracture_area[f.id]) + " of its area " +
                        std::to_string(f.polygon.area()) +
                        "): its corners must lie on grid lines of a grid plane");
          raw.fracture_normal[f.id]  = f.polygon.normal;
          raw.fracture_tangent[f.id] = f.polygon.t1;
        }
      return raw;
    }
  } // namespace geometry
} // namespace porofrac
