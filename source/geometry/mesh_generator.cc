// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/boundary_entries.h>
#include <porofrac/geometry/fracture_band.h>
#include <porofrac/geometry/gmsh_model.h>
#include <porofrac/geometry/gmsh_session.h>
#include <porofrac/geometry/mesh_generator.h>
#include <porofrac/geometry/planar_graph_checks.h>
#include <porofrac/geometry/polygon_mesher.h>
#include <porofrac/geometry/size_guard.h>
#include <porofrac/geometry/structured_mesh.h>
#include <porofrac/io/expression.h>
#include <porofrac/io/text.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <gmsh.h>

namespace porofrac
{
  namespace geometry
  {
    using io::trim;



    FractureNetwork
    network_from_parameters(const GeometryParameters &prm)
    {
      FractureNetwork network;
      if (prm.domain == "box")
        {
          const auto corners = FractureNetwork::parse_points(prm.box, "Geometry/Box");
          check_input(corners.size() == 2, "Geometry/Box", "needs exactly two corners");
          const Point<2> lo = corners[0], hi = corners[1];
          check_input(hi[0] > lo[0] && hi[1] > lo[1],
                      "Geometry/Box",
                      "the second corner must lie above and to the right of the first");
          network.domain.corners  = {lo, Point<2>(hi[0], lo[1]), hi, Point<2>(lo[0], hi[1])};
          network.domain.edge_ids = {2, 1, 3, 0};
        }
      else
        {
          network.domain.corners = FractureNetwork::parse_points(prm.polygon, "Geometry/Polygon");
          check_input(network.domain.corners.size() >= 3,
                      "Geometry/Polygon",
                      "needs at least three corners");
          double      area = 0;
          const auto &c    = network.domain.corners;
          for (unsigned int i = 0; i < c.size(); ++i)
            area += c[i][0] * c[(i + 1) % c.size()][1] - c[(i + 1) % c.size()][0] * c[i][1];
          check_input(area > 0,
                      "Geometry/Polygon",
                      "corners must be listed counter-clockwise and enclose a positive area");
          std::stringstream ids(prm.polygon_ids);
          std::string       item;
          while (std::getline(ids, item, ','))
            if (!trim(item).empty())
              network.domain.edge_ids.push_back(std::stoul(trim(item)));
          if (network.domain.edge_ids.empty())
            for (unsigned int i = 0; i < c.size(); ++i)
              network.domain.edge_ids.push_back(i);
          check_input(network.domain.edge_ids.size() == c.size(),
                      "Geometry/Polygon boundary ids",
                      "needs one id per polygon edge (" + std::to_string(c.size()) + ")");
        }
      network.fractures = FractureNetwork::parse_fractures(prm.fractures, "Geometry/Fractures");
      network.validate("Geometry/Fractures");
      return network;
    }



