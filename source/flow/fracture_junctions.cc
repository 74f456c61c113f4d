// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/flow/fracture_junctions.h>
#include <porofrac/geometry/fracture_edges.h>

#include <algorithm>
#include <map>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      /// Outer boundary id of each vertex (2D) or each edge, as a sorted vertex pair (3D), of the
      /// outer boundary faces of the cut Triangulation.
      template <int dim>
      std::map<std::array<unsigned int, dim - 1>, types::boundary_id>
      outer_boundary_ids(const geometry::CutMesh<dim> &mesh)
      {
        std::map<std::array<unsigned int, dim - 1>, types::boundary_id> ids;
        for (const auto &cell : mesh.triangulation.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->at_boundary(f))
                continue;
              const auto face = cell->face(f);
              if (face->boundary_id() >= geometry::first_fracture_boundary_id)
                continue;
              if constexpr (dim == 2)
                for (unsigned int v = 0; v < 2; ++v)
                  ids[{{face->vertex_index(v)}}] = face->boundary_id();
              else
                for (unsigned int l = 0; l < face->n_lines(); ++l)
                  {
                    std::array<unsigned int, 2> e = {
                      {face->line(l)->vertex_index(0), face->line(l)->vertex_index(1)}};
                    std::sort(e.begin(), e.end());
                    ids[e] = face->boundary_id();
                  }
            }
        return ids;
      }

      /// Circumcentre of the triangle @p a, @p b, @p c in its plane.
      Point<3>
      circumcentre(const Point<3> &a, const Point<3> &b, const Point<3> &c)
      {
        const Tensor<1, 3> u = b - a, v = c - a, n = cross_product_3d(u, v);
        return a + cross_product_3d(u.norm_square() * v - v.norm_square() * u, n) /
                     (2. * n.norm_square());
      }
    } // namespace



    template <int dim>
    std::vector<FractureJunction<dim>>
    fracture_junctions(const geometry::CutMesh<dim> &mesh)
    {
      const auto                         boundary = outer_boundary_ids(mesh);
      std::vector<FractureJunction<dim>> junctions;
      const auto                        &nodes = mesh.fracture_nodes;
      if constexpr (dim == 2)
        for (const auto &node : nodes)
          {
            FractureJunction<dim> j;
            j.location = node.location;
            j.measure  = 1.;
            j.faces    = node.faces;
            if (node.on_boundary)
              for (const unsigned int c : node.copies)
                if (boundary.count({{c}}))
                  j.boundary_id = boundary.at({{c}});
            junctions.push_back(j);
          }
      else
        {
          for (const auto &[e, faces] : geometry::faces_of_edges(mesh.fracture_faces))
            {
              FractureJunction<dim> j;
              j.ends     = e;
              j.location = 0.5 * (nodes[e[0]].location + nodes[e[1]].location);
              j.measure  = nodes[e[0]].location.distance(nodes[e[1]].location);
              j.faces    = faces;
              if (nodes[e[0]].on_boundary && nodes[e[1]].on_boundary)
                for (const unsigned int c0 : nodes[e[0]].copies)
                  for (const unsigned int c1 : nodes[e[1]].copies)
                    {
                      const auto it = boundary.find({{std::min(c0, c1), std::max(c0, c1)}});
                      if (it != boundary.end())
                        j.boundary_id = it->second;
                    }
              junctions.push_back(j);
            }
        }
      return junctions;
    }



    template <int dim>
    double
    distance_to_junction(const geometry::CutMesh<dim> &mesh,
                         const unsigned int            face,
                         const FractureJunction<dim>  &j,
                         const bool                    centroid)
    {
      const auto &f = mesh.fracture_faces[face];
      if constexpr (dim == 2)
        return f.centre.distance(j.location);
      else
        {
          const auto  &nodes    = mesh.fracture_nodes;
          unsigned int opposite = f.nodes[0];
          for (const unsigned int n : f.nodes)
            if (n != j.ends[0] && n != j.ends[1])
              opposite = n;
          const Point<3> a = nodes[j.ends[0]].location, b = nodes[j.ends[1]].location,
                         v = nodes[opposite].location;
          // In-plane unit normal of the edge, pointing away from the opposite vertex.
          const Tensor<1, 3> t  = (b - a) / (b - a).norm();
          Tensor<1, 3>       nu = (a - v) - ((a - v) * t) * t;
          nu /= nu.norm();
          if (centroid)
            {
              const Tensor<1, 3> d = 0.5 * (a + b) - (a + b + v) / 3.;
              return d.norm_square() / (d * nu);
            }
          return (a - circumcentre(a, b, v)) * nu;
        }
    }

    template std::vector<FractureJunction<2>>
    fracture_junctions(const geometry::CutMesh<2> &);
    template std::vector<FractureJunction<3>>
    fracture_junctions(const geometry::CutMesh<3> &);
    template double
    distance_to_junction(const geometry::CutMesh<2> &,
                         const unsigned int,
                         const FractureJunction<2> &,
                         const bool);
    template double
    distance_to_junction(const geometry::CutMesh<3> &,
                         const unsigned int,
                         const FractureJunction<3> &,
                         const bool);
  } // namespace flow
} // namespace porofrac
