// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <porofrac/geometry/distributed_cut_mesh.h>

#include <stdexcept>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    namespace
    {
      /// Throws on every rank unless the serial meshes of all ranks agree in their sizes: they
      /// are built independently and must be the same mesh.
      template <int dim>
      void
      check_same_mesh(const CutMesh<dim> &mesh, const MPI_Comm communicator)
      {
        const std::vector<double> sizes = {double(mesh.triangulation.n_active_cells()),
                                           double(mesh.triangulation.n_vertices()),
                                           double(mesh.fracture_faces.size())};
        std::vector<double>       low(3), high(3);
        Utilities::MPI::min(sizes, communicator, low);
        Utilities::MPI::max(sizes, communicator, high);
        if (low != high)
          throw std::runtime_error("the serial cut meshes of the MPI ranks differ");
      }
    } // namespace



    template <int dim>
    DistributedCutMesh<dim>::DistributedCutMesh(CutMesh<dim>  &serial_mesh,
                                                const MPI_Comm communicator)
        : serial(serial_mesh)
        , triangulation(communicator)
        , communicator(communicator)
        , rank(Utilities::MPI::this_mpi_process(communicator))
    {
      owner = partition_cells(serial_mesh, communicator);
      const auto description =
        TriangulationDescription::Utilities::create_description_from_triangulation(
          serial_mesh.triangulation, communicator);
      triangulation.create_triangulation(description);

      local_cells.assign(serial.triangulation.n_active_cells(), serial.triangulation.end());
      for (const auto &cell : triangulation.active_cell_iterators())
        if (!cell->is_artificial())
          local_cells[serial_cell(cell)->active_cell_index()] = cell;
      for (const auto &face : serial.fracture_faces)
        if (owns_face(face.index))
          owned_faces.push_back(face.index);
    }



    template <int dim>
    std::vector<unsigned int>
    partition_cells(CutMesh<dim> &serial_mesh, const MPI_Comm communicator)
    {
      check_same_mesh(serial_mesh, communicator);
      Triangulation<dim>       &tria = serial_mesh.triangulation;
      const unsigned int        n    = Utilities::MPI::n_mpi_processes(communicator);
      std::vector<unsigned int> owner(tria.n_active_cells(), 0);
      if (Utilities::MPI::this_mpi_process(communicator) == 0 && n > 1)
        {
          DynamicSparsityPattern graph;
          GridTools::get_face_connectivity_of_cells(tria, graph);
          for (const auto &face : serial_mesh.fracture_faces)
            {
              const unsigned int a = face.cell[plus]->active_cell_index();
              const unsigned int b = face.cell[minus]->active_cell_index();
              graph.add(a, b);
              graph.add(b, a);
            }
          SparsityPattern pattern;
          pattern.copy_from(graph);
          GridTools::partition_triangulation(n, pattern, tria, SparsityTools::Partitioner::metis);
          for (const auto &cell : tria.active_cell_iterators())
            owner[cell->active_cell_index()] = cell->subdomain_id();
        }
      owner = Utilities::MPI::broadcast(communicator, owner, 0);
      for (const auto &cell : tria.active_cell_iterators())
        cell->set_subdomain_id(owner[cell->active_cell_index()]);
      return owner;
    }



    template <int dim>
    typename DistributedCutMesh<dim>::cell_iterator
    DistributedCutMesh<dim>::serial_cell(const cell_iterator &local) const
    {
      return cell_iterator(serial.triangulation.create_cell_iterator(local->id()));
    }

    template std::vector<unsigned int>
    partition_cells(CutMesh<2> &, const MPI_Comm);
    template std::vector<unsigned int>
    partition_cells(CutMesh<3> &, const MPI_Comm);
    template class DistributedCutMesh<2>;
    template class DistributedCutMesh<3>;
  } // namespace geometry
} // namespace porofrac
