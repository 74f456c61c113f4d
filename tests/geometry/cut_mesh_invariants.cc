// SPDX-License-Identifier: LGPL-2.1-or-later
// Invariants of the cut mesh for the fracture configurations PoroFrac must handle (one interior
// fracture, X, T, corner, tip on the boundary, a fracture through the domain, the six-fracture
// network), each before and after two uniform refinements:
// - the cells tile the domain (area);
// - on each side, the fracture faces add up to the geometric length of each fracture;
// - every fracture face of the Triangulation has exactly one partner (same centre, opposite
//   normal, other cell);
// - side regions: a vertex is shared at interior tips and duplicated once per side region
//   elsewhere (2 inside a fracture or at a corner, 4 at an X, 3 at a T, k+1 where k fracture faces
//   reach the outer boundary);
// - the fracture-face table: n+ points out of the plus cell and is the left normal of the
//   tangent, abscissae are continuous along each fracture, tips lie half a face from the nearest
//   face centre (none for a fracture through the domain);
// - a P2 field that jumps across a fracture keeps its jump exactly.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/geometry/fracture_network.h>
#include <porofrac/geometry/mesh_generator.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>

using namespace dealii;
using namespace porofrac::geometry;

namespace
{
  struct Configuration
  {
    std::string name;
    std::string box;
    std::string fractures;
    double      domain_area;
  };

  /// Expected number of side regions (vertex copies) at a fracture node.
  unsigned int
  expected_copies(const FractureNode<2> &node)
  {
    switch (node.type)
      {
        case NodeType::tip:
          return 1;
        case NodeType::intersection:
          return node.faces.size();
        case NodeType::boundary:
          return node.faces.size() + 1;
        default:
          return 2;
      }
  }

