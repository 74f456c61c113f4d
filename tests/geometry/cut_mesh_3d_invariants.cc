// SPDX-License-Identifier: LGPL-2.1-or-later
// Invariants of the 3D cut mesh for the fracture configurations PoroFrac must handle (a fracture
// with tips all round, an X line, a T line, three fractures meeting at a point, a fracture
// cutting the boundary, a triangle meshed as one face, a disc, a plane through the box, three
// planes through the box), each
// from gmsh and after one uniform (Bey) refinement:
// - the cells tile the box (volume);
// - on each side, the fracture faces add up to each polygon's area inside the box;
// - every fracture face of the Triangulation has exactly one partner (same centre, opposite
//   normal, other cell, the other side's boundary id);
// - every fracture vertex has as many copies as there are side regions around it, counted
//   independently by sampling a small sphere around it and joining neighbouring samples whose
//   chord crosses no fracture polygon (1 on a tip edge, 2 inside a fracture, 3 on a T line,
//   4 on an X line, 8 where three planes cross, fewer on the outer boundary);
// - the fracture-face table: n+ points out of the plus cell and equals the right-hand-rule
//   normal of the polygon, (t1, t2, n+) is orthonormal and right-handed, t1 is the same on every
//   face of a fracture (the first edge direction), the distance to the tips equals the distance
//   to the polygon's tip edges;
// - the fracture edges: lengths of the intersection, tip and boundary edges;
// - three planes through the box: a P2 field with jumps 1, 2 and 4 across them keeps its jumps
//   exactly.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/polygon_mesher.h>
#include <porofrac/geometry/polygon_network.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

using namespace dealii;
using namespace porofrac::geometry;

namespace
{
  struct Configuration
  {
    std::string name;
    std::string fractures;
    double      fracture_mesh_size;
    double      intersection_length, tip_length, boundary_length; ///< the geometric truth
    bool        check_p2_jump;
  };

  /// A polygon as the test sees it, with its own plane (Newell normal) and projection.
  struct TestPolygon
  {
    std::vector<Point<3>> corners;
    Tensor<1, 3>          normal; ///< right-hand rule of the corner order
    unsigned int          drop;   ///< the coordinate dropped for point-in-polygon tests
  };

  TestPolygon
  make_polygon(const std::vector<Point<3>> &corners)
  {
    TestPolygon p{corners, Tensor<1, 3>(), 0};
    for (unsigned int i = 0; i < corners.size(); ++i)
      p.normal += cross_product_3d(corners[i], corners[(i + 1) % corners.size()]);
    p.normal /= p.normal.norm();
    for (unsigned int d = 1; d < 3; ++d)
      if (std::abs(p.normal[d]) > std::abs(p.normal[p.drop]))
        p.drop = d;
    return p;
  }

  /// Is @p x (in the polygon's plane) inside it? Crossing number in the projected plane.
  bool
  inside(const TestPolygon &p, const Point<3> &x)
  {
    const unsigned int a = (p.drop + 1) % 3, b = (p.drop + 2) % 3;
    bool               in = false;
    const auto        &c  = p.corners;
    for (unsigned int i = 0, j = c.size() - 1; i < c.size(); j = i++)
      if ((c[i][b] > x[b]) != (c[j][b] > x[b]) &&
          x[a] < (c[j][a] - c[i][a]) * (x[b] - c[i][b]) / (c[j][b] - c[i][b]) + c[i][a])
        in = !in;
    return in;
  }

  /// Does the chord [x, y] pass through the polygon?
  bool
  blocks(const TestPolygon &p, const Point<3> &x, const Point<3> &y)
  {
    const double hx = (x - p.corners[0]) * p.normal, hy = (y - p.corners[0]) * p.normal;
    if ((hx > 0) == (hy > 0))
      return false;
    return inside(p, x + (hx / (hx - hy)) * (y - x));
  }

  bool
  in_box(const Point<3> &x)
  {
    for (unsigned int d = 0; d < 3; ++d)
      if (x[d] <= 1e-12 || x[d] >= 1 - 1e-12)
        return false;
    return true;
  }

