// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/tria.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/geometry/simplex_tools.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

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
      Tensor<1, dim>
      face_normal(const std::vector<Point<dim>> &v, const std::array<unsigned int, dim> &f)
      {
        Tensor<1, dim> n;
        if constexpr (dim == 2)
          {
            const Tensor<1, 2> t = v[f[1]] - v[f[0]];
            n[0]                 = -t[1];
            n[1]                 = t[0];
          }
        else
          n = cross_product_3d(v[f[1]] - v[f[0]], v[f[2]] - v[f[0]]);
        return n / n.norm();
      }

      template <int dim>
      Point<dim>
      face_centre(const std::vector<Point<dim>> &v, const std::array<unsigned int, dim> &f)
      {
        Point<dim> c;
        for (const unsigned int i : f)
          c += v[i];
        return c / double(dim);
      }

      template <int dim>
      double
      face_measure(const std::vector<Point<dim>> &v, const std::array<unsigned int, dim> &f)
      {
        if constexpr (dim == 2)
          return (v[f[1]] - v[f[0]]).norm();
        else
          return 0.5 * cross_product_3d(v[f[1]] - v[f[0]], v[f[2]] - v[f[0]]).norm();
      }
      /// The uncut mesh's adjacency, and the faces and vertices on fractures and the boundary.
      template <int dim>
      struct Topology
      {
        using FaceKey = std::array<unsigned int, dim>;
        std::map<FaceKey, std::vector<unsigned int>> cells_of_face;
        std::vector<std::vector<unsigned int>>       cells_of_vertex;
        std::map<FaceKey, unsigned int>              fracture_face_of_key;
        std::set<unsigned int>                       boundary_vertices;
        std::set<unsigned int>                       fracture_vertices;
      };



      template <int dim>
      Topology<dim>
      build_topology(const RawMesh<dim> &raw)
      {
        using FaceKey   = std::array<unsigned int, dim>;
        const auto   &V = raw.vertices;
        Topology<dim> t;
        auto         &cells_of_face        = t.cells_of_face;
        auto         &cells_of_vertex      = t.cells_of_vertex;
        auto         &fracture_face_of_key = t.fracture_face_of_key;
        auto         &boundary_vertices    = t.boundary_vertices;
        cells_of_vertex.resize(V.size());

        for (unsigned int c = 0; c < raw.cells.size(); ++c)
          {
            for (unsigned int i = 0; i < dim + 1; ++i)
              {
                cells_of_face[sorted_face<dim>(face_opposite<dim>(raw.cells[c], i))].push_back(c);
                cells_of_vertex[raw.cells[c][i]].push_back(c);
              }
          }
        for (unsigned int k = 0; k < raw.fracture_faces.size(); ++k)
          {
            const FaceKey key = sorted_face<dim>(raw.fracture_faces[k].vertices);
            const auto    it  = cells_of_face.find(key);
            POROFRAC_CHECK_INPUT(
              it != cells_of_face.end(),
              InputError("Geometry",
                         "a fracture face at " +
                           io::to_text(face_centre<dim>(V, raw.fracture_faces[k].vertices)) +
                           " is not a face of the mesh"));
            POROFRAC_CHECK_INPUT(it->second.size() == 2,
                                 InputError("Geometry",
                                            "fracture " +
                                              std::to_string(raw.fracture_faces[k].tag) +
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
            t.fracture_vertices.insert(v);
        return t;
      }



      /**
       * The cut: around each fracture vertex, the cells connected through faces that are not
       * fracture faces form a side region; each region gets its own copy of the vertex (an
       * interior tip has one region, hence one shared vertex). Renumbers @p cells in place and
       * appends the copies to @p vertices.
       */
      template <int dim>
      std::map<unsigned int, std::vector<unsigned int>>
      cut_along_fractures(const RawMesh<dim>                             &raw,
                          const Topology<dim>                            &topology,
                          std::vector<std::array<unsigned int, dim + 1>> &cut_cells,
                          std::vector<Point<dim>>                        &cut_vertices)
      {
        using FaceKey                    = std::array<unsigned int, dim>;
        const auto &V                    = raw.vertices;
        const auto &cells_of_vertex      = topology.cells_of_vertex;
        const auto &fracture_face_of_key = topology.fracture_face_of_key;
        const auto &fracture_vertices    = topology.fracture_vertices;
        std::map<unsigned int, std::vector<unsigned int>> copies_of_vertex;

        for (const unsigned int v : fracture_vertices)
          {
            const auto                     &around = cells_of_vertex[v];
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
                    if (fracture_face_of_key.count(key))
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
                      cut_vertices.push_back(V[v]);
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



      /**
       * Orders the faces of each fracture along its polyline (2D): for each raw fracture face,
       * its (first, second) vertices in the direction of travel and the abscissa of the first.
       * The start is the end nearest the deck's first point, else the lexicographically smallest.
       */
      template <int dim>
      void
      chain_fractures(const RawMesh<dim>                         &raw,
                      std::vector<std::array<unsigned int, dim>> &oriented,
                      std::vector<double>                        &s_begin,
                      std::vector<unsigned int>                  &fracture_ids)
      {
        const auto &V = raw.vertices;
        oriented.assign(raw.fracture_faces.size(), std::array<unsigned int, dim>());
        s_begin.assign(raw.fracture_faces.size(), 0.);

        std::map<unsigned int, std::vector<unsigned int>> raw_faces_of_fracture;
        for (unsigned int k = 0; k < raw.fracture_faces.size(); ++k)
          raw_faces_of_fracture[raw.fracture_faces[k].tag].push_back(k);

        for (const auto &[fid, faces] : raw_faces_of_fracture)
          {
            fracture_ids.push_back(fid);
            if constexpr (dim == 2)
              {
                std::map<unsigned int, std::vector<unsigned int>> faces_at;
                for (const unsigned int k : faces)
                  for (const unsigned int v : raw.fracture_faces[k].vertices)
                    faces_at[v].push_back(k);
                std::vector<unsigned int> ends;
                for (const auto &[v, fs] : faces_at)
                  {
                    POROFRAC_CHECK_INPUT(fs.size() <= 2,
                                         InputError("Geometry/Fractures",
                                                    "fracture " + std::to_string(fid) +
                                                      " branches or crosses itself at " +
                                                      io::to_text(V[v])));
                    if (fs.size() == 1)
                      ends.push_back(v);
                  }
                POROFRAC_CHECK_INPUT(ends.size() == 2 || ends.empty(),
                                     InputError("Geometry/Fractures",
                                                "fracture " + std::to_string(fid) +
                                                  " is not one connected polyline"));
                unsigned int start = ends.empty() ? faces_at.begin()->first : ends[0];
                const auto   hint  = raw.fracture_start.find(fid);
                if (ends.size() == 2)
                  {
                    if (hint != raw.fracture_start.end())
                      {
                        if (V[ends[1]].distance(hint->second) < V[ends[0]].distance(hint->second))
                          start = ends[1];
                      }
                    else if (V[ends[1]][0] < V[ends[0]][0] - 1e-12 ||
                             (std::abs(V[ends[1]][0] - V[ends[0]][0]) <= 1e-12 &&
                              V[ends[1]][1] < V[ends[0]][1]))
                      start = ends[1];
                  }
                std::set<unsigned int> visited;
                unsigned int           node = start;
                double                 s    = 0;
                while (visited.size() < faces.size())
                  {
                    unsigned int next_face = numbers::invalid_unsigned_int;
                    for (const unsigned int k : faces_at[node])
                      if (!visited.count(k))
                        next_face = k;
                    POROFRAC_CHECK_INPUT(next_face != numbers::invalid_unsigned_int,
                                         InputError("Geometry/Fractures",
                                                    "fracture " + std::to_string(fid) +
                                                      " is not one connected polyline"));
                    visited.insert(next_face);
                    const auto        &fv    = raw.fracture_faces[next_face].vertices;
                    const unsigned int other = (fv[0] == node) ? fv[1] : fv[0];
                    oriented[next_face]      = {{node, other}};
                    s_begin[next_face]       = s;
                    s += V[node].distance(V[other]);
                    node = other;
                  }
              }
            else
              for (const unsigned int k : faces)
                oriented[k] = raw.fracture_faces[k].vertices;
          }
      }
    } // namespace



    template <int dim>
    CutMesh<dim>::CutMesh(const RawMesh<dim> &raw_in)
    {
      RawMesh<dim> raw = raw_in;
      raw.orient_cells();
      n_uncut_vertices = raw.vertices.size();
      const auto &V    = raw.vertices;

      const Topology<dim> topology          = build_topology<dim>(raw);
      const auto         &cells_of_face     = topology.cells_of_face;
      const auto         &boundary_vertices = topology.boundary_vertices;
      const auto         &fracture_vertices = topology.fracture_vertices;
      using FaceKey                         = std::array<unsigned int, dim>;

      std::vector<std::array<unsigned int, dim + 1>> cut_cells    = raw.cells;
      std::vector<Point<dim>>                        cut_vertices = V;
      auto copies_of_vertex = cut_along_fractures<dim>(raw, topology, cut_cells, cut_vertices);

      // Maps an uncut face of cell c to the cut vertex indices of that cell.
      auto cut_face = [&](const unsigned int c, const FaceKey &uncut) {
        FaceKey result;
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int i = 0; i < dim + 1; ++i)
            if (raw.cells[c][i] == uncut[k])
              result[k] = cut_cells[c][i];
        return result;
      };

      std::vector<std::array<unsigned int, dim>> oriented;
      std::vector<double>                        s_begin;
      chain_fractures<dim>(raw, oriented, s_begin, fracture_ids);

      // --- Boundary descriptions for the Triangulation.
      SubCellData                    subcell;
      std::vector<CellData<dim - 1>> boundary_objects;
      auto add_boundary = [&](const FaceKey &f, const types::boundary_id id) {
        CellData<dim - 1> data(dim);
        for (unsigned int k = 0; k < dim; ++k)
          data.vertices[k] = f[k];
        data.boundary_id = id;
        boundary_objects.push_back(data);
      };
      std::set<types::boundary_id> outer_ids;
      for (const auto &f : raw.boundary_faces)
        {
          POROFRAC_CHECK_INPUT(f.tag < first_fracture_boundary_id,
                               InputError("Geometry",
                                          "outer boundary ids must be below " +
                                            std::to_string(first_fracture_boundary_id)));
          const FaceKey key = sorted_face<dim>(f.vertices);
          const auto    it  = cells_of_face.find(key);
          POROFRAC_CHECK_INPUT(it != cells_of_face.end() && it->second.size() == 1,
                               InputError("Geometry",
                                          "a boundary face at " +
                                            io::to_text(face_centre<dim>(V, key)) +
                                            " is not on the outer boundary of the mesh"));
          add_boundary(cut_face(it->second[0], f.vertices), f.tag);
          outer_ids.insert(f.tag);
        }
      outer_boundary_ids.assign(outer_ids.begin(), outer_ids.end());

      // Plus/minus cells of each raw fracture face, from n+.
      struct Pending
      {
        unsigned int                raw_face;
        std::array<unsigned int, 2> cells;
        std::array<FaceKey, 2>      cut_faces;
        Tensor<1, dim>              normal, tangent;
      };
      std::vector<Pending> pending;
      for (unsigned int k = 0; k < raw.fracture_faces.size(); ++k)
        {
          const FaceKey &f = oriented[k];
          Pending        p;
          p.raw_face = k;
          p.normal   = face_normal<dim>(V, f);
          if constexpr (dim == 2)
            {
              // n+ = (-t_y, t_x): the left normal of the direction of travel.
              p.tangent = (V[f[1]] - V[f[0]]) / V[f[1]].distance(V[f[0]]);
            }
          else
            {
              // Orient planar fracture normals consistently: largest component positive.
              unsigned int j = 0;
              for (unsigned int d = 1; d < dim; ++d)
                if (std::abs(p.normal[d]) > std::abs(p.normal[j]))
                  j = d;
              if (p.normal[j] < 0)
                p.normal *= -1;
              p.tangent = (V[f[1]] - V[f[0]]) / V[f[1]].distance(V[f[0]]);
            }
          const auto      &two = cells_of_face.at(sorted_face<dim>(f));
          const Point<dim> c   = face_centre<dim>(V, f);
          Point<dim>       centroid0;
          for (const unsigned int v : raw.cells[two[0]])
            centroid0 += V[v] / double(dim + 1);
          // The plus side lies behind n+ (n+ is outward from it).
          const bool first_is_plus = (centroid0 - c) * p.normal < 0;
          p.cells                  = first_is_plus ? std::array<unsigned int, 2>{{two[0], two[1]}} :
                                                     std::array<unsigned int, 2>{{two[1], two[0]}};
          for (unsigned int side = 0; side < 2; ++side)
            {
              p.cut_faces[side] = cut_face(p.cells[side], raw.fracture_faces[k].vertices);
              add_boundary(p.cut_faces[side],
                           fracture_boundary_id(raw.fracture_faces[k].tag, Side(side)));
            }
          pending.push_back(p);
        }

      // --- The Triangulation.
      std::vector<CellData<dim>> cell_data(cut_cells.size(), CellData<dim>(dim + 1));
      for (unsigned int c = 0; c < cut_cells.size(); ++c)
        {
          for (unsigned int i = 0; i < dim + 1; ++i)
            cell_data[c].vertices[i] = cut_cells[c][i];
          cell_data[c].material_id = raw.cell_material.empty() ? 0 : raw.cell_material[c];
        }
      if constexpr (dim == 2)
        subcell.boundary_lines = boundary_objects;
      else
        subcell.boundary_quads = boundary_objects;
      triangulation.create_triangulation(cut_vertices, cell_data, subcell);
      simplex_mapping = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));

      // Cells of the Triangulation by their sorted cut vertex indices.
      std::map<std::array<unsigned int, dim + 1>, typename Triangulation<dim>::active_cell_iterator>
        cell_of_vertices;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          std::array<unsigned int, dim + 1> key;
          for (unsigned int i = 0; i < dim + 1; ++i)
            key[i] = cell->vertex_index(i);
          std::sort(key.begin(), key.end());
          cell_of_vertices[key] = cell;
        }
      auto find_cell = [&](const unsigned int c) {
        auto key = cut_cells[c];
        std::sort(key.begin(), key.end());
        return cell_of_vertices.at(key);
      };

      // --- Fracture nodes (uncut fracture vertices).
      std::map<unsigned int, unsigned int> node_of_vertex;
      for (const unsigned int v : fracture_vertices)
        {
          FractureNode<dim> node;
          node.location     = V[v];
          node.on_boundary  = boundary_vertices.count(v) > 0;
          node.copies       = copies_of_vertex[v];
          node_of_vertex[v] = fracture_nodes.size();
          fracture_nodes.push_back(node);
        }

      // --- Fracture faces, sorted by fracture id and abscissa.
      std::sort(pending.begin(), pending.end(), [&](const Pending &a, const Pending &b) {
        const unsigned int fa = raw.fracture_faces[a.raw_face].tag;
        const unsigned int fb = raw.fracture_faces[b.raw_face].tag;
        return fa != fb ? fa < fb : s_begin[a.raw_face] < s_begin[b.raw_face];
      });
      for (const Pending &p : pending)
        {
          FractureFace<dim> face;
          face.index           = fracture_faces.size();
          face.fracture_id     = raw.fracture_faces[p.raw_face].tag;
          face.normal          = p.normal;
          face.tangent         = p.tangent;
          face.measure         = face_measure<dim>(V, oriented[p.raw_face]);
          face.centre          = face_centre<dim>(V, oriented[p.raw_face]);
          face.abscissa_begin  = s_begin[p.raw_face];
          face.abscissa_end    = (dim == 2) ? s_begin[p.raw_face] + face.measure : 0.;
          face.abscissa        = 0.5 * (face.abscissa_begin + face.abscissa_end);
          face.distance_to_tip = std::numeric_limits<double>::infinity();
          for (unsigned int k = 0; k < dim; ++k)
            face.nodes[k] = node_of_vertex.at(oriented[p.raw_face][k]);
          for (unsigned int side = 0; side < 2; ++side)
            {
              face.cell[side]    = find_cell(p.cells[side]);
              const FaceKey want = sorted_face<dim>(p.cut_faces[side]);
              face.face_no[side] = numbers::invalid_unsigned_int;
              for (const unsigned int f : face.cell[side]->face_indices())
                {
                  FaceKey have;
                  for (unsigned int k = 0; k < dim; ++k)
                    have[k] = face.cell[side]->face(f)->vertex_index(k);
                  if (sorted_face<dim>(have) == want)
                    face.face_no[side] = f;
                }
              Assert(face.face_no[side] != numbers::invalid_unsigned_int, ExcInternalError());
              face_lookup[face.cell[side]->active_cell_index() * GeometryInfo<dim>::faces_per_cell +
                          face.face_no[side]] = {face.index, Side(side)};
            }
          for (const unsigned int n : face.nodes)
            fracture_nodes[n].faces.push_back(face.index);
          faces_of_fracture[face.fracture_id].push_back(face.index);
          fracture_faces.push_back(face);
        }

      // --- Node types, then distances to genuine tips.
      for (auto &node : fracture_nodes)
        {
          if (dim == 3)
            {
              // In 3D a fracture vertex has many faces; the side regions tell: one at a tip
              // (the fracture's edge inside the domain), two inside, more at intersections.
              node.type = node.on_boundary        ? NodeType::boundary :
                          node.copies.size() == 1 ? NodeType::tip :
                          node.copies.size() > 2  ? NodeType::intersection :
                                                    NodeType::interior;
            }
          else if (node.on_boundary)
            node.type = NodeType::boundary;
          else if (node.faces.size() == 1)
            node.type = NodeType::tip;
          else if (node.faces.size() >= 3)
            node.type = NodeType::intersection;
          else
            {
              const auto &a = fracture_faces[node.faces[0]];
              const auto &b = fracture_faces[node.faces[1]];
              if (a.fracture_id != b.fracture_id)
                node.type = NodeType::junction;
              else
                node.type = (std::abs(a.normal * b.normal) > 1 - 1e-10) ? NodeType::interior :
                                                                          NodeType::corner;
            }
        }
      for (auto &face : fracture_faces)
        for (const unsigned int other : faces_of_fracture[face.fracture_id])
          for (const unsigned int n : fracture_faces[other].nodes)
            if (fracture_nodes[n].type == NodeType::tip)
              face.distance_to_tip =
                std::min(face.distance_to_tip, face.centre.distance(fracture_nodes[n].location));
    }



    template <int dim>
    std::pair<unsigned int, Side>
    CutMesh<dim>::fracture_face(const typename Triangulation<dim>::active_cell_iterator &cell,
                                const unsigned int face_no) const
    {
      const auto it =
        face_lookup.find(cell->active_cell_index() * GeometryInfo<dim>::faces_per_cell + face_no);
      if (it == face_lookup.end())
        return {numbers::invalid_unsigned_int, plus};
      return it->second;
    }



    template <int dim>
    std::vector<unsigned int>
    CutMesh<dim>::special_nodes() const
    {
      std::vector<unsigned int> result;
      for (unsigned int n = 0; n < fracture_nodes.size(); ++n)
        if (fracture_nodes[n].faces.size() >= 3 || fracture_nodes[n].on_boundary)
          result.push_back(n);
      return result;
    }



    template <int dim>
    double
    CutMesh<dim>::fracture_measure(const unsigned int fracture_id) const
    {
      double     total = 0;
      const auto it    = faces_of_fracture.find(fracture_id);
      if (it != faces_of_fracture.end())
        for (const unsigned int f : it->second)
          total += fracture_faces[f].measure;
      return total;
    }



    template class CutMesh<2>;
    template class CutMesh<3>;
  } // namespace geometry
} // namespace porofrac