  void
  check(const Configuration &c, const unsigned int refinements)
  {
    GeometryParameters prm;
    prm.domain              = "box";
    prm.box                 = c.box;
    prm.fractures           = c.fractures;
    prm.mesh_size           = 0.1;
    prm.fracture_mesh_size  = 0.05;
    prm.transition_distance = 0.2;
    prm.global_refinements  = refinements;
    prm.algorithm           = "delaunay";
    prm.delaunay_flips      = false;
    const auto  mesh_ptr    = make_cut_mesh<2>(prm);
    const auto &mesh        = *mesh_ptr;
    const auto &tria        = mesh.triangulation;
    const auto  network     = network_from_parameters(prm);

    std::cout << c.name << ", " << refinements << " refinements: " << tria.n_active_cells()
              << " cells, " << mesh.fracture_faces.size() << " fracture faces" << std::endl;

    double area = 0;
    for (const auto &cell : tria.active_cell_iterators())
      area += cell->measure();
    std::cout << "  area relative error: " << std::abs(area - c.domain_area) / c.domain_area
              << std::endl;

    // Side lengths per fracture from the Triangulation's boundary faces.
    std::map<types::boundary_id, double> side_length;
    struct SideFace
    {
      Point<2>           centre;
      Tensor<1, 2>       normal;
      unsigned int       cell;
      types::boundary_id id;
    };
    std::vector<SideFace> side_faces;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) && cell->face(f)->boundary_id() >= first_fracture_boundary_id)
          {
            const auto face = cell->face(f);
            side_length[face->boundary_id()] += face->measure();
            Tensor<1, 2> t = face->vertex(1) - face->vertex(0), n;
            n[0]           = t[1] / t.norm();
            n[1]           = -t[0] / t.norm();
            if ((face->center() - cell->center()) * n < 0)
              n *= -1;
            side_faces.push_back(
              {face->center(), n, cell->active_cell_index(), face->boundary_id()});
          }
    double worst_length = 0;
    for (const auto &f : network.fractures)
      {
        double length = 0;
        for (unsigned int k = 0; k + 1 < f.points.size(); ++k)
          length += f.points[k].distance(f.points[k + 1]);
        for (const Side side : {plus, minus})
          worst_length =
            std::max(worst_length,
                     std::abs(side_length[fracture_boundary_id(f.id, side)] - length) / length);
      }
    std::cout << "  max relative error of side lengths: " << worst_length << std::endl;

    unsigned int exactly_one = 0;
    for (const auto &a : side_faces)
      {
        unsigned int partners = 0;
        for (const auto &b : side_faces)
          if (a.cell != b.cell && a.centre.distance(b.centre) < 1e-12 &&
              (a.normal + b.normal).norm() < 1e-12 && (a.id ^ 1u) == b.id)
            ++partners;
        exactly_one += (partners == 1);
      }
    std::cout << "  fracture sides with exactly one partner: " << exactly_one << " of "
              << side_faces.size() << std::endl;

    // The fracture-face table: n+ points out of the plus cell, n+ = (-t_y, t_x), abscissae
    // continue from face to face along each fracture, tips are as far as the geometry says.
    unsigned int bad_sides = 0, bad_frames = 0, bad_abscissae = 0;
    double       nearest_tip = std::numeric_limits<double>::infinity();
    for (const auto &f : mesh.fracture_faces)
      {
        bad_sides += ((f.cell[plus]->center() - f.centre) * f.normal >= 0) ||
                     ((f.cell[minus]->center() - f.centre) * f.normal <= 0);
        bad_frames += std::abs(f.normal.norm() - 1) > 1e-12 ||
                      std::abs(f.normal[0] + f.tangent[1]) > 1e-12 ||
                      std::abs(f.normal[1] - f.tangent[0]) > 1e-12;
        nearest_tip = std::min(nearest_tip, f.distance_to_tip / f.measure);
      }
    for (const auto &[id, faces] : mesh.faces_of_fracture)
      for (unsigned int k = 0; k < faces.size(); ++k)
        {
          const auto  &f = mesh.fracture_faces[faces[k]];
          const double expected_begin =
            k == 0 ? 0. : mesh.fracture_faces[faces[k - 1]].abscissa_end;
          bad_abscissae += std::abs(f.abscissa_begin - expected_begin) > 1e-12 ||
                           std::abs(f.abscissa_end - f.abscissa_begin - f.measure) > 1e-12;
        }
    std::cout << "  faces with the plus cell on the wrong side: " << bad_sides
              << ", with a wrong normal/tangent frame: " << bad_frames
              << ", with discontinuous abscissae: " << bad_abscissae << std::endl
              << "  smallest distance to a tip / face length: "
              << (std::isfinite(nearest_tip) ? nearest_tip : -1.) << std::endl;

    std::map<std::string, unsigned int> n_type;
    unsigned int                        wrong_copies = 0;
    for (const auto &node : mesh.fracture_nodes)
      {
        static const char *names[] = {
          "tip", "interior", "corner", "junction", "intersection", "boundary"};
        ++n_type[names[static_cast<int>(node.type)]];
        bool distinct_same_place = true;
        for (unsigned int i = 0; i < node.copies.size(); ++i)
          distinct_same_place &= tria.get_vertices()[node.copies[i]].distance(node.location) == 0.;
        if (node.copies.size() != expected_copies(node) || !distinct_same_place)
          ++wrong_copies;
      }
    std::cout << "  nodes:";
    for (const auto &[type, n] : n_type)
      std::cout << " " << type << " " << n;
    std::cout << "; with a wrong number of side regions: " << wrong_copies << std::endl;
  }

  /// A fracture through the whole box splits it: u = x y + (1 above, 0 below), interpolated in P2
  /// cell by cell, must jump by exactly [u] = u+ - u- = -1 on every face (plus side is below).
  void
  check_p2_jump()
  {
    GeometryParameters prm;
    prm.domain              = "box";
    prm.box                 = "(0, 0) (1, 1)";
    prm.fractures           = "1: (0, 0.4) (1, 0.6)";
    prm.mesh_size           = 0.1;
    prm.fracture_mesh_size  = 0.05;
    prm.transition_distance = 0.2;
    prm.global_refinements  = 1;
    prm.algorithm           = "delaunay";
    prm.delaunay_flips      = false;
    const auto mesh         = make_cut_mesh<2>(prm);

    FE_SimplexP<2> fe(2);
    DoFHandler<2>  dof_handler(mesh->triangulation);
    dof_handler.distribute_dofs(fe);
    Vector<double>                       u(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const Point<2> c     = cell->center();
        const double   above = (c[1] > 0.4 + 0.2 * c[0]) ? 1. : 0.;
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const Point<2> x =
              mesh->mapping().transform_unit_to_real_cell(cell, fe.get_unit_support_points()[i]);
            u[dofs[i]] = x[0] * x[1] + above;
          }
      }
    const QGaussSimplex<1> quadrature(3);
    FEFaceValues<2> fv(mesh->mapping(), fe, quadrature, update_values | update_quadrature_points);
    double          worst = 0;
    for (const auto &face : mesh->fracture_faces)
      {
        std::array<std::vector<double>, 2>   values;
        std::array<std::vector<Point<2>>, 2> points;
        for (const Side side : {plus, minus})
          {
            const typename DoFHandler<2>::active_cell_iterator cell(&mesh->triangulation,
                                                                    face.cell[side]->level(),
                                                                    face.cell[side]->index(),
                                                                    &dof_handler);
            fv.reinit(cell, face.face_no[side]);
            values[side].resize(quadrature.size());
            fv.get_function_values(u, values[side]);
            points[side] = fv.get_quadrature_points();
          }
        // Quadrature points of the two sides may be ordered differently: match them.
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          for (unsigned int r = 0; r < quadrature.size(); ++r)
            if (points[plus][q].distance(points[minus][r]) < 1e-12)
              worst = std::max(worst, std::abs(values[plus][q] - values[minus][r] + 1.));
      }
    std::cout << "P2 jump across a through-going fracture: " << mesh->fracture_faces.size()
              << " faces, max |[u] - (-1)| at quadrature points: " << worst << std::endl;
  }
} // namespace