    RawMesh<2>
    mesh_network(const FractureNetwork &network, const GeometryParameters &prm)
    {
      const PlanarGraph graph = network.planar_graph();
      check_near_degenerate(graph, 1e-3 * prm.fracture_mesh_size, 1., "Geometry/Fractures");
      GmshSession session;
      gmsh::model::add("porofrac");

      std::vector<int> point_tags;
      for (const auto &p : graph.points)
        point_tags.push_back(gmsh::model::geo::addPoint(p[0], p[1], 0., prm.mesh_size));
      std::vector<int>                         loop;
      std::map<unsigned int, std::vector<int>> boundary_lines, fracture_lines;
      for (const auto &s : graph.boundary)
        {
          loop.push_back(gmsh::model::geo::addLine(point_tags[s.a], point_tags[s.b]));
          boundary_lines[s.tag].push_back(loop.back());
        }
      const int surface = gmsh::model::geo::addPlaneSurface({gmsh::model::geo::addCurveLoop(loop)});
      std::vector<int> all_fracture_lines;
      for (const auto &s : graph.fractures)
        {
          const int line = gmsh::model::geo::addLine(point_tags[s.a], point_tags[s.b]);
          fracture_lines[s.tag].push_back(line);
          all_fracture_lines.push_back(line);
          const double length = graph.points[s.a].distance(graph.points[s.b]);
          const int    faces  = std::max(1, int(std::lround(length / prm.fracture_mesh_size)));
          gmsh::model::geo::mesh::setTransfiniteCurve(line, faces + 1);
        }
      gmsh::model::geo::synchronize();
      if (!all_fracture_lines.empty())
        gmsh::model::mesh::embed(1, all_fracture_lines, 2, surface);
      for (const auto &[id, lines] : boundary_lines)
        gmsh::model::setPhysicalName(1,
                                     gmsh::model::addPhysicalGroup(1, lines, id),
                                     "boundary " + std::to_string(id));
      for (const auto &[id, lines] : fracture_lines)
        gmsh::model::setPhysicalName(1,
                                     gmsh::model::addPhysicalGroup(1, lines, 100000 + id),
                                     "fracture " + std::to_string(id));
      gmsh::model::addPhysicalGroup(2, {surface}, 0);

      // Size fields: graded away from the fractures, refinement boxes, a user expression.
      std::vector<double> fields;
      if (!all_fracture_lines.empty())
        {
          const int distance = gmsh::model::mesh::field::add("Distance");
          gmsh::model::mesh::field::setNumbers(distance,
                                               "EdgesList",
                                               std::vector<double>(all_fracture_lines.begin(),
                                                                   all_fracture_lines.end()));
          gmsh::model::mesh::field::setNumber(distance, "NNodesByEdge", 200);
          const int threshold = gmsh::model::mesh::field::add("Threshold");
          gmsh::model::mesh::field::setNumber(threshold, "IField", distance);
          const FractureBand band(prm);
          gmsh::model::mesh::field::setNumber(threshold, "LcMin", band.h_fracture);
          gmsh::model::mesh::field::setNumber(threshold, "LcMax", band.h_far);
          gmsh::model::mesh::field::setNumber(threshold, "DistMin", 0.);
          gmsh::model::mesh::field::setNumber(threshold, "DistMax", band.transition);
          fields.push_back(threshold);
        }
      set_background_size(prm, 2, fields);
      gmsh::option::setNumber("Mesh.Algorithm", prm.algorithm == "delaunay" ? 5 : 6);
      generate_mesh(session, prm, 2);

      RawMesh<2> raw = extract_gmsh_mesh<2>("Geometry");
      for (const auto &f : network.fractures)
        raw.fracture_start[f.id] = f.points.front();
      return raw;
    }



    template <int dim>
    RawMesh<dim>
    read_gmsh_file(const std::string &filename, const std::string &parameter)
    {
      check_input(!filename.empty(), parameter, "no mesh file given");
      check_input(std::ifstream(filename).good(),
                  parameter,
                  "cannot open mesh file '" + std::filesystem::path(filename).filename().string() +
                    "'");
      const bool is_geo = filename.size() > 4 && filename.substr(filename.size() - 4) == ".geo";
      const bool is_msh = filename.size() > 4 && filename.substr(filename.size() - 4) == ".msh";
      check_input(is_geo || is_msh,
                  parameter,
                  "mesh file '" + filename + "' must end in .geo or .msh");
      GmshSession session;
      session.run(parameter,
                  "gmsh could not read '" + std::filesystem::path(filename).filename().string() +
                    "'",
                  [&] {
                    gmsh::open(filename);
                    if (is_geo)
                      gmsh::model::mesh::generate(dim);
                  });
      return extract_gmsh_mesh<dim>(parameter);
    }



