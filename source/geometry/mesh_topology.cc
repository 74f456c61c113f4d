// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/mesh_topology.h>
#include <porofrac/geometry/simplex_tools.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <numeric>
#include <set>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      /// Small union-find over local indices.
      struct UnionFind
      {
        std::vector<unsigned int> parent;
        explicit UnionFind(const unsigned int n)
            : parent(n)
        {
          std::iota(parent.begin(), parent.end(), 0u);
        }
        unsigned int
        find(unsigned int i)
        {
          while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
          return i;
        }
        void
        unite(const unsigned int a, const unsigned int b)
        {
          parent[find(a)] = find(b);
        }
      };

      template <int dim>
      bool
      has_vertex(const std::array<unsigned int, dim + 1> &cell, const unsigned int v)
      {
        return std::find(cell.begin(), cell.end(), v) != cell.end();
      }
    } // namespace



    template <int dim>
    MeshTopology<dim>::MeshTopology(const RawMesh<dim> &raw)
        : raw(raw)
        , offsets(raw.vertices.size() + 1, 0)
        , cells((dim + 1) * raw.cells.size())
    {
      // Cells of each vertex in compressed rows, in increasing cell order.
      for (const auto &cell : raw.cells)
        for (const unsigned int v : cell)
          ++offsets[v + 1];
      std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
      std::vector<unsigned int> next(offsets.begin(), offsets.end() - 1);
      for (unsigned int c = 0; c < raw.cells.size(); ++c)
        for (const unsigned int v : raw.cells[c])
          cells[next[v]++] = c;

      const auto &V = raw.vertices;
      for (unsigned int k = 0; k < raw.fracture_faces.size(); ++k)
        {
          const FaceKey key   = sorted_face<dim>(raw.fracture_faces[k].vertices);
          const auto    found = cells_of_face(key);
          POROFRAC_CHECK_INPUT(!found.empty(),
                               InputError("Geometry",
                                          "a fracture face at " +
                                            io::to_text(
                                              face_centre<dim>(V, raw.fracture_faces[k].vertices)) +
                                            " is not a face of the mesh"));
          POROFRAC_CHECK_INPUT(found.size() == 2,
                               InputError("Geometry",
                                          "fracture " + std::to_string(raw.fracture_faces[k].tag) +
                                            " lies on the outer boundary at " +
                                            io::to_text(face_centre<dim>(V, key))));
          POROFRAC_CHECK_INPUT(fracture_face_of_key.emplace(key, k).second,
                               InputError("Geometry",
                                          "two fractures overlap at " +
                                            io::to_text(face_centre<dim>(V, key))));
        }
      for (const auto &f : raw.boundary_faces)
        for (const unsigned int v : f.vertices)
          boundary_vertices.insert(v);
      for (const auto &f : raw.fracture_faces)
        for (const unsigned int v : f.vertices)
          fracture_vertices.insert(v);
    }



    template <int dim>
    ArrayView<const unsigned int>
    MeshTopology<dim>::cells_of_vertex(const unsigned int v) const
    {
      return make_array_view(cells.begin() + offsets[v], cells.begin() + offsets[v + 1]);
    }



    template <int dim>
    std::vector<unsigned int>
    MeshTopology<dim>::cells_of_face(const FaceKey &key) const
    {
      std::vector<unsigned int> result;
      for (const unsigned int c : cells_of_vertex(key[0]))
        {
          bool all = true;
          for (unsigned int k = 1; k < dim; ++k)
            all = all && has_vertex<dim>(raw.cells[c], key[k]);
          if (all)
            result.push_back(c);
        }
      return result;
    }



    template <int dim>
    bool
    MeshTopology<dim>::on_outer_boundary(const unsigned int a, const unsigned int b) const
    {
      // The faces through the edge, counted over the cells around it: once means boundary.
      std::map<FaceKey, unsigned int> count;
      for (const unsigned int c : cells_of_vertex(a))
        if (has_vertex<dim>(raw.cells[c], b))
          for (unsigned int i = 0; i < dim + 1; ++i)
            {
              const unsigned int w = raw.cells[c][i];
              if (w != a && w != b)
                ++count[sorted_face<dim>(face_opposite<dim>(raw.cells[c], i))];
            }
      for (const auto &[face, n] : count)
        if (n == 1)
          return true;
      return false;
    }



    template <int dim>
    std::map<unsigned int, std::vector<unsigned int>>
    cut_along_fractures(const RawMesh<dim>                             &raw,
                        const MeshTopology<dim>                        &topology,
                        std::vector<std::array<unsigned int, dim + 1>> &cut_cells,
                        std::vector<Point<dim>>                        &cut_vertices)
    {
      using FaceKey = typename MeshTopology<dim>::FaceKey;
      std::map<unsigned int, std::vector<unsigned int>> copies_of_vertex;
      for (const unsigned int v : topology.fracture_vertices)
        {
          const auto                      around = topology.cells_of_vertex(v);
          UnionFind                       regions(around.size());
          std::map<FaceKey, unsigned int> first_cell_with_face;
          for (unsigned int a = 0; a < around.size(); ++a)
            {
              const auto &cell = raw.cells[around[a]];
              for (unsigned int i = 0; i < dim + 1; ++i)
                {
                  if (cell[i] == v)
                    continue; // the face opposite v does not contain v
                  const FaceKey key = sorted_face<dim>(face_opposite<dim>(cell, i));
                  if (topology.fracture_face_of_key.count(key))
                    continue;
                  const auto it = first_cell_with_face.find(key);
                  if (it == first_cell_with_face.end())
                    first_cell_with_face[key] = a;
                  else
                    regions.unite(a, it->second);
                }
            }
          std::map<unsigned int, unsigned int> copy_of_region;
          for (unsigned int a = 0; a < around.size(); ++a)
            {
              const unsigned int root = regions.find(a);
              auto               it   = copy_of_region.find(root);
              if (it == copy_of_region.end())
                {
                  const unsigned int copy = copy_of_region.empty() ? v : cut_vertices.size();
                  if (copy != v)
                    cut_vertices.push_back(raw.vertices[v]);
                  it = copy_of_region.emplace(root, copy).first;
                  copies_of_vertex[v].push_back(copy);
                }
              for (auto &w : cut_cells[around[a]])
                if (w == v)
                  w = it->second;
            }
        }
      return copies_of_vertex;
    }



    template <int dim>
    std::vector<unsigned int>
    unseparated_fracture_faces(const RawMesh<dim>                                   &raw,
                               const MeshTopology<dim>                              &topology,
                               const std::vector<std::array<unsigned int, dim + 1>> &cut_cells)
    {
      std::vector<unsigned int> result;
      for (unsigned int k = 0; k < raw.fracture_faces.size(); ++k)
        {
          const auto &f     = raw.fracture_faces[k].vertices;
          const auto  cells = topology.cells_of_face(sorted_face<dim>(f));
          bool        same  = true;
          for (const unsigned int v : f)
            {
              // The copy of v in each of the two cells.
              std::array<unsigned int, 2> copy;
              for (unsigned int side = 0; side < 2; ++side)
                for (unsigned int i = 0; i < dim + 1; ++i)
                  if (raw.cells[cells[side]][i] == v)
                    copy[side] = cut_cells[cells[side]][i];
              same = same && copy[0] == copy[1];
            }
          if (same)
            result.push_back(k);
        }
      return result;
    }



    template <int dim>
    unsigned int
    split_fracture_faces(RawMesh<dim>                    &raw,
                         const MeshTopology<dim>         &topology,
                         const std::vector<unsigned int> &faces)
    {
      // The topology describes the cells before any split: a face next to a cell split already
      // waits for the next round.
      std::set<unsigned int> touched;
      unsigned int           n_split = 0;
      for (const unsigned int k : faces)
        {
          const auto f     = raw.fracture_faces[k].vertices;
          const auto cells = topology.cells_of_face(sorted_face<dim>(f));
          if (touched.count(cells[0]) || touched.count(cells[1]))
            continue;
          touched.insert(cells.begin(), cells.end());
          ++n_split;
          const unsigned int m = raw.vertices.size();
          raw.vertices.push_back(face_centre<dim>(raw.vertices, f));
          // Each cell f + {d} becomes the dim cells f_j + {d}, f_j = f with vertex j -> m.
          for (const unsigned int c : cells)
            {
              const auto cell = raw.cells[c];
              for (unsigned int j = 0; j < dim; ++j)
                {
                  auto child = cell;
                  for (auto &v : child)
                    if (v == f[j])
                      v = m;
                  if (j == 0)
                    raw.cells[c] = child;
                  else
                    {
                      raw.cells.push_back(child);
                      if (!raw.cell_material.empty())
                        raw.cell_material.push_back(raw.cell_material[c]);
                    }
                }
            }
          const auto whole = raw.fracture_faces[k];
          for (unsigned int j = 0; j < dim; ++j)
            {
              auto piece        = whole;
              piece.vertices[j] = m;
              if (j == 0)
                raw.fracture_faces[k] = piece;
              else
                raw.fracture_faces.push_back(piece);
            }
        }
      raw.orient_cells();
      return n_split;
    }



    template class MeshTopology<2>;
    template class MeshTopology<3>;
    template std::map<unsigned int, std::vector<unsigned int>>
    cut_along_fractures<2>(const RawMesh<2> &,
                           const MeshTopology<2> &,
                           std::vector<std::array<unsigned int, 3>> &,
                           std::vector<Point<2>> &);
    template std::map<unsigned int, std::vector<unsigned int>>
    cut_along_fractures<3>(const RawMesh<3> &,
                           const MeshTopology<3> &,
                           std::vector<std::array<unsigned int, 4>> &,
                           std::vector<Point<3>> &);
    template std::vector<unsigned int>
    unseparated_fracture_faces<2>(const RawMesh<2> &,
                                  const MeshTopology<2> &,
                                  const std::vector<std::array<unsigned int, 3>> &);
    template std::vector<unsigned int>
    unseparated_fracture_faces<3>(const RawMesh<3> &,
                                  const MeshTopology<3> &,
                                  const std::vector<std::array<unsigned int, 4>> &);
    template unsigned int
    split_fracture_faces<2>(RawMesh<2> &,
                            const MeshTopology<2> &,
                            const std::vector<unsigned int> &);
    template unsigned int
    split_fracture_faces<3>(RawMesh<3> &,
                            const MeshTopology<3> &,
                            const std::vector<unsigned int> &);
  } // namespace geometry
} // namespace porofrac
