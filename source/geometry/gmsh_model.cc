// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/fracture_network.h>
#include <porofrac/geometry/gmsh_model.h>
#include <porofrac/geometry/polygon_network.h>
#include <porofrac/io/text.h>

#include <cmath>
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
      /// Corners of a refinement region, "(x0, y0) (x1, y1)" or "(x0, y0, z0) (x1, y1, z1)".
      std::pair<Point<3>, Point<3>>
      region_corners(const std::string &text, const unsigned int dim)
      {
        const std::string     parameter = "Geometry/Refinement regions";
        std::vector<Point<3>> corners;
        if (dim == 2)
          for (const auto &p : FractureNetwork::parse_points(text, parameter))
            corners.emplace_back(p[0], p[1], 0.);
        else
          corners = PolygonNetwork::parse_points(text, parameter);
        check_input(corners.size() == 2, parameter, "each region needs two corners");
        Point<3> lo, hi;
        for (unsigned int d = 0; d < 3; ++d)
          {
            lo[d] = std::min(corners[0][d], corners[1][d]);
            hi[d] = std::max(corners[0][d], corners[1][d]);
          }
        return {lo, hi};
      }

      /// The id N of a physical group named "fracture N"; ids beyond 10^6 are refused rather
      /// than truncated into another fracture's id.
      unsigned int
      fracture_id(const std::string &digits, const std::string &name, const std::string &parameter)
      {
        check_input(digits.size() <= 7 && std::stoul(digits) <= 1000000,
                    parameter,
                    "physical group '" + name + "': fracture ids must be in [0, 1000000]");
        return std::stoul(digits);
      }

      /// Curves (2D) or surfaces (3D) embedded in the domain but in no physical group named
      /// "fracture N" would silently not be fractures: refuse them.
      void
      check_embedded_entities_are_fractures(const unsigned int   dim,
                                            const std::set<int> &fracture_entities,
                                            const std::string   &parameter)
      {
        gmsh::vectorpair cells;
        gmsh::model::getEntities(cells, dim);
        for (const auto &[d, tag] : cells)
          {
            gmsh::vectorpair embedded;
            gmsh::model::mesh::getEmbedded(d, tag, embedded);
            for (const auto &[e_dim, e_tag] : embedded)
              check_input(e_dim != static_cast<int>(dim) - 1 || fracture_entities.count(e_tag),
                          parameter,
                          std::string("the ") + (dim == 2 ? "curve " : "surface ") +
                            std::to_string(e_tag) +
                            " embedded in the domain is in no physical "
                            "group named 'fracture N' (N the fracture id): name its group so, "
                            "or remove it from the mesh");
          }
      }
    } // namespace



    template <int dim>
    RawMesh<dim>
    extract_gmsh_mesh(const std::string &parameter)
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
      std::set<int> fracture_entities;
      for (const auto &[d, tag] : groups)
        {
          std::string name;
          gmsh::model::getPhysicalName(d, tag, name);
          std::smatch match;
          const bool  is_fracture =
            std::regex_match(name, match, std::regex("\\s*fracture[ _:]*([0-9]+)\\s*"));
          std::vector<int> group_entities;
          gmsh::model::getEntitiesForPhysicalGroup(d, tag, group_entities);
          if (is_fracture)
            fracture_entities.insert(group_entities.begin(), group_entities.end());
          for (const int entity : group_entities)
            {
              std::vector<std::size_t> element_tags, element_nodes;
              gmsh::model::mesh::getElementsByType(face_type, element_tags, element_nodes, entity);
              for (std::size_t e = 0; e < element_tags.size(); ++e)
                {
                  typename RawMesh<dim>::TaggedFace face;
                  for (unsigned int i = 0; i < dim; ++i)
                    face.vertices[i] = vertex(element_nodes[dim * e + i]);
                  if (is_fracture)
                    {
                      face.tag = fracture_id(match[1], name, parameter);
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
      check_embedded_entities_are_fractures(dim, fracture_entities, parameter);
      return raw;
    }


    std::vector<RefinementRegion>
    parse_refinement_regions(const std::string &text, const unsigned int dim)
    {
      std::vector<RefinementRegion> result;
      std::stringstream             regions(text);
      std::string                   item;
      while (std::getline(regions, item, ';'))
        {
          item = trim(item);
          if (item.empty())
            continue;
          const auto colon = item.rfind(':');
          check_input(colon != std::string::npos,
                      "Geometry/Refinement regions",
                      dim == 2 ? "write each region as '(x0, y0) (x1, y1): h'" :
                                 "write each region as '(x0, y0, z0) (x1, y1, z1): h'");
          const auto [lo, hi] = region_corners(item.substr(0, colon), dim);
          double h            = 0;
          try
            {
              h = std::stod(item.substr(colon + 1));
            }
          catch (...)
            {
            }
          check_input(h > 0 && std::isfinite(h),
                      "Geometry/Refinement regions",
                      "cell size '" + trim(item.substr(colon + 1)) + "' must be a positive number");
          result.push_back({lo, hi, h});
        }
      return result;
    }



    void
    set_background_size(const GeometryParameters &prm,
                        const unsigned int        dim,
                        std::vector<double>       fields)
    {
      for (const auto &[lo, hi, h] : parse_refinement_regions(prm.refinement_regions, dim))
        {
          const int box = gmsh::model::mesh::field::add("Box");
          gmsh::model::mesh::field::setNumber(box, "VIn", h);
          gmsh::model::mesh::field::setNumber(box, "VOut", prm.mesh_size);
          for (unsigned int d = 0; d < dim; ++d)
            {
              const std::string axis(1, "XYZ"[d]);
              gmsh::model::mesh::field::setNumber(box, axis + "Min", lo[d]);
              gmsh::model::mesh::field::setNumber(box, axis + "Max", hi[d]);
            }
          fields.push_back(box);
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
    }



    template RawMesh<2>
    extract_gmsh_mesh<2>(const std::string &);
    template RawMesh<3>
    extract_gmsh_mesh<3>(const std::string &);

    void
    generate_mesh(GmshSession &session, const GeometryParameters &prm, const int dim)
    {
      try
        {
          session.run("Geometry", "gmsh could not mesh the domain", [dim] {
            gmsh::model::mesh::generate(dim);
          });
        }
      catch (const InputError &e)
        {
          const bool size_field_error =
            e.reason.find("mathex") != std::string::npos ||
            e.reason.find("Wrong mesh element size") != std::string::npos;
          if (prm.size_expression.empty() || !size_field_error)
            throw;
          throw InputError("Geometry/Mesh size expression",
                           "'" + prm.size_expression +
                             "' is not a valid positive size field: " + e.reason);
        }
    }
  } // namespace geometry
} // namespace porofrac
