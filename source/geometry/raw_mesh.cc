// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/exceptions.h>

#include <porofrac/base/config.h>
#include <porofrac/geometry/raw_mesh.h>
#include <porofrac/geometry/simplex_tools.h>

#include <algorithm>
#include <map>

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
      AssertThrow(dim == 2,
                  ExcMessage("Uniform refinement of cut meshes is implemented in 2D only; "
                             "refine 3D meshes in gmsh before reading them."));
      // One new vertex per edge, shared by the cells and tagged faces that contain the edge.
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> midpoint;
      auto mid = [&](unsigned int a, unsigned int b) {
        if (a > b)
          std::swap(a, b);
        const auto it = midpoint.find({a, b});
        if (it != midpoint.end())
          return it->second;
        const unsigned int index = vertices.size();
        Point<dim>         p     = vertices[a];
        p += vertices[b];
        vertices.push_back(0.5 * p);
        midpoint[{a, b}] = index;
        return index;
      };

      if constexpr (dim == 2)
        {
          std::vector<std::array<unsigned int, dim + 1>> new_cells;
          std::vector<types::material_id>              new_material;
          new_cells.reserve(4 * cells.size());
          for (unsigned int c = 0; c < cells.size(); ++c)
            {
              const auto &t   = cells[c];
              const auto  m01 = mid(t[0], t[1]);
              const auto  m12 = mid(t[1], t[2]);
              const auto  m20 = mid(t[2], t[0]);
              // Red refinement keeps the orientation of the parent in all four children.
              new_cells.push_back({{t[0], m01, m20}});
              new_cells.push_back({{m01, t[1], m12}});
              new_cells.push_back({{m20, m12, t[2]}});
              new_cells.push_back({{m01, m12, m20}});
              for (unsigned int k = 0; k < 4; ++k)
                new_material.push_back(cell_material.empty() ? 0 : cell_material[c]);
            }
          cells         = std::move(new_cells);
          cell_material = std::move(new_material);

          auto split = [&](std::vector<TaggedFace> &faces) {
            std::vector<TaggedFace> result;
            result.reserve(2 * faces.size());
            for (const auto &f : faces)
              {
                const unsigned int m = mid(f.vertices[0], f.vertices[1]);
                result.push_back({{{f.vertices[0], m}}, f.tag});
                result.push_back({{{m, f.vertices[1]}}, f.tag});
              }
            faces = std::move(result);
          };
          split(boundary_faces);
          split(fracture_faces);
        }
    }



    template struct RawMesh<2>;
    template struct RawMesh<3>;
  } // namespace geometry
} // namespace porofrac
