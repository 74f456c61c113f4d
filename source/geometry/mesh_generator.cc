// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/mesh_generator.h>
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
    namespace
    {
      /// Initializes gmsh for the lifetime of the object, quietly.
      struct GmshSession
      {
        GmshSession()
        {
          gmsh::initialize(0, nullptr, false);
          gmsh::option::setNumber("General.Terminal", 0);
          gmsh::option::setNumber("General.Verbosity", 1);
        }
        ~GmshSession()
        {
          gmsh::finalize();
        }
      };

      /// Reads the current gmsh model's mesh into a RawMesh (see read_gmsh_file for the rules).
      template <int dim>
      RawMesh<dim>
      extract_mesh(const std::string &parameter)
      {
        const int cell_type = (dim == 2) ? 2 : 4; // 3-node triangle, 4-node tetrahedron
        const int face_type = (dim == 2) ? 1 : 2; // 2-node line, 3-node triangle

        RawMesh<dim>             raw;
        std::vector<std::size_t> node_tags;
        std::vector<double>      coords, parametric;
        gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, true, false);
        std::map<std::size_t, unsigned int> index_of_tag;
        // gmsh node tags need not be contiguous: map them to our vertex indices on first use.
        std::map<std::size_t, std::size_t> position;
        for (std::size_t i = 0; i < node_tags.size(); ++i)
          position[node_tags[i]] = i;
        auto vertex = [&](const std::size_t tag) {
          const auto it = index_of_tag.find(tag);
          if (it != index_of_tag.end())
            return it->second;
          const std::size_t pos = position.at(tag);
          Point<dim>        p;
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = coords[3 * pos + d];
          raw.vertices.push_back(p);
          return index_of_tag[tag] = raw.vertices.size() - 1;
        };

        // Material ids from full-dimensional physical groups (0 without any).
        std::map<int, types::material_id> material_of_entity;
        gmsh::vectorpair                  groups;
        gmsh::model::getPhysicalGroups(groups, dim);
        for (const auto &[d, tag] : groups)
          {
            std::vector<int> entities;
            gmsh::model::getEntitiesForPhysicalGroup(d, tag, entities);
            for (const int e : entities)
              material_of_entity[e] = tag;
          }
        gmsh::vectorpair entities;
        gmsh::model::getEntities(entities, dim);
        for (const auto &[d, entity] : entities)
          {
            std::vector<std::size_t> element_tags, element_nodes;
            gmsh::model::mesh::getElementsByType(cell_type, element_tags, element_nodes, entity);
            const auto material = material_of_entity.count(entity) ? material_of_entity[entity] : 0;
            for (std::size_t e = 0; e < element_tags.size(); ++e)
              {
                std::array<unsigned int, dim + 1> cell;
                for (unsigned int i = 0; i < dim + 1; ++i)
                  cell[i] = vertex(element_nodes[(dim + 1) * e + i]);
                raw.cells.push_back(cell);
                raw.cell_material.push_back(material);
              }
          }
        POROFRAC_CHECK_INPUT(!raw.cells.empty(),
                             InputError(parameter,
                                        std::string("the mesh has no ") +
                                          (dim == 2 ? "triangles" : "tetrahedra")));

        // Codimension-one physical groups: fractures and boundary parts.
        groups.clear();
        gmsh::model::getPhysicalGroups(groups, dim - 1);
        for (const auto &[d, tag] : groups)
          {
            std::string name;
            gmsh::model::getPhysicalName(d, tag, name);
            std::smatch match;
            const bool  is_fracture =
              std::regex_match(name, match, std::regex("\\s*fracture[ _:]*([0-9]+)\\s*"));
            std::vector<int> group_entities;
            gmsh::model::getEntitiesForPhysicalGroup(d, tag, group_entities);
            for (const int entity : group_entities)
              {
                std::vector<std::size_t> element_tags, element_nodes;
                gmsh::model::mesh::getElementsByType(face_type,
                                                     element_tags,
                                                     element_nodes,
                                                     entity);
                for (std::size_t e = 0; e < element_tags.size(); ++e)
                  {
                    typename RawMesh<dim>::TaggedFace face;
                    for (unsigned int i = 0; i < dim; ++i)
                      face.vertices[i] = vertex(element_nodes[dim * e + i]);
                    if (is_fracture)
                      {
                        face.tag = std::stoul(match[1]);
                        raw.fracture_faces.push_back(face);
                      }
                    else
                      {
                        POROFRAC_CHECK_INPUT(tag >= 0 && tag < 1000,
                                             InputError(parameter,
                                                        "physical group " + std::to_string(tag) +
                                                          " ('" + name +
                                                          "'): boundary ids must be in [0, 999]"));
                        face.tag = tag;
                        raw.boundary_faces.push_back(face);
                      }
                  }
              }
          }
        return raw;
      }
    } // namespace



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
      GmshSession       session;
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
          gmsh::model::mesh::field::setNumber(threshold, "LcMin", prm.fracture_mesh_size);
          gmsh::model::mesh::field::setNumber(threshold, "LcMax", prm.mesh_size);
          gmsh::model::mesh::field::setNumber(threshold, "DistMin", 0.);
          gmsh::model::mesh::field::setNumber(threshold,
                                              "DistMax",
                                              prm.transition_distance > 0 ?
                                                prm.transition_distance :
                                                5 * prm.mesh_size);
          fields.push_back(threshold);
        }
      {
        std::stringstream regions(prm.refinement_regions);
        std::string       item;
        while (std::getline(regions, item, ';'))
          {
            item = trim(item);
            if (item.empty())
              continue;
            const auto colon = item.rfind(':');
            check_input(colon != std::string::npos,
                        "Geometry/Refinement regions",
                        "write each region as '(x0, y0) (x1, y1): h'");
            const auto corners =
              FractureNetwork::parse_points(item.substr(0, colon), "Geometry/Refinement regions");
            check_input(corners.size() == 2,
                        "Geometry/Refinement regions",
                        "each region needs two corners");
            double h = 0;
            try
              {
                h = std::stod(item.substr(colon + 1));
              }
            catch (...)
              {
              }
            check_input(h > 0,
                        "Geometry/Refinement regions",
                        "cell size '" + trim(item.substr(colon + 1)) +
                          "' must be a positive number");
            const int box = gmsh::model::mesh::field::add("Box");
            gmsh::model::mesh::field::setNumber(box, "VIn", h);
            gmsh::model::mesh::field::setNumber(box, "VOut", prm.mesh_size);
            gmsh::model::mesh::field::setNumber(box,
                                                "XMin",
                                                std::min(corners[0][0], corners[1][0]));
            gmsh::model::mesh::field::setNumber(box,
                                                "XMax",
                                                std::max(corners[0][0], corners[1][0]));
            gmsh::model::mesh::field::setNumber(box,
                                                "YMin",
                                                std::min(corners[0][1], corners[1][1]));
            gmsh::model::mesh::field::setNumber(box,
                                                "YMax",
                                                std::max(corners[0][1], corners[1][1]));
            fields.push_back(box);
          }
      }
      if (!prm.size_expression.empty())
        {
          const int expression = gmsh::model::mesh::field::add("MathEval");
          gmsh::model::mesh::field::setString(expression, "F", prm.size_expression);
          fields.push_back(expression);
        }
      {
        const int          constant = gmsh::model::mesh::field::add("MathEval");
        std::ostringstream h;
        h.precision(17);
        h << prm.mesh_size;
        gmsh::model::mesh::field::setString(constant, "F", h.str());
        fields.push_back(constant);
      }
      const int minimum = gmsh::model::mesh::field::add("Min");
      gmsh::model::mesh::field::setNumbers(minimum, "FieldsList", fields);
      gmsh::model::mesh::field::setAsBackgroundMesh(minimum);
      gmsh::option::setNumber("Mesh.CharacteristicLengthExtendFromBoundary", 0);
      gmsh::option::setNumber("Mesh.CharacteristicLengthFromPoints", 0);
      gmsh::option::setNumber("Mesh.CharacteristicLengthFromCurvature", 0);
      gmsh::option::setNumber("Mesh.Algorithm", prm.algorithm == "delaunay" ? 5 : 6);
      gmsh::model::mesh::generate(2);

      RawMesh<2> raw = extract_mesh<2>("Geometry");
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
      try
        {
          gmsh::open(filename);
          if (is_geo)
            gmsh::model::mesh::generate(dim);
        }
      catch (...)
        {
          throw InputError(parameter,
                           "gmsh could not read '" +
                             std::filesystem::path(filename).filename().string() + "'");
        }
      return extract_mesh<dim>(parameter);
    }



    template <int dim>
    std::unique_ptr<CutMesh<dim>>
    make_cut_mesh(const GeometryParameters &prm)
    {
      RawMesh<dim> raw;
      check_input(prm.domain == "mesh file" || prm.mesh_size > 0,
                  "Geometry/Mesh size",
                  "must be positive");
      check_input(prm.domain == "mesh file" || prm.fracture_mesh_size > 0,
                  "Geometry/Fracture mesh size",
                  "must be positive");
      if (prm.domain == "mesh file")
        raw = read_gmsh_file<dim>(prm.mesh_file, "Geometry/Mesh file");
      else
        {
          if constexpr (dim == 2)
            raw = mesh_network(network_from_parameters(prm), prm);
          else
            throw InputError("Geometry/Domain",
                             "3D domains must be given as a gmsh mesh file (Domain = mesh file)");
        }
      for (unsigned int r = 0; r < prm.global_refinements; ++r)
        raw.refine_uniformly();
      if (prm.delaunay_flips)
        raw.make_delaunay();
      return std::make_unique<CutMesh<dim>>(raw);
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
