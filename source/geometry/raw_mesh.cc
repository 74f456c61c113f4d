// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/exceptions.h>

#include <porofrac/base/config.h>
#include <porofrac/geometry/raw_mesh.h>
#include <porofrac/geometry/simplex_tools.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <unordered_map>

namespace porofrac
{
  namespace geometry
  {
    template <int dim>
    void
    RawMesh<dim>::orient_cells()
    {
      for (auto &cell : cells)
        if (signed_measure<dim>(vertices, cell) < 0)
          std::swap(cell[0], cell[1]);
    }



    template <int dim>
    double
    RawMesh<dim>::measure() const
    {
      double total = 0;
      for (const auto &cell : cells)
        total += std::abs(signed_measure<dim>(vertices, cell));
      return total;
    }



    template <int dim>
    void
    RawMesh<dim>::refine_uniformly()
    {
      // One new vertex per edge, shared by the cells and tagged faces that contain the edge.
      std::unordered_map<std::uint64_t, unsigned int> midpoint;
      midpoint.reserve(2 * vertices.size());
      auto mid = [&](unsigned int a, unsigned int b) {
        if (a > b)
          std::swap(a, b);
        const std::uint64_t key = (std::uint64_t(a) << 32) | b;
        const auto          it  = midpoint.find(key);
        if (it != midpoint.end())
          return it->second;
        const unsigned int index = vertices.size();
        Point<dim>         p     = vertices[a];
        p += vertices[b];
        vertices.push_back(0.5 * p);
        midpoint.emplace(key, index);
        return index;
      };

      std::vector<std::array<unsigned int, dim + 1>> new_cells;
      std::vector<types::material_id>                new_material;
      const unsigned int                             n_children = (dim == 2) ? 4 : 8;
      new_cells.reserve(n_children * cells.size());
      new_material.reserve(n_children * cells.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const auto &t = cells[c];
          if constexpr (dim == 2)
            {
              const auto m01 = mid(t[0], t[1]);
              const auto m12 = mid(t[1], t[2]);
              const auto m20 = mid(t[2], t[0]);
              // Red refinement keeps the orientation of the parent in all four children.
              new_cells.push_back({{t[0], m01, m20}});
              new_cells.push_back({{m01, t[1], m12}});
              new_cells.push_back({{m20, m12, t[2]}});
              new_cells.push_back({{m01, m12, m20}});
            }
          else
            {
              const auto m01 = mid(t[0], t[1]), m02 = mid(t[0], t[2]), m03 = mid(t[0], t[3]);
              const auto m12 = mid(t[1], t[2]), m13 = mid(t[1], t[3]), m23 = mid(t[2], t[3]);
              // Bey's children, in Bey's vertex order (the inner octahedron split along
              // m02-m13): repeated refinement then makes at most three similarity classes.
              new_cells.push_back({{t[0], m01, m02, m03}});
              new_cells.push_back({{m01, t[1], m12, m13}});
              new_cells.push_back({{m02, m12, t[2], m23}});
              new_cells.push_back({{m03, m13, m23, t[3]}});
              new_cells.push_back({{m01, m02, m03, m13}});
              new_cells.push_back({{m01, m02, m12, m13}});
              new_cells.push_back({{m02, m03, m13, m23}});
              new_cells.push_back({{m02, m12, m13, m23}});
            }
          for (unsigned int k = 0; k < n_children; ++k)
            new_material.push_back(cell_material.empty() ? 0 : cell_material[c]);
        }
      cells         = std::move(new_cells);
      cell_material = std::move(new_material);

      // Tagged faces split like the faces of the cells: edges in two (2D), triangles in four.
      auto split = [&](std::vector<TaggedFace> &faces) {
        std::vector<TaggedFace> result;
        result.reserve((dim == 2 ? 2 : 4) * faces.size());
        for (const auto &f : faces)
          {
            const auto &v = f.vertices;
            if constexpr (dim == 2)
              {
                const unsigned int m = mid(v[0], v[1]);
                result.push_back({{{v[0], m}}, f.tag});
                result.push_back({{{m, v[1]}}, f.tag});
              }
            else
              {
                const auto m01 = mid(v[0], v[1]), m12 = mid(v[1], v[2]), m20 = mid(v[2], v[0]);
                result.push_back({{{v[0], m01, m20}}, f.tag});
                result.push_back({{{m01, v[1], m12}}, f.tag});
                result.push_back({{{m20, m12, v[2]}}, f.tag});
                result.push_back({{{m01, m12, m20}}, f.tag});
              }
          }
        faces = std::move(result);
      };
      split(boundary_faces);
      split(fracture_faces);
    }