int
main()
{
  std::cout << std::scientific << std::setprecision(3);
  const std::vector<Configuration> configurations = {
    {"interior fracture", "(0, 0) (1, 1)", "1: (0.3, 0.5) (0.7, 0.5)", 1.},
    {"X intersection", "(0, 0) (1, 1)", "1: (0.2, 0.5) (0.8, 0.5); 2: (0.5, 0.2) (0.5, 0.8)", 1.},
    {"T intersection", "(0, 0) (1, 1)", "1: (0.2, 0.5) (0.8, 0.5); 2: (0.5, 0.5) (0.5, 0.8)", 1.},
    {"corner", "(0, 0) (1, 1)", "1: (0.2, 0.3) (0.5, 0.6) (0.8, 0.4)", 1.},
    {"tip on the boundary", "(0, 0) (1, 1)", "1: (0.5, 0.5) (1, 0.5)", 1.},
    {"through fracture", "(0, 0) (1, 1)", "1: (0, 0.4) (1, 0.6)", 1.},
    {"six fractures",
     "(0, 0) (2, 1)",
     "1: (0.2, 0.7) (0.5, 0.7) (0.8, 0.65); 2: (1.0, 0.3) (1.8, 0.4); "
     "3: (0.2, 0.3) (0.6, 0.25); 4: (1.0, 0.4) (1.7, 0.85); 5: (1.5, 0.65) (2.0, 0.55); "
     "6: (1.5, 0.05) (1.4, 0.25)",
     2.}};
  for (const auto &c : configurations)
    for (const unsigned int r : {0u, 2u})
      check(c, r);
  check_p2_jump();
}
