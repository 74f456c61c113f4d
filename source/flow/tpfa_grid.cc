// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/numbers.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/flow/fracture_junctions.h>
#include <porofrac/flow/tpfa_grid.h>
#include <porofrac/io/text.h>

#include <cmath>
#include <map>
#include <sstream>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      /// Circumcentre of a simplex: 2 (v_i - v_0) . x = |v_i|^2 - |v_0|^2.
      template <int dim, typename Cell>
      Point<dim>
      circumcentre(const Cell &cell)
      {
        FullMatrix<double> A(dim, dim);
        Vector<double>     rhs(dim), x(dim);
        const Point<dim>   v0 = cell->vertex(0);
        for (unsigned int i = 0; i < dim; ++i)
          {
            const Point<dim> vi = cell->vertex(i + 1);
            for (unsigned int d = 0; d < dim; ++d)
              A(i, d) = 2. * (vi[d] - v0[d]);
            rhs(i) = vi.norm_square() - v0.norm_square();
          }
        A.gauss_jordan();
        A.vmult(x, rhs);
        Point<dim> c;
        for (unsigned int d = 0; d < dim; ++d)
          c[d] = x(d);
        return c;
      }

      template <int dim, typename Cell>
      double
      simplex_measure(const Cell &cell)
      {
        const Tensor<1, dim> a = cell->vertex(1) - cell->vertex(0);
        const Tensor<1, dim> b = cell->vertex(2) - cell->vertex(0);
        if constexpr (dim == 2)
          return 0.5 * std::abs(a[0] * b[1] - a[1] * b[0]);
        else
          {
            const Tensor<1, dim> c = cell->vertex(3) - cell->vertex(0);
            return std::abs(cross_product_3d(a, b) * c) / 6.;
          }
      }

      /// Face measure, centroid and unit normal (orientation arbitrary).
      template <int dim, typename Face>
      void
      face_geometry(const Face &face, double &measure, Point<dim> &centre, Tensor<1, dim> &normal)
      {
        centre = Point<dim>();
        for (unsigned int v = 0; v < dim; ++v)
          centre += face->vertex(v) / double(dim);
        const Tensor<1, dim> a = face->vertex(1) - face->vertex(0);
        if constexpr (dim == 2)
          {
            measure   = a.norm();
            normal[0] = -a[1] / measure;
            normal[1] = a[0] / measure;
          }
        else
          {
            const Tensor<1, dim> n = cross_product_3d(a, face->vertex(2) - face->vertex(0));
            measure                = 0.5 * n.norm();
            normal                 = n / n.norm();
          }
      }

      /// d_a/k_a + d_b/k_b; where a centre beyond the face (3D) and a jump of k across it make
      /// this signed resistance vanish or change sign, the unsigned one.
      double
      resistance(const double d_a, const double k_a, const double d_b, const double k_b)
      {
        const double signed_resistance   = d_a / k_a + d_b / k_b;
        const double unsigned_resistance = std::abs(d_a) / k_a + std::abs(d_b) / k_b;
        return signed_resistance < 1e-2 * unsigned_resistance ? unsigned_resistance :
                                                                signed_resistance;
      }

      /// Length scale of a face of measure @p measure: its length (2D), the root of its area (3D).
      template <int dim>
      double
      face_length(const double measure)
      {
        return dim == 2 ? measure : std::sqrt(measure);
      }

      template <int dim>
      double
      weight(const bool axisymmetric, const Point<dim> &x)
      {
        return axisymmetric ? 2. * numbers::PI * x[1] : 1.;
      }
    } // namespace



    template <int dim>
    void
    TpfaGrid<dim>::merge_or_refuse(double           &d_a,
                                   double           &d_b,
                                   const double      measure,
                                   const Point<dim> &centre) const
    {
      // Two circumcentres that (nearly) coincide: the pair is cocircular, the exact two-point
      // flux has T -> infinity. 2D: a distance of 1e-2 |sigma| keeps their pressures together;
      // 3D: the true distance, at least 1e-5 sqrt|sigma| (the six tetrahedra of a cube of a
      // structured mesh then act as one cell to 1e-5).
      const double length = face_length<dim>(measure);
      if (d_a + d_b >= -1e-6 * length)
        {
          if (dim == 2)
            d_a = d_b = 5e-3 * measure;
          else
            d_a = d_b = 0.5 * std::max(d_a + d_b, 1e-5 * length);
          return;
        }
      // Circumcentres in the wrong order: the two-point flux (13) would have the wrong sign. In
      // 2D, Delaunay flips remove these pairs (except across material interfaces): refuse.
      if constexpr (dim == 2)
        throw InputError("Geometry/Delaunay flips",
                         "two-phase flow (TPFA) needs a Delaunay mesh, but the two cells at "
                         "the face centred at " +
                           io::to_text(centre) +
                           " have their circumcentres in the wrong order; set Delaunay flips "
                           "= auto or true (a material interface there is never flipped: "
                           "refine the mesh at it)");
      // 3D (no flips yet): unsigned distances, a consistent but not exact two-point flux.
      d_a = std::max(std::abs(d_a), 5e-6 * length);
      d_b = std::max(std::abs(d_b), 5e-6 * length);
    }



    template <int dim>
    void
    TpfaGrid<dim>::make_nodes(const geometry::CutMesh<dim> &mesh, const bool axisymmetric)
    {
      const auto &tria = mesh.triangulation;
      nodes.resize(n_matrix_cells + n_fracture_cells + n_interfaces);
      for (const auto &cell : tria.active_cell_iterators())
        {
          Node &node = nodes[cell->active_cell_index()];
          node.kind  = NodeKind::matrix;
          node.rock  = matrix_rock;
          Point<dim> centroid;
          for (unsigned int v = 0; v < dim + 1; ++v)
            centroid += cell->vertex(v) / double(dim + 1);
          node.centre  = centres == Centres::circumcentre ? circumcentre<dim>(cell) : centroid;
          node.measure = simplex_measure<dim>(cell) * weight(axisymmetric, centroid);
        }
      for (unsigned int s = 0; s < n_fracture_cells; ++s)
        {
          const auto &face = mesh.fracture_faces[s];
          Node       &node = nodes[n_matrix_cells + s];
          node.kind        = NodeKind::fracture;
          node.rock        = fracture_rock;
          node.centre      = face.centre;
          node.measure     = face.measure * weight(axisymmetric, face.centre);
          for (unsigned int side = 0; side < 2; ++side)
            {
              Node &inode   = nodes[n_matrix_cells + n_fracture_cells + 2 * s + side];
              inode.kind    = NodeKind::interface;
              inode.rock    = fracture_rock;
              inode.centre  = face.centre;
              inode.measure = 0;
            }
        }
    }



    template <int dim>
    void
    TpfaGrid<dim>::add_matrix_connections(const geometry::CutMesh<dim>       &mesh,
                                          const bool                          axisymmetric,
                                          const std::set<types::boundary_id> &matrix_dirichlet_ids)
    {
      const auto &tria = mesh.triangulation;
      // Matrix connections.
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int K = cell->active_cell_index();
          for (const unsigned int f : cell->face_indices())
            {
              double         measure;
              Point<dim>     centre;
              Tensor<1, dim> normal;
              face_geometry<dim>(cell->face(f), measure, centre, normal);
              // Outward normal of K: the opposite vertex lies inside.
              Point<dim> inner;
              for (unsigned int v = 0; v < dim + 1; ++v)
                inner += cell->vertex(v) / double(dim + 1);
              if ((centre - inner) * normal < 0)
                normal = -normal;
              const double d_K  = half_distance(nodes[K].centre, centre, normal); // signed
              const double area = measure * weight(axisymmetric, centre);
              if (d_K <= 0)
                ++n_non_admissible;
              const double d_K_pos = std::max(d_K, 1e-3 * cell->diameter());

              if (!cell->at_boundary(f))
                {
                  const unsigned int L = cell->neighbor(f)->active_cell_index();
                  if (K < L)
                    {
                      double d_a = d_K, d_b = half_distance(nodes[L].centre, centre, -normal);
                      if (d_a + d_b < 1e-2 * face_length<dim>(measure))
                        {
                          ++n_fallback;
                          merge_or_refuse(d_a, d_b, measure, centre);
                        }
                      connections.push_back({ConnectionKind::matrix_matrix,
                                             K,
                                             L,
                                             matrix_rock,
                                             matrix_rock,
                                             area,
                                             d_a,
                                             d_b});
                    }
                  continue;
                }
              const auto ff = mesh.fracture_face(cell, f);
              if (ff.first != numbers::invalid_unsigned_int)
                {
                  const unsigned int I =
                    n_matrix_cells + n_fracture_cells + 2 * ff.first + ff.second;
                  connections.push_back({ConnectionKind::matrix_interface,
                                         K,
                                         I,
                                         matrix_rock,
                                         matrix_rock,
                                         area,
                                         d_K_pos,
                                         0.});
                  continue;
                }
              const types::boundary_id id = cell->face(f)->boundary_id();
              if (matrix_dirichlet_ids.count(id))
                {
                  Node node;
                  node.kind        = NodeKind::dirichlet_matrix;
                  node.rock        = matrix_rock;
                  node.measure     = 0;
                  node.centre      = centre;
                  node.boundary_id = id;
                  nodes.push_back(node);
                  connections.push_back({ConnectionKind::matrix_boundary,
                                         K,
                                         static_cast<unsigned int>(nodes.size() - 1),
                                         matrix_rock,
                                         matrix_rock,
                                         area,
                                         d_K_pos,
                                         0.});
                }
            }
        }
    }



    template <int dim>
    void
    TpfaGrid<dim>::add_interface_connections(const geometry::CutMesh<dim> &mesh,
                                             const bool                    axisymmetric)
    {
      // Interface-fracture connections (eq. (3); the interface carries rock type a = fracture).
      for (unsigned int s = 0; s < n_fracture_cells; ++s)
        for (unsigned int side = 0; side < 2; ++side)
          connections.push_back(
            {ConnectionKind::interface_fracture,
             n_matrix_cells + n_fracture_cells + 2 * s + side,
             n_matrix_cells + s,
             fracture_rock,
             fracture_rock,
             mesh.fracture_faces[s].measure * weight(axisymmetric, mesh.fracture_faces[s].centre),
             0.,
             0.});
    }



    template <int dim>
    double
    TpfaGrid<dim>::one_sided_distance(const geometry::CutMesh<dim> &mesh,
                                      const unsigned int            face,
                                      const FractureJunction<dim>  &junction)
    {
      const double d = distance_to_junction(mesh, face, junction, centres == Centres::centroid);
      if (d > 0)
        return d;
      // A circumcentre on or beyond the edge (3D, obtuse triangle): as for matrix cells at the
      // boundary, a small positive distance.
      ++n_non_admissible_fracture;
      return 1e-3 * std::sqrt(mesh.fracture_faces[face].measure);
    }



    template <int dim>
    void
    TpfaGrid<dim>::add_fracture_node_connections(
      const geometry::CutMesh<dim>       &mesh,
      const bool                          axisymmetric,
      const std::set<types::boundary_id> &fracture_dirichlet_ids)
    {
      for (const auto &j : fracture_junctions(mesh))
        {
          const unsigned int n_faces   = j.faces.size();
          const double       area      = j.measure * weight(axisymmetric, j.location);
          const bool         dirichlet = fracture_dirichlet_ids.count(j.boundary_id) > 0;
          if (dirichlet || n_faces >= 3)
            {
              Node node;
              node.kind        = dirichlet ? NodeKind::dirichlet_fracture : NodeKind::intersection;
              node.rock        = fracture_rock;
              node.measure     = 0;
              node.centre      = j.location;
              node.boundary_id = j.boundary_id;
              nodes.push_back(node);
              if (!dirichlet)
                ++n_intersections;
              for (const unsigned int s : j.faces)
                connections.push_back({ConnectionKind::fracture_node,
                                       n_matrix_cells + s,
                                       static_cast<unsigned int>(nodes.size() - 1),
                                       fracture_rock,
                                       fracture_rock,
                                       area,
                                       one_sided_distance(mesh, s, j),
                                       0.});
            }
          else if (n_faces == 2)
            {
              const unsigned int s0 = j.faces[0], s1 = j.faces[1];
              const bool         c  = centres == Centres::centroid;
              double             d0 = distance_to_junction(mesh, s0, j, c);
              double             d1 = distance_to_junction(mesh, s1, j, c);
              if (dim == 3 && d0 + d1 < 1e-2 * j.measure)
                {
                  // 3D: circumcentres (nearly) together, as for the two triangles of a grid
                  // square, or in the wrong order across the edge (as merge_or_refuse).
                  ++n_non_admissible_fracture;
                  if (d0 + d1 >= -1e-6 * j.measure)
                    d0 = d1 = 0.5 * std::max(d0 + d1, 1e-5 * j.measure);
                  else
                    {
                      d0 = std::max(std::abs(d0), 5e-6 * j.measure);
                      d1 = std::max(std::abs(d1), 5e-6 * j.measure);
                    }
                }
              connections.push_back({ConnectionKind::fracture_fracture,
                                     n_matrix_cells + s0,
                                     n_matrix_cells + s1,
                                     fracture_rock,
                                     fracture_rock,
                                     area,
                                     d0,
                                     d1});
            }
          // one face: a tip or a no-flow boundary point or edge
        }
    }



    template <int dim>
    TpfaGrid<dim>::TpfaGrid(const geometry::CutMesh<dim>       &mesh,
                            const bool                          axisymmetric,
                            const std::set<types::boundary_id> &matrix_dirichlet_ids,
                            const std::set<types::boundary_id> &fracture_dirichlet_ids,
                            const Centres                       centres)
        : centres(centres)
    {
      const auto &tria          = mesh.triangulation;
      n_matrix_cells            = tria.n_active_cells();
      n_fracture_cells          = mesh.fracture_faces.size();
      n_interfaces              = 2 * n_fracture_cells;
      n_intersections           = 0;
      n_non_admissible          = 0;
      n_fallback                = 0;
      n_non_admissible_fracture = 0;

      make_nodes(mesh, axisymmetric);
      add_matrix_connections(mesh, axisymmetric, matrix_dirichlet_ids);
      add_interface_connections(mesh, axisymmetric);
      add_fracture_node_connections(mesh, axisymmetric, fracture_dirichlet_ids);
      porosity.assign(n_matrix_cells, 0.1);
      permeability.assign(n_matrix_cells, 1.);
      aperture.assign(n_fracture_cells, 1e-3);
    }

    template <int dim>
    void
    TpfaGrid<dim>::update_transmissibilities()
    {
      check_input(normal_transmissibility > 0,
                  "Flow/Fracture/Normal transmissibility",
                  "must be positive");
      for (const double k : permeability)
        check_input(k > 0 && std::isfinite(k), "Flow/Matrix/Permeability", "must be positive");
      for (const double d : aperture)
        check_input(d > 0 && std::isfinite(d), "Flow/Fracture/Aperture", "must be positive");
      for (const double p : porosity)
        check_input(p > 0 && p < 1, "Flow/Matrix/Porosity", "must lie in (0, 1)");
      const auto conductivity = [this](const unsigned int node) {
        const double d = aperture[node - n_matrix_cells];
        return d * d * d / 12.;
      };
      for (auto &c : connections)
        switch (c.kind)
          {
            case ConnectionKind::matrix_matrix:
              c.transmissibility =
                c.area / resistance(c.d_a, permeability[c.a], c.d_b, permeability[c.b]);
              break;
            case ConnectionKind::matrix_boundary:
            case ConnectionKind::matrix_interface:
              c.transmissibility = c.area * permeability[c.a] / c.d_a;
              break;
            case ConnectionKind::interface_fracture:
              c.transmissibility = c.area * normal_transmissibility;
              break;
            case ConnectionKind::fracture_fracture:
              c.transmissibility =
                c.area / resistance(c.d_a, conductivity(c.a), c.d_b, conductivity(c.b));
              break;
            case ConnectionKind::fracture_node:
              c.transmissibility = c.area * conductivity(c.a) / c.d_a;
              break;
          }
      for (const auto &c : connections)
        if (!(c.transmissibility > 0) || !std::isfinite(c.transmissibility))
          {
            std::ostringstream s;
            s << "a transmissibility is not positive (" << c.transmissibility
              << ") between flow nodes at " << nodes[c.a].centre << " and " << nodes[c.b].centre
              << ": the mesh is not TPFA-admissible there";
            throw InputError("Geometry/Mesh size", s.str());
          }
    }

    template <int dim>
    double
    TpfaGrid<dim>::pore_volume(const unsigned int i) const
    {
      if (i < n_matrix_cells)
        return nodes[i].measure * porosity[i];
      if (i < n_matrix_cells + n_fracture_cells)
        return nodes[i].measure * aperture[i - n_matrix_cells];
      if (nodes[i].kind == NodeKind::interface)
        {
          // Interface node 2 s + side of fracture face s, whose fracture cell has measure |sigma|.
          const unsigned int s = (i - n_matrix_cells - n_fracture_cells) / 2;
          return nodes[n_matrix_cells + s].measure * damaged_layer_thickness *
                 damaged_layer_porosity;
        }
      return 0.;
    }

    template <int dim>
    std::vector<unsigned int>
    TpfaGrid<dim>::node_owners(const std::vector<unsigned int> &cell_owner) const
    {
      constexpr unsigned int    none = numbers::invalid_unsigned_int;
      std::vector<unsigned int> owner(n_nodes(), none);
      for (unsigned int K = 0; K < n_matrix_cells; ++K)
        owner[K] = cell_owner[K];
      for (bool changed = true; changed;)
        {
          changed = false;
          for (const auto &c : connections)
            if ((owner[c.a] == none) != (owner[c.b] == none))
              {
                owner[owner[c.a] == none ? c.a : c.b] = std::min(owner[c.a], owner[c.b]);
                changed                               = true;
              }
        }
      // An interface node goes with its fracture cell (that of the side-0 matrix cell), not
      // with its own matrix cell: a partition boundary along a fracture then cuts the matrix-
      // interface connections, not the interface-fracture ones, whose |sigma| Lambda_f is
      // typically orders of magnitude larger and which block-Jacobi ILU and per-process AMG
      // aggregates would otherwise lose.
      for (const auto &c : connections)
        if (c.kind == ConnectionKind::interface_fracture)
          owner[c.a] = owner[c.b];
      for (auto &o : owner)
        if (o == none)
          o = 0;
      return owner;
    }

    template class TpfaGrid<2>;
    template class TpfaGrid<3>;
  } // namespace flow
} // namespace porofrac