  /// Unit-sphere samples (Fibonacci) and, for each, its six nearest neighbours.
  struct Sphere
  {
    std::vector<Tensor<1, 3>>              points;
    std::vector<std::vector<unsigned int>> neighbours;
    Sphere()
    {
      const unsigned int n = 300;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double z = 1 - (2 * i + 1.) / n, r = std::sqrt(1 - z * z);
          const double phi = i * M_PI * (3 - std::sqrt(5.));
          points.push_back(Tensor<1, 3>({r * std::cos(phi), r * std::sin(phi), z}));
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          std::vector<unsigned int> order(n);
          std::iota(order.begin(), order.end(), 0u);
          std::partial_sort(order.begin(), order.begin() + 7, order.end(), [&](auto a, auto b) {
            return (points[a] - points[i]).norm() < (points[b] - points[i]).norm();
          });
          neighbours.emplace_back(order.begin() + 1, order.begin() + 7);
        }
    }
  };

  /// Side regions around @p x: connected components of the samples of a small sphere.
  unsigned int
  side_regions(const Point<3> &x, const std::vector<TestPolygon> &polygons, const Sphere &sphere)
  {
    const double              rho = 0.004;
    const unsigned int        n   = sphere.points.size();
    std::vector<unsigned int> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](unsigned int i) {
      while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    };
    // Only polygons whose plane passes through the ball can separate samples.
    std::vector<const TestPolygon *> near;
    for (const auto &p : polygons)
      if (std::abs((x - p.corners[0]) * p.normal) < rho)
        near.push_back(&p);
    std::vector<bool> used(n);
    for (unsigned int i = 0; i < n; ++i)
      used[i] = in_box(x + rho * sphere.points[i]);
    for (unsigned int i = 0; i < n; ++i)
      for (const unsigned int j : sphere.neighbours[i])
        if (used[i] && used[j])
          {
            const Point<3> a = x + rho * sphere.points[i], b = x + rho * sphere.points[j];
            bool           free = true;
            for (const auto *p : near)
              free = free && !blocks(*p, a, b);
            if (free)
              parent[find(i)] = find(j);
          }
    unsigned int regions = 0;
    for (unsigned int i = 0; i < n; ++i)
      regions += used[i] && find(i) == i;
    return regions;
  }

  double
  distance_to_segment(const Point<3> &x, const Point<3> &a, const Point<3> &b)
  {
    const double t = std::clamp((x - a) * (b - a) / (b - a).norm_square(), 0., 1.);
    return x.distance(a + t * (b - a));
  }

  /// The polygon edges of fracture k that are tips: inside the box, not on another fracture.
  std::vector<std::array<Point<3>, 2>>
  tip_segments(const std::vector<TestPolygon> &polygons, const unsigned int k)
  {
    std::vector<std::array<Point<3>, 2>> tips;
    const auto                          &c = polygons[k].corners;
    for (unsigned int i = 0; i < c.size(); ++i)
      {
        const Point<3> a = c[i], b = c[(i + 1) % c.size()], m = 0.5 * (a + b);
        bool           on_other = false;
        for (unsigned int j = 0; j < polygons.size(); ++j)
          if (j != k && std::abs((a - polygons[j].corners[0]) * polygons[j].normal) < 1e-12 &&
              std::abs((b - polygons[j].corners[0]) * polygons[j].normal) < 1e-12 &&
              inside(polygons[j], m))
            on_other = true;
        // The part of the edge inside the box (Liang-Barsky clipping).
        double lo = 0, hi = 1;
        for (unsigned int d = 0; d < 3; ++d)
          {
            const double delta = b[d] - a[d];
            if (std::abs(delta) < 1e-14)
              {
                if (a[d] < 0 || a[d] > 1)
                  hi = -1;
                continue;
              }
            const double t0 = (0 - a[d]) / delta, t1 = (1 - a[d]) / delta;
            lo = std::max(lo, std::min(t0, t1));
            hi = std::min(hi, std::max(t0, t1));
          }
        if (hi > lo + 1e-12 && !on_other)
          tips.push_back({{a + lo * (b - a), a + hi * (b - a)}});
      }
    return tips;
  }

  /// Outward unit normal of a boundary face of a tetrahedron.
  Tensor<1, 3>
  outward_normal(const Triangulation<3>::active_cell_iterator &cell, const unsigned int f)
  {
    const auto   face = cell->face(f);
    Tensor<1, 3> n =
      cross_product_3d(face->vertex(1) - face->vertex(0), face->vertex(2) - face->vertex(0));
    n /= n.norm();
    return (face->center() - cell->center()) * n < 0 ? -n : n;
  }

  /// Cells tile the box, side areas, partners.
  void
  check_sides(const CutMesh<3>                   &mesh,
              const std::vector<PolygonFracture> &fractures,
              const std::vector<double>          &areas)
  {
    double volume = 0;
    for (const auto &cell : mesh.triangulation.active_cell_iterators())
      volume += cell->measure();
    std::cout << "  volume relative error: " << std::abs(volume - 1) << std::endl;

    struct SideFace
    {
      Point<3>           centre;
      Tensor<1, 3>       normal;
      unsigned int       cell;
      types::boundary_id id;
    };
    std::vector<SideFace>                side_faces;
    std::map<types::boundary_id, double> side_area;
    for (const auto &cell : mesh.triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) && cell->face(f)->boundary_id() >= first_fracture_boundary_id)
          {
            side_area[cell->face(f)->boundary_id()] += cell->face(f)->measure();
            side_faces.push_back({cell->face(f)->center(),
                                  outward_normal(cell, f),
                                  cell->active_cell_index(),
                                  cell->face(f)->boundary_id()});
          }
    double worst_area = 0;
    for (unsigned int k = 0; k < fractures.size(); ++k)
      for (const Side side : {plus, minus})
        worst_area =
          std::max(worst_area,
                   std::abs(side_area[fracture_boundary_id(fractures[k].id, side)] - areas[k]) /
                     areas[k]);
    std::cout << "  max relative error of side areas: " << worst_area << std::endl;

    // Partners, found through centres sorted along x.
    std::sort(side_faces.begin(), side_faces.end(), [](const auto &a, const auto &b) {
      return a.centre[0] < b.centre[0];
    });
    unsigned int exactly_one = 0;
    for (unsigned int i = 0; i < side_faces.size(); ++i)
      {
        unsigned int partners = 0;
        const auto  &a        = side_faces[i];
        for (unsigned int j = 0; j < side_faces.size(); ++j)
          {
            const auto &b = side_faces[j];
            if (std::abs(b.centre[0] - a.centre[0]) > 1e-12)
              continue;
            partners += a.cell != b.cell && a.centre.distance(b.centre) < 1e-12 &&
                        (a.normal + b.normal).norm() < 1e-12 && (a.id ^ 1u) == b.id;
          }
        exactly_one += (partners == 1);
      }
    std::cout << "  fracture sides with exactly one partner: " << exactly_one << " of "
              << side_faces.size() << std::endl;
  }

  /// The fracture-face table against the polygons.
  void
  check_table(const CutMesh<3>                   &mesh,
              const std::vector<PolygonFracture> &fractures,
              const std::vector<TestPolygon>     &polygons)
  {
    unsigned int bad_sides = 0, bad_normals = 0, bad_frames = 0, bad_tangents = 0;
    double       worst_distance = 0;
    for (unsigned int k = 0; k < fractures.size(); ++k)
      {
        const auto   tips = tip_segments(polygons, k);
        Tensor<1, 3> t1   = fractures[k].polygon.corners[1] - fractures[k].polygon.corners[0];
        if (fractures[k].shape != "polygon")
          t1 = fractures[k].polygon.t1;
        t1 -= (t1 * polygons[k].normal) * polygons[k].normal;
        t1 /= t1.norm();
        for (const unsigned int i : mesh.faces_of_fracture.at(fractures[k].id))
          {
            const auto &f = mesh.fracture_faces[i];
            bad_sides += ((f.cell[plus]->center() - f.centre) * f.normal >= 0) ||
                         ((f.cell[minus]->center() - f.centre) * f.normal <= 0);
            bad_normals += (f.normal - polygons[k].normal).norm() > 1e-12;
            bad_frames +=
              std::abs(f.tangent.norm() - 1) > 1e-12 || std::abs(f.tangent2.norm() - 1) > 1e-12 ||
              std::abs(f.tangent * f.normal) > 1e-12 || std::abs(f.tangent2 * f.normal) > 1e-12 ||
              std::abs(f.tangent * f.tangent2) > 1e-12 ||
              (cross_product_3d(f.tangent, f.tangent2) - f.normal).norm() > 1e-12;
            bad_tangents += (f.tangent - t1).norm() > 1e-12;
            double expected = std::numeric_limits<double>::infinity();
            for (const auto &s : tips)
              expected = std::min(expected, distance_to_segment(f.centre, s[0], s[1]));
            worst_distance =
              std::max(worst_distance,
                       std::isfinite(expected) ? std::abs(expected - f.distance_to_tip) :
                                                 (std::isfinite(f.distance_to_tip) ? 1. : 0.));
          }
      }
    std::cout << "  faces with the plus cell on the wrong side: " << bad_sides
              << ", n+ not the polygon's: " << bad_normals
              << ", (t1, t2, n+) not orthonormal and right-handed: " << bad_frames
              << ", t1 not the fracture's: " << bad_tangents << std::endl
              << "  max error of the distance to the tips: " << worst_distance << std::endl;
  }

  /// Copies of each fracture vertex against the side regions, and the fracture edges.
  void
  check_copies_and_edges(const CutMesh<3>               &mesh,
                         const std::vector<TestPolygon> &polygons,
                         const Configuration            &c,
                         const Sphere                   &sphere)
  {
    std::map<unsigned int, unsigned int> n_with_copies;
    unsigned int                         wrong = 0;
    for (const auto &node : mesh.fracture_nodes)
      {
        ++n_with_copies[node.copies.size()];
        bool same_place = true;
        for (const unsigned int v : node.copies)
          same_place &= mesh.triangulation.get_vertices()[v].distance(node.location) == 0.;
        wrong += !same_place || node.copies.size() != side_regions(node.location, polygons, sphere);
      }
    std::cout << "  fracture vertices by number of copies:";
    for (const auto &[copies, n] : n_with_copies)
      std::cout << " " << copies << ": " << n;
    std::cout << "; copies differing from the side regions: " << wrong << std::endl;

    std::array<double, 3> length = {{0, 0, 0}};
    for (const auto &e : mesh.fracture_edges)
      length[static_cast<int>(e.type)] += e.length;
    auto error = [](const double value, const double truth) {
      return truth > 0 ? std::abs(value - truth) / truth : value;
    };
    std::cout << "  edge length errors: intersection "
              << error(length[static_cast<int>(EdgeType::intersection)], c.intersection_length)
              << ", tip " << error(length[static_cast<int>(EdgeType::tip)], c.tip_length)
              << ", boundary "
              << error(length[static_cast<int>(EdgeType::boundary)], c.boundary_length)
              << std::endl;
  }

  /// u = x y z + 1 [x > 1/2] + 2 [y > 1/2] + 4 [z > 1/2], interpolated cell by cell in P2: the
  /// jump u+ - u- on every face equals the jump of the indicators between the two cells.
  void
  check_p2_jump(const CutMesh<3> &mesh)
  {
    auto step = [](const Point<3> &c) {
      return 1. * (c[0] > 0.5) + 2. * (c[1] > 0.5) + 4. * (c[2] > 0.5);
    };
    FE_SimplexP<3> fe(2);
    DoFHandler<3>  dof_handler(mesh.triangulation);
    dof_handler.distribute_dofs(fe);
    Vector<double>                       u(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const Point<3> x =
              mesh.mapping().transform_unit_to_real_cell(cell, fe.get_unit_support_points()[i]);
            u[dofs[i]] = x[0] * x[1] * x[2] + step(cell->center());
          }
      }
    const QGaussSimplex<2> quadrature(3);
    FEFaceValues<3> fv(mesh.mapping(), fe, quadrature, update_values | update_quadrature_points);
    double          worst = 0;
    for (const auto &face : mesh.fracture_faces)
      {
        std::array<std::vector<double>, 2>   values;
        std::array<std::vector<Point<3>>, 2> points;
        for (const Side side : {plus, minus})
          {
            const DoFHandler<3>::active_cell_iterator cell(&mesh.triangulation,
                                                           face.cell[side]->level(),
                                                           face.cell[side]->index(),
                                                           &dof_handler);
            fv.reinit(cell, face.face_no[side]);
            values[side].resize(quadrature.size());
            fv.get_function_values(u, values[side]);
            points[side] = fv.get_quadrature_points();
          }
        const double jump = step(face.cell[plus]->center()) - step(face.cell[minus]->center());
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          for (unsigned int r = 0; r < quadrature.size(); ++r)
            if (points[plus][q].distance(points[minus][r]) < 1e-12)
              worst = std::max(worst, std::abs(values[plus][q] - values[minus][r] - jump));
      }
    std::cout << "  P2 jumps across the three planes: max |[u] - [step]| at quadrature points: "
              << worst << std::endl;
  }

  void
  check(const Configuration &c,
        const RawMesh<3>    &raw,
        const unsigned int   refinements,
        const Sphere        &sphere)
  {
    const auto mesh      = std::make_unique<CutMesh<3>>(raw);
    const auto fractures = PolygonNetwork::parse_fractures(c.fractures, "test");

    std::vector<TestPolygon> polygons;
    std::vector<double>      areas;
    for (const auto &f : fractures)
      {
        polygons.push_back(make_polygon(f.polygon.corners));
        areas.push_back(area_inside_box(f.polygon, Point<3>(0, 0, 0), Point<3>(1, 1, 1)));
      }
    std::cout << c.name << ", " << refinements << " refinements: " << mesh->fracture_faces.size()
              << " fracture faces, " << mesh->n_split_fracture_faces << " split" << std::endl;
    check_sides(*mesh, fractures, areas);
    check_table(*mesh, fractures, polygons);
    check_copies_and_edges(*mesh, polygons, c, sphere);
    if (c.check_p2_jump)
      check_p2_jump(*mesh);
  }
} // namespace

