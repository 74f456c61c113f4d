// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/mesh_report.h>
#include <porofrac/base/config.h>
#include <porofrac/geometry/mesh_quality.h>

#include <array>
#include <cmath>
#include <iomanip>

namespace porofrac
{
  namespace app
  {
    namespace
    {
      /// Counts and lengths of the 3D fracture edges by type.
      template <int dim>
      void
      report_fracture_edges(const geometry::CutMesh<dim> &mesh, std::ostream &out, io::Json &m)
      {
        std::array<unsigned int, 3> n      = {{0, 0, 0}};
        std::array<double, 3>       length = {{0, 0, 0}};
        for (const auto &e : mesh.fracture_edges)
          {
            ++n[static_cast<int>(e.type)];
            length[static_cast<int>(e.type)] += e.length;
          }
        const int tip = 0, intersection = 1, boundary = 2;
        out << "  fracture edges: " << n[intersection] << " intersection (length "
            << length[intersection] << "), " << n[tip] << " tip (length " << length[tip] << "), "
            << n[boundary] << " on the boundary (length " << length[boundary] << ")\n";
        io::Json &e              = m["fracture_edges"];
        e["n_intersection"]      = n[intersection];
        e["intersection_length"] = length[intersection];
        e["n_tip"]               = n[tip];
        e["tip_length"]          = length[tip];
        e["n_boundary"]          = n[boundary];
        e["boundary_length"]     = length[boundary];
      }

      /// The random disc generator's counts (report and JSON) and the build phases (JSON only:
      /// timings never go into compared output).
      void
      report_build(const geometry::MeshBuildLog &log, std::ostream &out, io::Json &m)
      {
        if (log.random_discs.accepted > 0)
          {
            unsigned int total = 0;
            for (const auto &[why, n] : log.random_discs.rejected)
              total += n;
            out << "  random discs: " << log.random_discs.accepted
                << ", candidates rejected: " << total;
            io::Json &r   = m["random_discs"];
            r["accepted"] = log.random_discs.accepted;
            io::Json &why = r["rejected"];
            why           = io::Json::object();
            for (const auto &[reason, n] : log.random_discs.rejected)
              {
                out << (&reason == &log.random_discs.rejected.begin()->first ? " (" : "; ")
                    << reason << ": " << n;
                why[reason] = n;
              }
            out << (log.random_discs.rejected.empty() ? "" : ")") << "\n";
          }
        io::Json &phases = m["build_phases"];
        phases           = io::Json::array();
        for (const auto &p : log.phases)
          {
            io::Json phase          = io::Json::object();
            phase["phase"]          = p.name;
            phase["seconds"]        = p.seconds;
            phase["peak_memory_mb"] = p.peak_memory_mb;
            phase["memory_mb"]      = p.memory_mb;
            phases.push_back(phase);
          }
      }
    } // namespace



