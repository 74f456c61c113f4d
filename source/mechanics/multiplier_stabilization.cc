// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/mechanics/multiplier_stabilization.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /// Length (2D) or square root of the area (3D) of a fracture face.
      template <int dim>
      double
      face_size(const std::vector<Point<dim>> &v)
      {
        if constexpr (dim == 2)
          return v[0].distance(v[1]);
        else
          return std::sqrt(0.5 * cross_product_3d(v[1] - v[0], v[2] - v[0]).norm());
      }
    } // namespace



    template <int dim>
    MultiplierStabilization
    make_multiplier_stabilization(const geometry::CutMesh<dim> &mesh,
                                  const ContactParameters      &parameters)
    {
      const double alpha = parameters.multiplier_stabilization;
      if (alpha == 0)
        return {};
      const unsigned int n_f = mesh.fracture_faces.size();
      const double       E_prime =
        parameters.young_modulus / (1. - parameters.poisson_ratio * parameters.poisson_ratio);
      // The faces at each vertex (2D) or edge (3D) of the plus sides, per fracture: neighbours
      // across an intersecting fracture or a tip were cut apart and share none.
      std::map<std::vector<unsigned int>, std::vector<unsigned int>> faces_at;
      std::vector<double>                                            size(n_f);
      for (const auto &face : mesh.fracture_faces)
        {
          const auto side = face.cell[geometry::plus]->face(face.face_no[geometry::plus]);
          std::vector<Point<dim>>   points;
          std::vector<unsigned int> vertices;
          for (unsigned int v = 0; v < side->n_vertices(); ++v)
            {
              points.push_back(side->vertex(v));
              vertices.push_back(side->vertex_index(v));
            }
          size[face.index] = face_size(points);
          for (unsigned int a = 0; a < vertices.size(); ++a)
            {
              std::vector<unsigned int> key = {face.fracture_id, vertices[a]};
              if (dim == 3)
                key.push_back(vertices[(a + 1) % vertices.size()]);
              std::sort(key.begin() + 1, key.end());
              faces_at[key].push_back(face.index);
            }
        }
      MultiplierStabilization S(n_f);
      for (const auto &[key, faces] : faces_at)
        for (const unsigned int f : faces)
          for (const unsigned int g : faces)
            if (f != g)
              S[f].emplace_back(g, alpha * 0.5 * (size[f] + size[g]) / E_prime);
      return S;
    }

    template MultiplierStabilization
    make_multiplier_stabilization(const geometry::CutMesh<2> &, const ContactParameters &);
    template MultiplierStabilization
    make_multiplier_stabilization(const geometry::CutMesh<3> &, const ContactParameters &);
  } // namespace mechanics
} // namespace porofrac
