// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/geometry/mesh_quality.h>
#include <porofrac/geometry/simplex_tools.h>

#include <algorithm>
#include <cmath>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      template <int dim>
      std::array<Point<dim>, dim + 1>
      corners(const typename Triangulation<dim>::active_cell_iterator &cell)
      {
        std::array<Point<dim>, dim + 1> p;
        for (unsigned int i = 0; i < dim + 1; ++i)
          p[i] = cell->vertex(i);
        return p;
      }

      /// Outward unit normal of face @p f of a simplex cell.
      template <int dim>
      Tensor<1, dim>
      outward_normal(const typename Triangulation<dim>::active_cell_iterator &cell,
                     const unsigned int                                       f)
      {
        const auto     face = cell->face(f);
        Tensor<1, dim> n;
        if constexpr (dim == 2)
          {
            const Tensor<1, 2> t = face->vertex(1) - face->vertex(0);
            n[0]                 = t[1];
            n[1]                 = -t[0];
          }
        else
          n =
            cross_product_3d(face->vertex(1) - face->vertex(0), face->vertex(2) - face->vertex(0));
        n /= n.norm();
        if ((face->center() - cell->center()) * n < 0)
          n *= -1;
        return n;
      }

      template <int dim>
      double
      face_diameter(const typename Triangulation<dim>::active_cell_iterator &cell,
                    const unsigned int                                       f)
      {
        double     d    = 0;
        const auto face = cell->face(f);
        for (unsigned int i = 0; i < face->n_vertices(); ++i)
          for (unsigned int j = i + 1; j < face->n_vertices(); ++j)
            d = std::max(d, face->vertex(i).distance(face->vertex(j)));
        return d;
      }

      /// Smallest and largest dihedral angle (degrees) of a tetrahedron, at its six edges.
      std::pair<double, double>
      dihedral_angles(const std::array<Point<3>, 4> &p)
      {
        std::array<Tensor<1, 3>, 4> n; // outward normal of the face opposite vertex i
        for (unsigned int i = 0; i < 4; ++i)
          {
            const Point<3> &a = p[(i + 1) % 4], &b = p[(i + 2) % 4], &c = p[(i + 3) % 4];
            n[i] = cross_product_3d(b - a, c - a);
            n[i] /= n[i].norm();
            if ((p[i] - a) * n[i] > 0)
              n[i] *= -1;
          }
        double lo = 180, hi = 0;
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = i + 1; j < 4; ++j)
            {
              const double angle = 180 - std::acos(std::clamp(n[i] * n[j], -1., 1.)) * 180 / M_PI;
              lo                 = std::min(lo, angle);
              hi                 = std::max(hi, angle);
            }
        return {lo, hi};
      }
    } // namespace



    template <int dim>
    std::vector<Point<dim>>
    cell_circumcentres(const Triangulation<dim> &triangulation)
    {
      std::vector<Point<dim>> centres(triangulation.n_active_cells());
      for (const auto &cell : triangulation.active_cell_iterators())
        centres[cell->active_cell_index()] = circumcentre<dim>(corners<dim>(cell));
      return centres;
    }



    template <int dim>
    MeshQuality
    assess_mesh(const CutMesh<dim> &mesh)
    {
      const auto &tria    = mesh.triangulation;
      const auto  centres = cell_circumcentres(tria);
      MeshQuality q;
      q.n_cells           = tria.n_active_cells();
      q.n_vertices        = tria.n_used_vertices();
      q.n_fracture_faces  = mesh.fracture_faces.size();
      q.min_angle_degrees = 180;
      if (dim == 3)
        q.min_dihedral_degrees = 180;
      for (const auto &cell : tria.active_cell_iterators())
        {
          const auto p = corners<dim>(cell);
          // Angles at the corners of each triangular facet (2D: the triangle itself).
          for (unsigned int i = 0; i < dim + 1; ++i)
            for (unsigned int j = 0; j < dim + 1; ++j)
              for (unsigned int k = j + 1; k < dim + 1; ++k)
                if (j != i && k != i)
                  {
                    const Tensor<1, dim> a = p[j] - p[i], b = p[k] - p[i];
                    const double         angle =
                      std::acos(std::clamp(a * b / (a.norm() * b.norm()), -1., 1.)) * 180 / M_PI;
                    q.min_angle_degrees = std::min(q.min_angle_degrees, angle);
                    q.max_angle_degrees = std::max(q.max_angle_degrees, angle);
                  }
          if constexpr (dim == 3)
            {
              const auto [lo, hi]    = dihedral_angles(p);
              q.min_dihedral_degrees = std::min(q.min_dihedral_degrees, lo);
              q.max_dihedral_degrees = std::max(q.max_dihedral_degrees, hi);
            }
          const Point<dim> &xK = centres[cell->active_cell_index()];
          if (!contains<dim>(p, xK, 1e-10))
            ++q.n_centres_outside;
          for (const unsigned int f : cell->face_indices())
            {
              const Tensor<1, dim> n = outward_normal<dim>(cell, f);
              if (cell->at_boundary(f))
                {
                  if ((cell->face(f)->center() - xK) * n <= 0)
                    ++q.n_boundary_non_positive_distance;
                  continue;
                }
              const auto neighbor = cell->neighbor(f);
              if (neighbor->active_cell_index() < cell->active_cell_index())
                continue;
              ++q.n_connections;
              const Tensor<1, dim> d     = centres[neighbor->active_cell_index()] - xK;
              const double         along = d * n;
              if (along <= 0)
                ++q.n_non_positive_distance;
              // Relative to the face too: nearly cospherical neighbours have nearly equal
              // circumcentres, whose round-off would otherwise count as a deviation.
              else if ((d - along * n).norm() >
                       1e-8 * std::max(d.norm(), face_diameter<dim>(cell, f)))
                ++q.n_non_orthogonal;
            }
        }
      return q;
    }



    template MeshQuality
    assess_mesh<2>(const CutMesh<2> &);
    template MeshQuality
    assess_mesh<3>(const CutMesh<3> &);
    template std::vector<Point<2>>
    cell_circumcentres<2>(const Triangulation<2> &);
    template std::vector<Point<3>>
    cell_circumcentres<3>(const Triangulation<3> &);
  } // namespace geometry
} // namespace porofrac