    /// Geometry/Boundary regions: each outer face whose centroid satisfies a region's condition,
    /// and no earlier one's, gets the region's id.
    template <int dim>
    void
    apply_boundary_regions(const std::string &text, RawMesh<dim> &raw)
    {
      const std::string               parameter = "Geometry/Boundary regions";
      std::vector<bool>               taken(raw.boundary_faces.size(), false);
      std::vector<types::boundary_id> ids(raw.boundary_faces.size());
      for (const auto &[id, condition_text] :
           split_boundary_entries(text, parameter, "id: condition"))
        {
          const auto   condition = io::parse_expressions<dim>({condition_text}, parameter);
          unsigned int n_faces   = 0;
          for (unsigned int f = 0; f < raw.boundary_faces.size(); ++f)
            {
              Point<dim> centroid;
              for (const unsigned int v : raw.boundary_faces[f].vertices)
                centroid += raw.vertices[v] / double(dim);
              if (!taken[f] && condition->value(centroid) != 0)
                {
                  taken[f] = true;
                  ids[f]   = id;
                  ++n_faces;
                }
            }
          check_input(n_faces > 0,
                      parameter,
                      "no outer boundary face has its centroid in region " + std::to_string(id) +
                        " ('" + condition_text + "')");
        }
      for (unsigned int f = 0; f < raw.boundary_faces.size(); ++f)
        if (taken[f])
          raw.boundary_faces[f].tag = ids[f];
    }



    template <int dim>
    std::unique_ptr<CutMesh<dim>>
    make_cut_mesh(const GeometryParameters &prm)
    {
      Timer        timer;
      MeshBuildLog log;
      RawMesh<dim> raw;
      check_input(prm.domain == "mesh file" || prm.mesh_size > 0,
                  "Geometry/Mesh size",
                  "must be positive");
      check_input(prm.domain == "mesh file" || prm.fracture_mesh_size > 0,
                  "Geometry/Fracture mesh size",
                  "must be positive");
      check_input(dim == 2 || !prm.delaunay_flips,
                  "Geometry/Delaunay flips",
                  "Delaunay flips are implemented in 2D only");
      check_input(dim == 3 || prm.structured_cells.empty(),
                  "Geometry/Structured cells",
                  "structured meshes are implemented for 3D boxes only");
      check_input(dim == 3 || prm.random_discs.count == 0,
                  "Geometry/Random discs/Count",
                  "random discs are 3D fractures");
      if (prm.domain == "mesh file")
        raw = read_gmsh_file<dim>(prm.mesh_file, "Geometry/Mesh file");
      else if constexpr (dim == 2)
        {
          const FractureNetwork network  = network_from_parameters(prm);
          const auto            estimate = estimate_cells(network, prm);
          check_cell_count(estimate.cells, prm, estimate.parameter, "about");
          raw = mesh_network(network, prm);
        }
      else
        {
          const PolygonNetwork network = polygon_network_from_parameters(prm, &log.random_discs);
          if (!prm.structured_cells.empty())
            {
              const std::string parameter = "Geometry/Structured cells";
              check_input(prm.domain == "box", parameter, "needs Domain = box");
              const auto cells = parse_structured_cells(prm.structured_cells, parameter);
              check_cell_count(6. * cells[0] * cells[1] * cells[2], prm, parameter, "exactly");
              raw = structured_box_mesh(network, cells, parameter);
            }
          else
            {
              const auto estimate = estimate_cells(network, prm);
              check_cell_count(estimate.cells, prm, estimate.parameter, "about");
              raw = mesh_polygon_network(network, prm);
            }
        }
      log.add("gmsh", timer);
      check_cell_count(raw.cells.size() * std::pow(2., dim * prm.global_refinements),
                       prm,
                       "Geometry/Global refinements",
                       "exactly");
      for (unsigned int r = 0; r < prm.global_refinements; ++r)
        raw.refine_uniformly();
      if (prm.delaunay_flips)
        raw.make_delaunay();
      apply_boundary_regions(prm.boundary_regions, raw);
      log.add("refinement", timer);
      auto mesh = std::make_unique<CutMesh<dim>>(raw);
      mesh->build_log.phases.insert(mesh->build_log.phases.begin(),
                                    log.phases.begin(),
                                    log.phases.end());
      mesh->build_log.random_discs = log.random_discs;
      return mesh;
    }



    template RawMesh<2>
    read_gmsh_file<2>(const std::string &, const std::string &);
    template RawMesh<3>
    read_gmsh_file<3>(const std::string &, const std::string &);
    template std::unique_ptr<CutMesh<2>>
    make_cut_mesh<2>(const GeometryParameters &);
    template std::unique_ptr<CutMesh<3>>
    make_cut_mesh<3>(const GeometryParameters &);
  } // namespace geometry
} // namespace porofrac
