// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/geometry/fracture_edges.h>
#include <porofrac/geometry/planar_polygon.h>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace porofrac
{
  namespace geometry
  {
    template <int dim>
    std::map<std::array<unsigned int, 2>, std::vector<unsigned int>>
    faces_of_edges(const std::vector<FractureFace<dim>> &faces)
    {
      static_assert(dim == 3, "fracture triangles exist in 3D only");
      std::map<std::array<unsigned int, 2>, std::vector<unsigned int>> result;
      for (const auto &f : faces)
        for (unsigned int i = 0; i < 3; ++i)
          {
            std::array<unsigned int, 2> e = {{f.nodes[i], f.nodes[(i + 1) % 3]}};
            std::sort(e.begin(), e.end());
            result[e].push_back(f.index);
          }
      return result;
    }



    template <int dim>
    std::vector<FractureEdge<dim>>
    find_fracture_edges(
      const std::vector<FractureFace<dim>>                              &faces,
      const std::vector<FractureNode<dim>>                              &nodes,
      const std::function<bool(const unsigned int, const unsigned int)> &on_outer_boundary)
    {
      std::vector<FractureEdge<dim>> edges;
      if constexpr (dim == 3)
        {
          for (const auto &[e, with] : faces_of_edges(faces))
            {
              std::set<unsigned int> ids;
              for (const unsigned int f : with)
                ids.insert(faces[f].fracture_id);
              if (with.size() == 2 && ids.size() == 1)
                continue; // inside one fracture
              FractureEdge<dim> edge;
              edge.type         = on_outer_boundary(e[0], e[1]) ? EdgeType::boundary :
                                  with.size() == 1              ? EdgeType::tip :
                                                                  EdgeType::intersection;
              edge.nodes        = e;
              edge.faces        = with;
              edge.fracture_ids = std::vector<unsigned int>(ids.begin(), ids.end());
              edge.length       = nodes[e[0]].location.distance(nodes[e[1]].location);
              edge.centre       = 0.5 * (nodes[e[0]].location + nodes[e[1]].location);
              edges.push_back(edge);
            }
          std::stable_sort(edges.begin(), edges.end(), [](const auto &a, const auto &b) {
            return static_cast<int>(a.type) < static_cast<int>(b.type);
          });
        }
      return edges;
    }



    template <int dim>
    void
    set_distances_to_tip_edges(std::vector<FractureFace<dim>>       &faces,
                               const std::vector<FractureEdge<dim>> &edges,
                               const std::vector<FractureNode<dim>> &nodes)
    {
      std::map<unsigned int, std::vector<unsigned int>> tips_of_fracture;
      for (unsigned int e = 0; e < edges.size(); ++e)
        if (edges[e].type == EdgeType::tip)
          tips_of_fracture[edges[e].fracture_ids[0]].push_back(e);
      for (auto &face : faces)
        {
          face.distance_to_tip = std::numeric_limits<double>::infinity();
          const auto it        = tips_of_fracture.find(face.fracture_id);
          if (it == tips_of_fracture.end())
            continue;
          for (const unsigned int e : it->second)
            face.distance_to_tip =
              std::min(face.distance_to_tip,
                       distance_to_segment<dim>(face.centre,
                                                nodes[edges[e].nodes[0]].location,
                                                nodes[edges[e].nodes[1]].location));
        }
    }



    template std::map<std::array<unsigned int, 2>, std::vector<unsigned int>>
    faces_of_edges<3>(const std::vector<FractureFace<3>> &);
    template std::vector<FractureEdge<2>>
    find_fracture_edges<2>(const std::vector<FractureFace<2>> &,
                           const std::vector<FractureNode<2>> &,
                           const std::function<bool(const unsigned int, const unsigned int)> &);
    template std::vector<FractureEdge<3>>
    find_fracture_edges<3>(const std::vector<FractureFace<3>> &,
                           const std::vector<FractureNode<3>> &,
                           const std::function<bool(const unsigned int, const unsigned int)> &);
    template void
    set_distances_to_tip_edges<2>(std::vector<FractureFace<2>> &,
                                  const std::vector<FractureEdge<2>> &,
                                  const std::vector<FractureNode<2>> &);
    template void
    set_distances_to_tip_edges<3>(std::vector<FractureFace<3>> &,
                                  const std::vector<FractureEdge<3>> &,
                                  const std::vector<FractureNode<3>> &);
  } // namespace geometry
} // namespace porofrac