    template <int dim>
    void
    report_mesh(const geometry::CutMesh<dim> &mesh, io::RunContext &context)
    {
      const geometry::MeshQuality q         = geometry::assess_mesh(mesh);
      std::ostream               &out       = context.report;
      const auto                  flags     = out.flags();
      const auto                  precision = out.precision();
      out << std::scientific << std::setprecision(4);
      // Checks a user can trust at a glance: the cells tile the domain, and the two sides of every
      // fracture face are coincident faces of two different cells.
      double measure = 0;
      for (const auto &cell : mesh.triangulation.active_cell_iterators())
        measure += cell->measure();
      unsigned int n_matching = 0;
      for (const auto &f : mesh.fracture_faces)
        {
          const auto   plus  = f.cell[geometry::plus]->face(f.face_no[geometry::plus]);
          const auto   minus = f.cell[geometry::minus]->face(f.face_no[geometry::minus]);
          const double tol = 1e-10 * std::sqrt(f.measure) * (dim == 3 ? 1. : std::sqrt(f.measure));
          n_matching += (f.cell[geometry::plus] != f.cell[geometry::minus]) &&
                        plus->center().distance(minus->center()) <= tol &&
                        plus->center().distance(f.centre) <= tol &&
                        std::abs(plus->measure() - minus->measure()) <= 1e-12 * f.measure;
        }
      out << "Mesh:\n"
          << "  cells: " << q.n_cells << "\n"
          << "  vertices: " << q.n_vertices << " (" << mesh.n_uncut_vertices << " before cutting)\n"
          << "  fracture faces: " << q.n_fracture_faces
          << ", with coincident sides in two cells: " << n_matching << "\n"
          << "  measure of the cells: " << measure << "\n";
      if (mesh.n_split_fracture_faces > 0)
        out << "  fracture faces with all vertices on tips, split at their centre: "
            << mesh.n_split_fracture_faces << "\n";
      io::Json fractures = io::Json::array();
      for (const unsigned int id : mesh.fracture_ids)
        {
          const unsigned int n = mesh.faces_of_fracture.at(id).size();
          out << "  fracture " << id << ": " << n << " faces, measure " << mesh.fracture_measure(id)
              << "\n";
          io::Json f   = io::Json::object();
          f["id"]      = id;
          f["faces"]   = n;
          f["measure"] = mesh.fracture_measure(id);
          fractures.push_back(f);
        }
      unsigned int n_tips = 0, n_intersections = 0, n_corners = 0, n_on_boundary = 0;
      for (const auto &node : mesh.fracture_nodes)
        {
          n_tips += node.type == geometry::NodeType::tip;
          n_intersections += node.type == geometry::NodeType::intersection;
          n_corners += node.type == geometry::NodeType::corner;
          n_on_boundary += node.type == geometry::NodeType::boundary;
        }
      out << "  fracture nodes: " << n_tips << " tips, " << n_corners << " corners, "
          << n_intersections << " intersections, " << n_on_boundary << " on the boundary\n";
      if (dim == 3)
        report_fracture_edges(mesh, out, context.summary["mesh"]);
      out << std::fixed << std::setprecision(2) << "  angles (degrees): min " << q.min_angle_degrees
          << ", max " << q.max_angle_degrees << "\n";
      if (dim == 3)
        out << "  dihedral angles (degrees): min " << q.min_dihedral_degrees << ", max "
            << q.max_dihedral_degrees << "\n";
      out << std::fixed << std::setprecision(2) << "  TPFA connections: " << q.n_connections
          << ", non-orthogonal " << q.n_non_orthogonal << ", non-positive distance "
          << q.n_non_positive_distance << "\n"
          << "  circumcentres outside their cell: " << q.n_centres_outside
          << ", boundary faces with non-positive distance: " << q.n_boundary_non_positive_distance
          << "\n";
      out.flags(flags);
      out.precision(precision);

      io::Json &m                                 = context.summary["mesh"];
      m["n_cells"]                                = q.n_cells;
      m["n_vertices"]                             = q.n_vertices;
      m["n_vertices_before_cut"]                  = mesh.n_uncut_vertices;
      m["n_fracture_faces"]                       = q.n_fracture_faces;
      m["n_fracture_faces_with_coincident_sides"] = n_matching;
      m["measure"]                                = measure;
      m["n_split_fracture_faces"]                 = mesh.n_split_fracture_faces;
      io::Json &copies                            = m["fracture_vertices_by_copies"];
      copies                                      = io::Json::object();
      for (const auto &node : mesh.fracture_nodes)
        {
          io::Json &n = copies[std::to_string(node.copies.size())];
          n           = static_cast<unsigned int>(n.as_number()) + 1;
        }
      m["fractures"]                              = fractures;
      m["n_tips"]                                 = n_tips;
      m["n_corners"]                              = n_corners;
      m["n_intersections"]                        = n_intersections;
      m["n_fracture_nodes_on_boundary"]           = n_on_boundary;
      m["min_angle_degrees"]                      = q.min_angle_degrees;
      m["max_angle_degrees"]                      = q.max_angle_degrees;
      io::Json &a                                 = m["tpfa_admissibility"];
      a["n_connections"]                          = q.n_connections;
      a["n_non_orthogonal"]                       = q.n_non_orthogonal;
      a["n_non_positive_distance"]                = q.n_non_positive_distance;
      a["n_inadmissible"]                         = q.n_inadmissible();
      a["n_circumcentres_outside_cell"]           = q.n_centres_outside;
      a["n_boundary_faces_non_positive_distance"] = q.n_boundary_non_positive_distance;
      if (dim == 3)
        {
          m["min_dihedral_degrees"] = q.min_dihedral_degrees;
          m["max_dihedral_degrees"] = q.max_dihedral_degrees;
        }
      report_build(mesh.build_log, out, m);
    }



    template void
    report_mesh<2>(const geometry::CutMesh<2> &, io::RunContext &);
    template void
    report_mesh<3>(const geometry::CutMesh<3> &, io::RunContext &);
  } // namespace app
} // namespace porofrac
