// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/fracture_band.h>
#include <porofrac/geometry/gmsh_model.h>
#include <porofrac/geometry/gmsh_session.h>
#include <porofrac/geometry/polygon_mesher.h>
#include <porofrac/geometry/random_discs.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <gmsh.h>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      /// One OpenCASCADE plane surface per fracture, in network order.
      gmsh::vectorpair
      add_polygons(const PolygonNetwork &network)
      {
        gmsh::vectorpair surfaces;
        for (const auto &f : network.fractures)
          {
            // Corners exactly in the plane (validation allowed a deviation of 1e-6 of the size).
            const auto      &poly = f.polygon;
            std::vector<int> points, lines;
            for (const auto &x : poly.corners)
              {
                const Point<3> y = std::abs(poly.height(x)) > 1e-12 * network.diameter() ?
                                     x - poly.height(x) * poly.normal :
                                     x;
                points.push_back(gmsh::model::occ::addPoint(y[0], y[1], y[2]));
              }
            for (unsigned int i = 0; i < points.size(); ++i)
              lines.push_back(
                gmsh::model::occ::addLine(points[i], points[(i + 1) % points.size()]));
            const int loop = gmsh::model::occ::addCurveLoop(lines);
            surfaces.emplace_back(2, gmsh::model::occ::addPlaneSurface({loop}));
          }
        return surfaces;
      }



      /// Is @p x outside the box (+1), inside it (-1), or too close to its boundary to tell (0)?
      int
      side_of_box(const Point<3> &x, const PolygonNetwork &network)
      {
        const double tol    = 1e3 * network.tolerance();
        double       margin = std::numeric_limits<double>::infinity();
        for (unsigned int d = 0; d < 3; ++d)
          margin = std::min({margin, x[d] - network.lo[d], network.hi[d] - x[d]});
        return margin < -tol ? 1 : margin > tol ? -1 : 0;
      }

      /**
       * Does the fragment surface @p tag (a piece of a fracture, entirely inside or entirely
       * outside the box) lie outside the box? Decided by points inside the piece, sampled on its
       * parametric domain; points on the box's faces (the piece's edges) do not count.
       */
      bool
      outside_box(const int tag, const PolygonNetwork &network)
      {
        std::vector<double> lo, hi;
        gmsh::model::getParametrizationBounds(2, tag, lo, hi);
        const unsigned int n = 16;
        for (unsigned int i = 1; i < n; ++i)
          for (unsigned int j = 1; j < n; ++j)
            {
              const std::vector<double> uv = {lo[0] + (hi[0] - lo[0]) * i / n,
                                              lo[1] + (hi[1] - lo[1]) * j / n};
              if (gmsh::model::isInside(2, tag, uv) <= 0)
                continue;
              std::vector<double> x;
              gmsh::model::getValue(2, tag, uv, x);
              if (const int side = side_of_box(Point<3>(x[0], x[1], x[2]), network))
                return side > 0;
            }
        double x, y, z;
        gmsh::model::occ::getCenterOfMass(2, tag, x, y, z);
        return side_of_box(Point<3>(x, y, z), network) > 0;
      }



      /**
       * Fragments the box with the fracture surfaces and drops the fracture pieces outside the
       * box. Returns the gmsh surfaces of each fracture, in network order.
       */
      std::vector<std::vector<int>>
      fragment(const PolygonNetwork &network)
      {
        const Tensor<1, 3> size = network.hi - network.lo;
        const int          box  = gmsh::model::occ::addBox(
          network.lo[0], network.lo[1], network.lo[2], size[0], size[1], size[2]);
        const gmsh::vectorpair        tools = add_polygons(network);
        gmsh::vectorpair              out;
        std::vector<gmsh::vectorpair> map;
        gmsh::model::occ::fragment({{3, box}}, tools, out, map);
        gmsh::model::occ::synchronize();

        std::vector<std::vector<int>> pieces(network.fractures.size());
        gmsh::vectorpair              outside;
        for (unsigned int k = 0; k < network.fractures.size() && k + 1 < map.size(); ++k)
          for (const auto &[dim, tag] : map[k + 1])
            if (dim == 2)
              {
                if (outside_box(tag, network))
                  outside.emplace_back(2, tag);
                else
                  pieces[k].push_back(tag);
              }
        if (!outside.empty())
          {
            gmsh::model::occ::remove(outside, true);
            gmsh::model::occ::synchronize();
          }
        return pieces;
      }



      /// Physical groups: fractures by id, box faces by boundary id, the volumes as material 0.
      void
      add_physical_groups(const PolygonNetwork                &network,
                          const std::vector<std::vector<int>> &pieces)
      {
        std::map<unsigned int, std::vector<int>> fracture_surfaces;
        std::vector<int>                         all_pieces;
        for (unsigned int k = 0; k < pieces.size(); ++k)
          {
            check_input(!pieces[k].empty(),
                        "Geometry/Fractures",
                        "fracture " + std::to_string(network.fractures[k].id) +
                          " vanished in the geometry kernel (it lies outside the domain or is "
                          "smaller than its tolerance)");
            auto &s = fracture_surfaces[network.fractures[k].id];
            s.insert(s.end(), pieces[k].begin(), pieces[k].end());
            all_pieces.insert(all_pieces.end(), pieces[k].begin(), pieces[k].end());
          }
        std::sort(all_pieces.begin(), all_pieces.end());

        std::map<int, std::vector<int>> boundary_surfaces;
        gmsh::vectorpair                surfaces;
        gmsh::model::getEntities(surfaces, 2);
        const double tol = 1e3 * network.tolerance();
        for (const auto &[dim, tag] : surfaces)
          {
            if (std::binary_search(all_pieces.begin(), all_pieces.end(), tag))
              continue;
            double c[3];
            gmsh::model::occ::getCenterOfMass(2, tag, c[0], c[1], c[2]);
            int id = -1;
            for (unsigned int d = 0; d < 3; ++d)
              for (unsigned int side = 0; side < 2; ++side)
                if (std::abs(c[d] - (side ? network.hi[d] : network.lo[d])) <= tol)
                  id = 2 * d + side;
            check_input(id >= 0,
                        "Geometry/Fractures",
                        "the geometry kernel made a surface at (" + std::to_string(c[0]) + ", " +
                          std::to_string(c[1]) + ", " + std::to_string(c[2]) +
                          ") that is neither a fracture nor on the box");
            boundary_surfaces[id].push_back(tag);
          }
        for (const auto &[id, tags] : boundary_surfaces)
          gmsh::model::setPhysicalName(2,
                                       gmsh::model::addPhysicalGroup(2, tags, id),
                                       "boundary " + std::to_string(id));
        for (const auto &[id, tags] : fracture_surfaces)
          gmsh::model::setPhysicalName(2,
                                       gmsh::model::addPhysicalGroup(2, tags, 100000 + id),
                                       "fracture " + std::to_string(id));
        gmsh::vectorpair volumes;
        gmsh::model::getEntities(volumes, 3);
        std::vector<int> volume_tags;
        for (const auto &[dim, tag] : volumes)
          volume_tags.push_back(tag);
        gmsh::model::addPhysicalGroup(3, volume_tags, 0);
      }
    } // namespace



    PolygonNetwork
    polygon_network_from_parameters(const GeometryParameters &prm, RandomDiscStatistics *statistics)
    {
      PolygonNetwork network;
      check_input(prm.domain == "box",
                  "Geometry/Domain",
                  "3D domains are a box (Domain = box) or a gmsh mesh file (Domain = mesh file)");
      const auto corners = PolygonNetwork::parse_points(prm.box, "Geometry/Box");
      check_input(corners.size() == 2,
                  "Geometry/Box",
                  "needs exactly two corners, '(x0, y0, z0) (x1, y1, z1)'");
      network.lo = corners[0];
      network.hi = corners[1];
      for (unsigned int d = 0; d < 3; ++d)
        check_input(network.hi[d] > network.lo[d],
                    "Geometry/Box",
                    "the second corner must be larger than the first in x, y and z");
      network.fractures = PolygonNetwork::parse_fractures(prm.fractures, "Geometry/Fractures");
      network.validate("Geometry/Fractures");
      if (prm.random_discs.count > 0)
        {
          const auto s = add_random_discs(prm.random_discs, network);
          if (statistics)
            *statistics = s;
        }
      return network;
    }



    RawMesh<3>
    mesh_polygon_network(const PolygonNetwork &network, const GeometryParameters &prm)
    {
      GmshSession                   session;
      std::vector<std::vector<int>> pieces;
      session.run("Geometry/Fractures", "the geometry kernel failed", [&] {
        gmsh::model::add("porofrac");
        pieces = fragment(network);
        add_physical_groups(network, pieces);
      });

      // The fracture band evaluated exactly on the polygons: gmsh's Distance field samples
      // surfaces and comes out coarser than asked on the fractures.
      const FractureBand band(prm);
      session.run("Geometry", "gmsh could not set the mesh sizes", [&] {
        gmsh::model::mesh::setSizeCallback([&](int, int, double x, double y, double z) {
          return band.size(distance_to_fractures(network, Point<3>(x, y, z), band.transition));
        });
        set_background_size(prm, 3, {});
        gmsh::option::setNumber("Mesh.Algorithm", prm.algorithm == "delaunay" ? 5 : 6);
        gmsh::option::setNumber("Mesh.Algorithm3D", 1); // Delaunay
        gmsh::option::setNumber("Mesh.Optimize", prm.mesh_optimization ? 1 : 0);
      });
      generate_mesh(session, prm, 3);

      RawMesh<3> raw = extract_gmsh_mesh<3>("Geometry");
      for (const auto &f : network.fractures)
        {
          raw.fracture_normal[f.id]  = f.polygon.normal;
          raw.fracture_tangent[f.id] = f.polygon.t1;
        }
      return raw;
    }
  } // namespace geometry
} // namespace porofrac
