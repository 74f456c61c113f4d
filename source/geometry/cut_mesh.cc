// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/tria.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/geometry/fracture_chains.h>
#include <porofrac/geometry/fracture_edges.h>
#include <porofrac/geometry/mesh_topology.h>
#include <porofrac/geometry/planar_polygon.h>
#include <porofrac/geometry/simplex_tools.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      template <int dim>
      using FaceKey = std::array<unsigned int, dim>;

      /// The frame (n+, t1) of a fracture, constant over a planar fracture (3D).
      template <int dim>
      struct Frame
      {
        Tensor<1, dim> normal, tangent;
      };

      /**
       * The frame of each fracture (3D): the deck's hints (right-hand rule, first edge or axis);
       * for fractures from a mesh file the normal of the fracture's first face with its largest
       * component positive, and t1 = default_tangent(n+).
       */
      template <int dim>
      std::map<unsigned int, Frame<dim>>
      fracture_frames(const RawMesh<dim> &raw)
      {
        std::map<unsigned int, Frame<dim>> frames;
        if constexpr (dim == 3)
          for (const auto &f : raw.fracture_faces)
            {
              if (frames.count(f.tag))
                continue;
              Frame<dim> frame;
              const auto n = raw.fracture_normal.find(f.tag);
              if (n != raw.fracture_normal.end())
                frame.normal = n->second / n->second.norm();
              else
                {
                  frame.normal   = face_normal<dim>(raw.vertices, f.vertices);
                  unsigned int j = 0;
                  for (unsigned int d = 1; d < dim; ++d)
                    if (std::abs(frame.normal[d]) > std::abs(frame.normal[j]))
                      j = d;
                  if (frame.normal[j] < 0)
                    frame.normal *= -1;
                }
              const auto t = raw.fracture_tangent.find(f.tag);
              frame.tangent =
                (t != raw.fracture_tangent.end()) ? t->second : default_tangent(frame.normal);
              frames[f.tag] = frame;
            }
        return frames;
      }

      /// A raw fracture face and its two sides, before the Triangulation exists.
      template <int dim>
      struct Pending
      {
        unsigned int                raw_face;
        std::array<unsigned int, 2> cells; ///< raw cell indices, plus then minus
        std::array<FaceKey<dim>, 2> cut_faces;
        Tensor<1, dim>              normal, tangent, tangent2;
      };

      /**
       * n+, the tangent(s) and the plus and minus cells of raw fracture face @p k. 2D: n+ is the
       * left normal of the direction of travel. 3D: the face normal turned to agree with the
       * fracture's frame, t1 the frame's tangent projected onto the face, t2 = n+ x t1.
       */
      template <int dim>
      Pending<dim>
      sides_of_face(const RawMesh<dim>                       &raw,
                    const MeshTopology<dim>                  &topology,
                    const unsigned int                        k,
                    const FaceKey<dim>                       &f,
                    const std::map<unsigned int, Frame<dim>> &frames)
      {
        const auto  &V = raw.vertices;
        Pending<dim> p;
        p.raw_face = k;
        p.normal   = face_normal<dim>(V, f);
        if constexpr (dim == 2)
          p.tangent = (V[f[1]] - V[f[0]]) / V[f[1]].distance(V[f[0]]);
        else
          {
            const Frame<dim> &frame = frames.at(raw.fracture_faces[k].tag);
            if (p.normal * frame.normal < 0)
              p.normal *= -1;
            Tensor<1, dim> t = frame.tangent - (frame.tangent * p.normal) * p.normal;
            if (t.norm() < 1e-8)
              t = default_tangent(p.normal); // a curved fracture from a mesh file
            p.tangent  = t / t.norm();
            p.tangent2 = cross_product_3d(p.normal, p.tangent);
          }
        const auto       two = topology.cells_of_face(sorted_face<dim>(f));
        const Point<dim> c   = face_centre<dim>(V, f);
        Point<dim>       centroid0;
        for (const unsigned int v : raw.cells[two[0]])
          centroid0 += V[v] / double(dim + 1);
        // The plus side lies behind n+ (n+ is outward from it).
        const bool first_is_plus = (centroid0 - c) * p.normal < 0;
        p.cells                  = first_is_plus ? std::array<unsigned int, 2>{{two[0], two[1]}} :
                                                   std::array<unsigned int, 2>{{two[1], two[0]}};
        return p;
      }

      /// Active cell of the Triangulation for each raw cell index. deal.II keeps the order of
      /// the cells it is given; a map of vertex sets takes over should it not.
      template <int dim>
      std::vector<typename Triangulation<dim>::active_cell_iterator>
      cells_by_index(const Triangulation<dim>                             &tria,
                     const std::vector<std::array<unsigned int, dim + 1>> &cut_cells)
      {
        using Iterator = typename Triangulation<dim>::active_cell_iterator;
        auto sorted    = [](std::array<unsigned int, dim + 1> a) {
          std::sort(a.begin(), a.end());
          return a;
        };
        std::vector<Iterator> result;
        bool                  in_order = tria.n_active_cells() == cut_cells.size();
        for (const auto &cell : tria.active_cell_iterators())
          {
            std::array<unsigned int, dim + 1> key;
            for (unsigned int i = 0; i < dim + 1; ++i)
              key[i] = cell->vertex_index(i);
            in_order = in_order && result.size() < cut_cells.size() &&
                       sorted(key) == sorted(cut_cells[result.size()]);
            result.push_back(cell);
          }
        if (in_order)
          return result;
        std::map<std::array<unsigned int, dim + 1>, Iterator> by_vertices;
        for (const auto &cell : result)
          {
            std::array<unsigned int, dim + 1> key;
            for (unsigned int i = 0; i < dim + 1; ++i)
              key[i] = cell->vertex_index(i);
            by_vertices[sorted(key)] = cell;
          }
        for (unsigned int c = 0; c < cut_cells.size(); ++c)
          result[c] = by_vertices.at(sorted(cut_cells[c]));
        return result;
      }

      /// Local number of the face of @p cell with the (cut) vertices @p want.
      template <int dim>
      unsigned int
      face_number(const typename Triangulation<dim>::active_cell_iterator &cell,
                  const FaceKey<dim>                                      &want)
      {
        for (const unsigned int f : cell->face_indices())
          {
            FaceKey<dim> have;
            for (unsigned int k = 0; k < dim; ++k)
              have[k] = cell->face(f)->vertex_index(k);
            if (sorted_face<dim>(have) == sorted_face<dim>(want))
              return f;
          }
        Assert(false, ExcInternalError());
        return numbers::invalid_unsigned_int;
      }

      /// The geometric fields of the fracture face made of raw face @p p (cells come later).
      template <int dim>
      FractureFace<dim>
      geometric_face(const Pending<dim>                         &p,
                     const RawMesh<dim>                         &raw,
                     const std::vector<FaceKey<dim>>            &oriented,
                     const std::vector<double>                  &s_begin,
                     const std::map<unsigned int, unsigned int> &node_of_vertex)
      {
        const auto       &f = oriented[p.raw_face];
        FractureFace<dim> face;
        face.fracture_id     = raw.fracture_faces[p.raw_face].tag;
        face.normal          = p.normal;
        face.tangent         = p.tangent;
        face.tangent2        = p.tangent2;
        face.measure         = face_measure<dim>(raw.vertices, f);
        face.centre          = face_centre<dim>(raw.vertices, f);
        face.abscissa_begin  = s_begin[p.raw_face];
        face.abscissa_end    = (dim == 2) ? s_begin[p.raw_face] + face.measure : 0.;
        face.abscissa        = 0.5 * (face.abscissa_begin + face.abscissa_end);
        face.distance_to_tip = std::numeric_limits<double>::infinity();
        for (unsigned int k = 0; k < dim; ++k)
          face.nodes[k] = node_of_vertex.at(f[k]);
        return face;
      }

      /// The Triangulation's cells: the cut cells with their materials.
      template <int dim>
      std::vector<CellData<dim>>
      cell_data(const std::vector<std::array<unsigned int, dim + 1>> &cut_cells,
                const RawMesh<dim>                                   &raw)
      {
        std::vector<CellData<dim>> cells(cut_cells.size(), CellData<dim>(dim + 1));
        for (unsigned int c = 0; c < cut_cells.size(); ++c)
          {
            for (unsigned int i = 0; i < dim + 1; ++i)
              cells[c].vertices[i] = cut_cells[c][i];
            cells[c].material_id = raw.cell_material.empty() ? 0 : raw.cell_material[c];
          }
        return cells;
      }

      /// Node types: in 2D from the faces meeting at a node, in 3D from its side regions.
      template <int dim>
      void
      classify_nodes(std::vector<FractureNode<dim>>       &nodes,
                     const std::vector<FractureFace<dim>> &faces)
      {
        for (auto &node : nodes)
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
                const auto &a = faces[node.faces[0]];
                const auto &b = faces[node.faces[1]];
                if (a.fracture_id != b.fracture_id)
                  node.type = NodeType::junction;
                else
                  node.type = (std::abs(a.normal * b.normal) > 1 - 1e-10) ? NodeType::interior :
                                                                            NodeType::corner;
              }
          }
      }

      /// 2D distances to tips: from the face centre to the nearest tip node of its fracture.
      template <int dim>
      void
      set_distances_to_tip_nodes(
        std::vector<FractureFace<dim>>                          &faces,
        const std::vector<FractureNode<dim>>                    &nodes,
        const std::map<unsigned int, std::vector<unsigned int>> &of_fracture)
      {
        for (auto &face : faces)
          for (const unsigned int other : of_fracture.at(face.fracture_id))
            for (const unsigned int n : faces[other].nodes)
              if (nodes[n].type == NodeType::tip)
                face.distance_to_tip =
                  std::min(face.distance_to_tip, face.centre.distance(nodes[n].location));
      }
    } // namespace



    namespace
    {
      /// The mesh being cut: the uncut mesh (with split faces), its topology, the cut cells and
      /// vertices, and the boundary descriptions for the Triangulation.
      template <int dim>
      struct Cut
      {
        RawMesh<dim>                                      raw;
        std::unique_ptr<MeshTopology<dim>>                topology;
        std::vector<std::array<unsigned int, dim + 1>>    cells;
        std::vector<Point<dim>>                           vertices;
        std::map<unsigned int, std::vector<unsigned int>> copies_of_vertex;
        std::vector<FaceKey<dim>>                         oriented; ///< raw fracture faces
        std::vector<double>                               s_begin;
        std::vector<CellData<dim - 1>>                    boundary_objects;
        std::vector<Pending<dim>>                         pending;
        unsigned int                                      n_split = 0;

        /// Cut vertex indices of the uncut face @p uncut of cell @p c.
        FaceKey<dim>
        cut_face(const unsigned int c, const FaceKey<dim> &uncut) const
        {
          FaceKey<dim> result;
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int i = 0; i < dim + 1; ++i)
              if (raw.cells[c][i] == uncut[k])
                result[k] = cells[c][i];
          return result;
        }

        void
        add_boundary(const FaceKey<dim> &f, const types::boundary_id id)
        {
          CellData<dim - 1> data(dim);
          for (unsigned int k = 0; k < dim; ++k)
            data.vertices[k] = f[k];
          data.boundary_id = id;
          boundary_objects.push_back(data);
        }
      };

      /// The cut, after splitting the fracture faces whose sides it would leave joined.
      template <int dim>
      void
      cut_with_splits(Cut<dim> &cut)
      {
        for (;;)
          {
            cut.topology = std::make_unique<MeshTopology<dim>>(cut.raw);
            cut.cells    = cut.raw.cells;
            cut.vertices = cut.raw.vertices;
            cut.copies_of_vertex =
              cut_along_fractures<dim>(cut.raw, *cut.topology, cut.cells, cut.vertices);
            const auto joined = unseparated_fracture_faces<dim>(cut.raw, *cut.topology, cut.cells);
            if (joined.empty())
              return;
            cut.n_split += split_fracture_faces<dim>(cut.raw, *cut.topology, joined);
          }
      }

      /// Outer boundary faces with their ids (returned), then both sides of each fracture face.
      template <int dim>
      std::set<types::boundary_id>
      describe_boundaries(Cut<dim> &cut)
      {
        const auto                  &raw = cut.raw;
        std::set<types::boundary_id> outer_ids;
        for (const auto &f : raw.boundary_faces)
          {
            POROFRAC_CHECK_INPUT(f.tag < first_fracture_boundary_id,
                                 InputError("Geometry",
                                            "outer boundary ids must be below " +
                                              std::to_string(first_fracture_boundary_id)));
            const FaceKey<dim> key   = sorted_face<dim>(f.vertices);
            const auto         cells = cut.topology->cells_of_face(key);
            POROFRAC_CHECK_INPUT(cells.size() == 1,
                                 InputError("Geometry",
                                            "a boundary face at " +
                                              io::to_text(face_centre<dim>(raw.vertices, key)) +
                                              " is not on the outer boundary of the mesh"));
            cut.add_boundary(cut.cut_face(cells[0], f.vertices), f.tag);
            outer_ids.insert(f.tag);
          }
        const auto frames = fracture_frames<dim>(raw);
        for (unsigned int k = 0; k < raw.fracture_faces.size(); ++k)
          {
            Pending<dim> p = sides_of_face<dim>(raw, *cut.topology, k, cut.oriented[k], frames);
            for (unsigned int side = 0; side < 2; ++side)
              {
                p.cut_faces[side] = cut.cut_face(p.cells[side], raw.fracture_faces[k].vertices);
                cut.add_boundary(p.cut_faces[side],
                                 fracture_boundary_id(raw.fracture_faces[k].tag, Side(side)));
              }
            cut.pending.push_back(p);
          }
        return outer_ids;
      }
    } // namespace



    template <int dim>
    CutMesh<dim>::CutMesh(const RawMesh<dim> &raw_in)
    {
      Timer    timer;
      Cut<dim> cut;
      cut.raw = raw_in;
      cut.raw.orient_cells();
      cut_with_splits(cut);
      const auto              &raw      = cut.raw;
      const MeshTopology<dim> &topology = *cut.topology;
      n_uncut_vertices                  = raw.vertices.size();
      n_split_fracture_faces            = cut.n_split;
      chain_fractures<dim>(raw, cut.oriented, cut.s_begin, fracture_ids);
      const auto outer_ids = describe_boundaries(cut);
      outer_boundary_ids.assign(outer_ids.begin(), outer_ids.end());
      build_log.add("cut", timer);

      SubCellData subcell;
      if constexpr (dim == 2)
        subcell.boundary_lines = cut.boundary_objects;
      else
        subcell.boundary_quads = cut.boundary_objects;
      triangulation.create_triangulation(cut.vertices, cell_data<dim>(cut.cells, raw), subcell);
      simplex_mapping = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
      build_log.add("triangulation", timer);

      // --- Fracture nodes (uncut fracture vertices).
      std::map<unsigned int, unsigned int> node_of_vertex;
      std::vector<unsigned int>            vertex_of_node;
      for (const unsigned int v : topology.fracture_vertices)
        {
          FractureNode<dim> node;
          node.location     = raw.vertices[v];
          node.on_boundary  = topology.boundary_vertices.count(v) > 0;
          node.copies       = cut.copies_of_vertex[v];
          node_of_vertex[v] = fracture_nodes.size();
          vertex_of_node.push_back(v);
          fracture_nodes.push_back(node);
        }

      // --- Fracture faces, sorted by fracture id and abscissa (3D: in gmsh's order).
      std::stable_sort(cut.pending.begin(), cut.pending.end(), [&](const auto &a, const auto &b) {
        const unsigned int fa = raw.fracture_faces[a.raw_face].tag;
        const unsigned int fb = raw.fracture_faces[b.raw_face].tag;
        return fa != fb ? fa < fb : cut.s_begin[a.raw_face] < cut.s_begin[b.raw_face];
      });
      const auto cell_of = cells_by_index<dim>(triangulation, cut.cells);
      for (const auto &p : cut.pending)
        {
          FractureFace<dim> face =
            geometric_face<dim>(p, raw, cut.oriented, cut.s_begin, node_of_vertex);
          face.index = fracture_faces.size();
          for (unsigned int side = 0; side < 2; ++side)
            {
              face.cell[side]    = cell_of[p.cells[side]];
              face.face_no[side] = face_number<dim>(face.cell[side], p.cut_faces[side]);
              face_lookup[face.cell[side]->active_cell_index() * GeometryInfo<dim>::faces_per_cell +
                          face.face_no[side]] = {face.index, Side(side)};
            }
          for (const unsigned int n : face.nodes)
            fracture_nodes[n].faces.push_back(face.index);
          faces_of_fracture[face.fracture_id].push_back(face.index);
          fracture_faces.push_back(face);
        }

      // --- Node types, fracture edges, then distances to genuine tips.
      classify_nodes(fracture_nodes, fracture_faces);
      fracture_edges = find_fracture_edges<dim>(
        fracture_faces, fracture_nodes, [&](const unsigned int a, const unsigned int b) {
          return topology.on_outer_boundary(vertex_of_node[a], vertex_of_node[b]);
        });
      if constexpr (dim == 2)
        set_distances_to_tip_nodes(fracture_faces, fracture_nodes, faces_of_fracture);
      else
        set_distances_to_tip_edges(fracture_faces, fracture_edges, fracture_nodes);
      build_log.add("fracture tables", timer);
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
