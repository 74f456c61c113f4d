// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_SIMPLEX_TOOLS_H
#define POROFRAC_GEOMETRY_SIMPLEX_TOOLS_H

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    using namespace dealii;

    /// Signed measure of a simplex (area in 2D, volume in 3D); positive if counter-clockwise.
    template <int dim>
    double
    signed_measure(const std::vector<Point<dim>>           &vertices,
                   const std::array<unsigned int, dim + 1> &cell)
    {
      if constexpr (dim == 2)
        {
          const Tensor<1, 2> a = vertices[cell[1]] - vertices[cell[0]];
          const Tensor<1, 2> b = vertices[cell[2]] - vertices[cell[0]];
          return 0.5 * (a[0] * b[1] - a[1] * b[0]);
        }
      else
        {
          const Tensor<1, 3> a = vertices[cell[1]] - vertices[cell[0]];
          const Tensor<1, 3> b = vertices[cell[2]] - vertices[cell[0]];
          const Tensor<1, 3> c = vertices[cell[3]] - vertices[cell[0]];
          return cross_product_3d(a, b) * c / 6.0;
        }
    }

    /// Vertex indices of a face (dim of them), sorted: a key for maps.
    template <int dim>
    std::array<unsigned int, dim>
    sorted_face(std::array<unsigned int, dim> face)
    {
      std::sort(face.begin(), face.end());
      return face;
    }

    /// The face of a simplex opposite its local vertex @p i.
    template <int dim>
    std::array<unsigned int, dim>
    face_opposite(const std::array<unsigned int, dim + 1> &cell, const unsigned int i)
    {
      std::array<unsigned int, dim> face;
      unsigned int                  k = 0;
      for (unsigned int j = 0; j < dim + 1; ++j)
        if (j != i)
          face[k++] = cell[j];
      return face;
    }

    /// Unit normal of a face given by its dim vertices (2D: the left normal of the edge
    /// v0 -> v1; 3D: the right-hand rule of v0, v1, v2).
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

    /// Centre of mass of a face given by its dim vertices.
    template <int dim>
    Point<dim>
    face_centre(const std::vector<Point<dim>> &v, const std::array<unsigned int, dim> &f)
    {
      Point<dim> c;
      for (const unsigned int i : f)
        c += v[i];
      return c / double(dim);
    }

    /// Measure of a face given by its dim vertices (length in 2D, area in 3D).
    template <int dim>
    double
    face_measure(const std::vector<Point<dim>> &v, const std::array<unsigned int, dim> &f)
    {
      if constexpr (dim == 2)
        return (v[f[1]] - v[f[0]]).norm();
      else
        return 0.5 * cross_product_3d(v[f[1]] - v[f[0]], v[f[2]] - v[f[0]]).norm();
    }

    /// Circumcentre of a triangle (2D) or tetrahedron (3D).
    template <int dim>
    Point<dim>
    circumcentre(const std::array<Point<dim>, dim + 1> &p)
    {
      // Solve 2 (p_i - p_0) . x = |p_i|^2 - |p_0|^2 for i = 1..dim.
      Tensor<2, dim> A;
      Tensor<1, dim> rhs;
      for (unsigned int i = 0; i < dim; ++i)
        {
          const Tensor<1, dim> d = p[i + 1] - p[0];
          for (unsigned int j = 0; j < dim; ++j)
            A[i][j] = 2 * d[j];
          rhs[i] = p[i + 1].norm_square() - p[0].norm_square();
        }
      return Point<dim>(invert(A) * rhs);
    }

    /// Barycentric test with a relative tolerance: is @p x inside the simplex @p p?
    template <int dim>
    bool
    contains(const std::array<Point<dim>, dim + 1> &p,
             const Point<dim>                      &x,
             const double                           tol = 1e-12)
    {
      Tensor<2, dim> A;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          A[j][i] = p[i + 1][j] - p[0][j];
      const Tensor<1, dim> lambda = invert(A) * (x - p[0]);
      double               sum    = 0;
      for (unsigned int i = 0; i < dim; ++i)
        {
          if (lambda[i] < -tol)
            return false;
          sum += lambda[i];
        }
      return sum <= 1 + tol;
    }
  } // namespace geometry
} // namespace porofrac

#endif