    template <int dim>
    unsigned int
    RawMesh<dim>::make_delaunay()
    {
      AssertThrow(dim == 2, ExcMessage("Delaunay flips are implemented in 2D only."));
      if constexpr (dim == 2)
        {
          orient_cells();
          std::set<std::pair<unsigned int, unsigned int>> constrained;
          auto                                            key = [](unsigned int a, unsigned int b) {
            return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
          };
          for (const auto *faces : {&boundary_faces, &fracture_faces})
            for (const auto &f : *faces)
              constrained.insert(key(f.vertices[0], f.vertices[1]));

          // d strictly inside the circumcircle of the counter-clockwise triangle (a, b, c)?
          auto in_circle = [&](unsigned int a, unsigned int b, unsigned int c, unsigned int d) {
            const Tensor<1, 2> A = vertices[a] - vertices[d], B = vertices[b] - vertices[d],
                               C = vertices[c] - vertices[d];
            const double det     = A.norm_square() * (B[0] * C[1] - B[1] * C[0]) -
                               B.norm_square() * (A[0] * C[1] - A[1] * C[0]) +
                               C.norm_square() * (A[0] * B[1] - A[1] * B[0]);
            const double scale = A.norm_square() * B.norm_square() +
                                 B.norm_square() * C.norm_square() +
                                 C.norm_square() * A.norm_square();
            return det > 1e-10 * scale; // cocircular quads (common after refinement) stay put
          };

          unsigned int total = 0;
          for (unsigned int pass = 0; pass < 100; ++pass)
            {
              std::map<std::pair<unsigned int, unsigned int>, std::vector<unsigned int>>
                cells_of_edge;
              for (unsigned int c = 0; c < cells.size(); ++c)
                for (unsigned int i = 0; i < 3; ++i)
                  cells_of_edge[key(cells[c][i], cells[c][(i + 1) % 3])].push_back(c);
              std::vector<bool> touched(cells.size(), false);
              unsigned int      flips = 0;
              for (const auto &[edge, two] : cells_of_edge)
                {
                  if (two.size() != 2 || constrained.count(edge) || touched[two[0]] ||
                      touched[two[1]] ||
                      (!cell_material.empty() && cell_material[two[0]] != cell_material[two[1]]))
                    continue;
                  // Rotate t1 to (a, b, c) with edge (a, b); t2 is then (b, a, d).
                  auto t1 = cells[two[0]];
                  while (key(t1[0], t1[1]) != edge)
                    std::rotate(t1.begin(), t1.begin() + 1, t1.end());
                  const unsigned int a = t1[0], b = t1[1], c = t1[2];
                  unsigned int       d = 0;
                  for (const unsigned int v : cells[two[1]])
                    if (v != a && v != b)
                      d = v;
                  if (!in_circle(a, b, c, d))
                    continue;
                  cells[two[0]] = {{a, d, c}};
                  cells[two[1]] = {{b, c, d}};
                  // A non-convex quadrilateral cannot violate Delaunay, but guard anyway.
                  if (signed_measure<2>(vertices, cells[two[0]]) <= 0 ||
                      signed_measure<2>(vertices, cells[two[1]]) <= 0)
                    {
                      cells[two[0]] = t1;
                      cells[two[1]] = {{b, a, d}};
                      continue;
                    }
                  touched[two[0]] = touched[two[1]] = true;
                  ++flips;
                }
              total += flips;
              if (flips == 0)
                break;
            }
          return total;
        }
      return 0;
    }



    template struct RawMesh<2>;
    template struct RawMesh<3>;
  } // namespace geometry
} // namespace porofrac
