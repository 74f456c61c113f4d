// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/mesh_output.h>
#include <porofrac/geometry/mesh_quality.h>
#include <porofrac/geometry/simplex_tools.h>
#include <porofrac/io/output_file.h>
#include <porofrac/io/vtk_grid.h>

#include <filesystem>
#include <numeric>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      /**
       * Writes unconnected simplices (@p n_corners consecutive @p points each, VTK cell type
       * @p vtk_type) with per-cell @p fields to @p filename as "vtk" (legacy) or "vtu" (XML),
       * both ASCII.
       */
      template <int dim>
      void
      write_simplices(const std::string             &filename,
                      const std::string             &format,
                      const std::vector<Point<dim>> &points,
                      const unsigned int             n_corners,
                      const std::uint8_t             vtk_type,
                      const FractureFields          &fields)
      {
        io::VtkGrid               grid;
        std::vector<std::int32_t> corners;
        for (const auto &p : points)
          {
            corners.push_back(grid.add_point(p[0], p[1], dim == 3 ? p[dim - 1] : 0.));
            if (corners.size() == n_corners)
              {
                grid.add_cell(vtk_type, corners);
                corners.clear();
              }
          }
        grid.cell_data = fields;
        io::write_vtk_grid(grid, filename, format, io::VtuEncoding::ascii);
      }



      /// VTK's vertex order of a linear cell as deal.II's vertex indices: the same for
      /// simplices, counter-clockwise instead of lexicographic for quadrilaterals and hexahedra.
      std::vector<unsigned int>
      vtk_vertex_order(const ReferenceCell &cell)
      {
        if (cell == ReferenceCells::Quadrilateral)
          return {0, 1, 3, 2};
        if (cell == ReferenceCells::Hexahedron)
          return {0, 1, 3, 2, 4, 5, 7, 6};
        AssertThrow(cell.is_simplex(),
                    ExcMessage("field output supports simplices, quadrilaterals and hexahedra"));
        std::vector<unsigned int> order(cell.n_vertices());
        std::iota(order.begin(), order.end(), 0U);
        return order;
      }



      /**
       * The cells of @p triangulation this process writes (@p pieces), with the mesh vertices
       * they use as shared points and @p fields (plus "subdomain" when the file is split) as
       * cell data.
       */
      template <int dim>
      io::VtkGrid
      cell_field_grid(const Triangulation<dim> &triangulation,
                      const std::string        &format,
                      const CellFields         &fields,
                      const OutputPieces       &pieces)
      {
        io::VtkGrid grid;
        grid.cell_data.reserve(fields.size() + 1);
        for (const auto &field : fields)
          grid.cell_data.emplace_back(field.first, std::vector<double>());
        if (pieces.split(format))
          grid.cell_data.emplace_back("subdomain", std::vector<double>());
        const auto               &vertices = triangulation.get_vertices();
        std::vector<std::int32_t> point_of_vertex(vertices.size(), -1);
        std::vector<std::int32_t> corners;
        ReferenceCell             kind = ReferenceCells::Invalid;
        std::vector<unsigned int> order;
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            const unsigned int c = cell->active_cell_index();
            if (!cell->is_locally_owned() || !pieces.writes(c, format))
              continue;
            if (cell->reference_cell() != kind)
              {
                kind  = cell->reference_cell();
                order = vtk_vertex_order(kind);
              }
            corners.clear();
            for (const unsigned int v : order)
              {
                std::int32_t &point = point_of_vertex[cell->vertex_index(v)];
                if (point < 0)
                  {
                    const Point<dim> &x = vertices[cell->vertex_index(v)];
                    point = grid.add_point(x[0], dim > 1 ? x[1] : 0., dim > 2 ? x[2] : 0.);
                  }
                corners.push_back(point);
              }
            grid.add_cell(kind.vtk_linear_type(), corners);
            for (unsigned int f = 0; f < fields.size(); ++f)
              grid.cell_data[f].second.push_back(fields[f].second[c]);
            if (pieces.split(format))
              grid.cell_data.back().second.push_back(pieces.rank);
          }
        return grid;
      }

      /// The file name of process @p rank's piece of the field file @p name.
      std::string
      piece_name(const std::string &name, const unsigned int rank, const std::string &format)
      {
        return name + "_" + Utilities::int_to_string(rank, 4) + "." + format;
      }

      /// The file names of every process's piece of the field file @p basename, as a .pvtu
      /// record next to them lists them.
      std::vector<std::string>
      piece_names(const std::string &basename, const unsigned int n_ranks)
      {
        const std::string        name = std::filesystem::path(basename).filename().string();
        std::vector<std::string> files;
        for (unsigned int r = 0; r < n_ranks; ++r)
          files.push_back(piece_name(name, r, "vtu"));
        return files;
      }
    } // namespace



    template <int dim>
    void
    write_fracture_cells(const CutMesh<dim>   &mesh,
                         const std::string    &filename,
                         const std::string    &format,
                         const FractureFields &extra)
    {
      const auto             &faces  = mesh.fracture_faces;
      FractureFields          fields = {{"fracture_id", {}},
                                        {"face_id", {}},
                                        {"abscissa", {}},
                                        {"distance_to_tip", {}}};
      std::vector<Point<dim>> points;
      for (const auto &f : faces)
        {
          fields[0].second.push_back(f.fracture_id);
          fields[1].second.push_back(f.index);
          fields[2].second.push_back(f.abscissa);
          fields[3].second.push_back(std::isfinite(f.distance_to_tip) ? f.distance_to_tip : -1.);
          for (const unsigned int n : f.nodes)
            points.push_back(mesh.fracture_nodes[n].location);
        }
      for (const auto &e : extra)
        {
          AssertThrow(e.second.size() == faces.size(),
                      ExcMessage("fracture field '" + e.first + "' has the wrong size"));
          fields.push_back(e);
        }
      // VTK_LINE, VTK_TRIANGLE; faces are written unconnected.
      write_simplices<dim>(filename, format, points, dim, (dim == 2) ? 3 : 5, fields);
    }



    template <int dim>
    void
    write_fracture_edges(const CutMesh<dim> &mesh,
                         const std::string  &filename,
                         const std::string  &format)
    {
      FractureFields          fields = {{"edge_type", {}},
                                        {"n_faces", {}},
                                        {"fracture_id_min", {}},
                                        {"fracture_id_max", {}}};
      std::vector<Point<dim>> points;
      for (const auto &e : mesh.fracture_edges)
        {
          fields[0].second.push_back(static_cast<int>(e.type));
          fields[1].second.push_back(e.faces.size());
          fields[2].second.push_back(e.fracture_ids.front());
          fields[3].second.push_back(e.fracture_ids.back());
          for (const unsigned int n : e.nodes)
            points.push_back(mesh.fracture_nodes[n].location);
        }
      write_simplices<dim>(filename, format, points, 2, 3, fields);
    }



    template <int dim>
    std::string
    write_cell_fields(const CutMesh<dim> &mesh,
                      const std::string  &basename,
                      const std::string  &format,
                      const CellFields   &fields,
                      const OutputPieces &pieces)
    {
      if (format == "none")
        return "";
      for (const auto &[name, values] : fields)
        AssertThrow(values.size() == mesh.triangulation.n_active_cells(),
                    ExcMessage("cell field '" + name + "' has the wrong size"));
      const io::VtkGrid grid = cell_field_grid(mesh.triangulation, format, fields, pieces);
      const auto        encoding =
        (format == "vtu") ? io::VtuEncoding::compressed : io::VtuEncoding::ascii;
      const std::string name = std::filesystem::path(basename).filename().string();
      if (!pieces.split(format))
        {
          if (pieces.rank == 0)
            io::write_vtk_grid(grid, basename + "." + format, format, encoding);
          return name + "." + format;
        }
      io::write_vtk_grid(grid, piece_name(basename, pieces.rank, format), format, encoding);
      if (format != "vtu")
        return "";
      if (pieces.rank == 0)
        {
          std::vector<std::string> names;
          for (const auto &field : grid.cell_data)
            names.push_back(field.first);
          io::write_pvtu_record(basename + ".pvtu", piece_names(basename, pieces.n_ranks), names);
        }
      return name + ".pvtu";
    }



    OutputPieces
    replicated_mesh_pieces(const std::vector<unsigned int> &cell_owner, const MPI_Comm communicator)
    {
      OutputPieces pieces;
      pieces.rank    = Utilities::MPI::this_mpi_process(communicator);
      pieces.n_ranks = Utilities::MPI::n_mpi_processes(communicator);
      if (pieces.n_ranks > 1)
        pieces.cell_owner = cell_owner;
      return pieces;
    }



    template <int dim>
    std::string
    write_field_file(DataOut<dim>             &data_out,
                     const Triangulation<dim> &triangulation,
                     const Mapping<dim>       &mapping,
                     const unsigned int        n_subdivisions,
                     const std::string        &basename,
                     const std::string        &format,
                     const OutputPieces       &pieces)
    {
      const std::string name = std::filesystem::path(basename).filename().string();
      if (!pieces.split(format))
        {
          if (pieces.rank == 0)
            {
              data_out.build_patches(mapping, n_subdivisions);
              write_data_out(data_out, basename + "." + format, format);
            }
          return name + "." + format;
        }
      Vector<float> subdomain(triangulation.n_active_cells());
      if (pieces.own_cells_only)
        subdomain = static_cast<float>(pieces.rank);
      else
        {
          const auto        &owner = pieces.cell_owner;
          const unsigned int rank  = pieces.rank;
          AssertThrow(owner.size() == triangulation.n_active_cells(),
                      ExcMessage("the cell owners do not fit the mesh"));
          for (unsigned int c = 0; c < owner.size(); ++c)
            subdomain[c] = static_cast<float>(owner[c]);
          data_out.set_cell_selection(
            [&owner, rank](const typename Triangulation<dim>::cell_iterator &cell) {
              return cell->is_active() && owner[cell->active_cell_index()] == rank;
            });
        }
      data_out.add_data_vector(subdomain, "subdomain", DataOut<dim>::type_cell_data);
      data_out.build_patches(mapping, n_subdivisions);
      write_data_out(data_out, piece_name(basename, pieces.rank, format), format);
      if (format != "vtu")
        return "";
      if (pieces.rank == 0)
        {
          io::OutputFile record(basename + ".pvtu");
          data_out.write_pvtu_record(record.stream(), piece_names(basename, pieces.n_ranks));
          record.close();
        }
      return name + ".pvtu";
    }



    template <int dim>
    void
    write_data_out(DataOut<dim> &data_out, const std::string &filename, const std::string &format)
    {
      io::OutputFile file(filename);
      std::ostream  &out = file.stream();
      if (format == "vtk")
        {
          // Legacy ASCII VTK: every digit of a double, not the stream's default 6.
          out << std::setprecision(17);
          data_out.write_vtk(out);
        }
      else
        {
          DataOutBase::VtkFlags flags;
          flags.compression_level = DataOutBase::VtkFlags::best_speed;
          data_out.set_flags(flags);
          data_out.write_vtu(out);
        }
      file.close();
    }



    template <int dim>
    void
    write_mesh(const CutMesh<dim> &mesh,
               const std::string  &basename,
               const std::string  &format,
               const OutputPieces &pieces)
    {
      if (format == "none")
        return;
      // The flags of the cells this process writes only.
      const auto    &tria = mesh.triangulation;
      Vector<double> material(tria.n_active_cells()), centre_inside(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int c = cell->active_cell_index();
          if (!pieces.writes(c, format))
            continue;
          std::array<Point<dim>, dim + 1> p;
          for (unsigned int i = 0; i < dim + 1; ++i)
            p[i] = cell->vertex(i);
          material[c]      = cell->material_id();
          centre_inside[c] = contains<dim>(p, circumcentre<dim>(p), 1e-10) ? 1 : 0;
        }
      write_cell_fields(mesh,
                        basename,
                        format,
                        {{"material_id", material}, {"circumcentre_inside", centre_inside}},
                        pieces);
      if (pieces.rank != 0)
        return;
      write_fracture_cells(mesh, basename + "_fractures." + format, format);
      if (dim == 3)
        write_fracture_edges(mesh, basename + "_fracture_edges." + format, format);
    }



    template void
    write_fracture_cells<2>(const CutMesh<2> &,
                            const std::string &,
                            const std::string &,
                            const FractureFields &);
    template void
    write_fracture_cells<3>(const CutMesh<3> &,
                            const std::string &,
                            const std::string &,
                            const FractureFields &);
    template void
    write_fracture_edges<2>(const CutMesh<2> &, const std::string &, const std::string &);
    template void
    write_fracture_edges<3>(const CutMesh<3> &, const std::string &, const std::string &);
    template std::string
    write_cell_fields<2>(const CutMesh<2> &,
                         const std::string &,
                         const std::string &,
                         const CellFields &,
                         const OutputPieces &);
    template std::string
    write_cell_fields<3>(const CutMesh<3> &,
                         const std::string &,
                         const std::string &,
                         const CellFields &,
                         const OutputPieces &);
    template std::string
    write_field_file<2>(DataOut<2> &,
                        const Triangulation<2> &,
                        const Mapping<2> &,
                        const unsigned int,
                        const std::string &,
                        const std::string &,
                        const OutputPieces &);
    template std::string
    write_field_file<3>(DataOut<3> &,
                        const Triangulation<3> &,
                        const Mapping<3> &,
                        const unsigned int,
                        const std::string &,
                        const std::string &,
                        const OutputPieces &);
    template void
    write_mesh<2>(const CutMesh<2> &,
                  const std::string &,
                  const std::string &,
                  const OutputPieces &);
    template void
    write_mesh<3>(const CutMesh<3> &,
                  const std::string &,
                  const std::string &,
                  const OutputPieces &);
    template void
    write_data_out<2>(DataOut<2> &, const std::string &, const std::string &);
    template void
    write_data_out<3>(DataOut<3> &, const std::string &, const std::string &);
  } // namespace geometry
} // namespace porofrac