int
main()
{
  std::cout << std::scientific << std::setprecision(3);
  const std::string square_z  = "(0.2, 0.2, 0.5) (0.8, 0.2, 0.5) (0.8, 0.8, 0.5) (0.2, 0.8, 0.5)";
  const std::string square_x  = "(0.5, 0.2, 0.2) (0.5, 0.8, 0.2) (0.5, 0.8, 0.8) (0.5, 0.2, 0.8)";
  const std::string square_y  = "(0.2, 0.5, 0.2) (0.8, 0.5, 0.2) (0.8, 0.5, 0.8) (0.2, 0.5, 0.8)";
  const double      dodecagon = 12 * 2 * 0.3 * std::sin(M_PI / 12);
  const std::vector<Configuration> configurations = {
    {"tips all round",
     "1: (0.3, 0.3, 0.5) (0.7, 0.3, 0.5) (0.7, 0.7, 0.5) (0.3, 0.7, 0.5)",
     0.1,
     0,
     1.6,
     0,
     false},
    {"X line", "1: " + square_z + "; 2: " + square_x, 0.1, 0.6, 4.8, 0, false},
    {"T line",
     "1: " + square_z + "; 2: (0.5, 0.3, 0.5) (0.5, 0.7, 0.5) (0.5, 0.7, 0.8) (0.5, 0.3, 0.8)",
     0.1,
     0.4,
     3.4,
     0,
     false},
    {"three meet at a point",
     "1: " + square_z + "; 2: " + square_x + "; 3: " + square_y,
     0.1,
     1.8,
     7.2,
     0,
     false},
    {"cuts the boundary",
     "1: (-0.4, 0.3, 0.5) (0.6, 0.3, 0.5) (0.6, 0.7, 0.5) (-0.4, 0.7, 0.5)",
     0.1,
     0,
     1.6,
     0.4,
     false},
    {"a fracture of one face (split at its centre before the cut)",
     "1: (0.4, 0.4, 0.5) (0.6, 0.4, 0.5) (0.5, 0.55, 0.5)",
     0.4,
     0,
     0.2 + 2 * std::sqrt(0.0325),
     0,
     false},
    {"disc",
     "1: disc centre (0.5, 0.5, 0.5) normal (1, 1, 1) radius 0.3 sides 12",
     0.1,
     0,
     dodecagon,
     0,
     false},
    {"plane through the box",
     "1: (-0.5, -0.5, 0.3) (1.5, -0.5, 0.7) (1.5, 1.5, 0.7) (-0.5, 1.5, 0.3)",
     0.15,
     0,
     0,
     2 + 2 * std::sqrt(1.04),
     false},
    {"three planes through the box",
     "1: (-0.1, -0.1, 0.5) (1.1, -0.1, 0.5) (1.1, 1.1, 0.5) (-0.1, 1.1, 0.5); "
     "2: (0.5, -0.1, -0.1) (0.5, 1.1, -0.1) (0.5, 1.1, 1.1) (0.5, -0.1, 1.1); "
     "3: (-0.1, 0.5, -0.1) (1.1, 0.5, -0.1) (1.1, 0.5, 1.1) (-0.1, 0.5, 1.1)",
     0.2,
     3,
     0,
     12,
     true}};
  const Sphere sphere;
  for (const auto &c : configurations)
    {
      // gmsh once; refinement as make_cut_mesh does it (Bey, before the cut).
      GeometryParameters prm;
      prm.domain              = "box";
      prm.box                 = "(0, 0, 0) (1, 1, 1)";
      prm.fractures           = c.fractures;
      prm.mesh_size           = 0.25;
      prm.fracture_mesh_size  = c.fracture_mesh_size;
      prm.transition_distance = 0.2;
      RawMesh<3> raw          = mesh_polygon_network(polygon_network_from_parameters(prm), prm);
      for (const unsigned int r : {0u, 1u})
        {
          if (r > 0)
            raw.refine_uniformly();
          check(c, raw, r, sphere);
        }
    }
}
