// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>

#include <deal.II/numerics/data_out.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/mesh_output.h>
#include <porofrac/mechanics/coupling_entry.h>
#include <porofrac/mechanics/distributed_contact_problem.h>

#include <array>
#include <fstream>
#include <utility>

namespace porofrac
{
  namespace mechanics
  {
    template <int dim>
    DistributedContactProblem<dim>::DistributedContactProblem(
      const geometry::DistributedCutMesh<dim> &mesh,
      const ContactParameters                 &parameters,
      ConditionalOStream                      &progress,
      TimerOutput                             &timer)
        : prm(parameters)
        , system(mesh, prm, timer)
        , solver(system, friction_field, prm, progress, timer)
    {
    }



    template <int dim>
    void
    DistributedContactProblem<dim>::setup()
    {
      system.setup();
      solver.clear();
      friction_field.initialize(system.get_mesh(), prm);
      system.initial_displacement(u);
      system.reinit_multipliers(lambda);
      solved_once = false;
    }



    template <int dim>
    const ContactStatistics &
    DistributedContactProblem<dim>::solve(const bool warm_start)
    {
      const bool cold = !(warm_start && solved_once);
      solved_once     = true;
      return solver.solve(u, lambda, cold);
    }



    template <int dim>
    void
    DistributedContactProblem<dim>::replicate_state(const DoFHandler<dim> &serial_dofs,
                                                    Vector<double>        &displacement,
                                                    Vector<double>        &multipliers) const
    {
      const MPI_Comm comm = system.get_communicator();
      const bool     root = system.get_distributed_mesh().this_rank() == 0;
      displacement        = gather_displacement(root ? &serial_dofs : nullptr);
      multipliers         = gather_multipliers();
      if (!root)
        {
          displacement.reinit(serial_dofs.n_dofs());
          multipliers.reinit(dim * system.n_faces());
        }
      for (Vector<double> *v : {&displacement, &multipliers})
        {
          const int ierr = MPI_Bcast(v->begin(), v->size(), MPI_DOUBLE, 0, comm);
          AssertThrowMPI(ierr);
        }
    }



    template <int dim>
    void
    DistributedContactProblem<dim>::set_state(const DoFHandler<dim> &serial_dofs,
                                              const Vector<double>  &displacement,
                                              const Vector<double>  &multipliers)
    {
      AssertDimension(displacement.size(), serial_dofs.n_dofs());
      AssertDimension(multipliers.size(), dim * system.n_faces());
      // Every owned dof lies on an owned cell; a cell's local dof order is the same in both
      // DoFHandlers (gather_displacement).
      const auto &mesh = system.get_distributed_mesh();
      std::vector<typename DoFHandler<dim>::active_cell_iterator> serial_cells(
        serial_dofs.get_triangulation().n_active_cells());
      for (const auto &cell : serial_dofs.active_cell_iterators())
        serial_cells[cell->active_cell_index()] = cell;
      const unsigned int                   n = system.get_fe().n_dofs_per_cell();
      Vector<double>                       local(n);
      std::vector<types::global_dof_index> indices(n);
      for (const auto &cell : system.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            serial_cells[mesh.serial_cell(cell)->active_cell_index()]->get_dof_values(displacement,
                                                                                      local);
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < n; ++i)
              if (system.owned_displacements().is_element(indices[i]))
                u(indices[i]) = local[i];
          }
      for (const auto i : system.owned_multipliers())
        lambda(i) = multipliers(i);
      u.compress(VectorOperation::insert);
      lambda.compress(VectorOperation::insert);
    }



    template <int dim>
    typename DistributedContactProblem<dim>::VectorType
    DistributedContactProblem<dim>::ghosted_displacement() const
    {
      VectorType ghosted(system.owned_displacements(),
                         system.relevant_displacements(),
                         system.get_communicator());
      ghosted = u;
      return ghosted;
    }



    template <int dim>
    std::vector<ContactFaceValues<dim>>
    DistributedContactProblem<dim>::gather_face_values() const
    {
      // Per owned face: index, jump and multiplier (local frame), state, friction.
      using Row = std::pair<unsigned int, std::array<double, 2 * dim + 2>>;
      std::vector<Tensor<1, dim>> jumps, contact_jumps;
      system.face_jumps(u, jumps);
      system.contact_jumps(u, lambda, contact_jumps);
      std::vector<Row> rows;
      for (const unsigned int f : system.get_distributed_mesh().locally_owned_faces())
        {
          const Tensor<1, dim> l = face_multiplier<dim>(lambda, f);
          const Tensor<2, dim> R = system.frame(f);
          const Tensor<1, dim> j = R * jumps[f], lr = R * l;
          Row                  row{f, {}};
          for (unsigned int d = 0; d < dim; ++d)
            {
              row.second[d]       = j[d];
              row.second[dim + d] = lr[d];
            }
          row.second[2 * dim]     = static_cast<double>(solver.state(contact_jumps[f], l, f));
          row.second[2 * dim + 1] = solver.friction(contact_jumps[f], f);
          rows.push_back(row);
        }
      const auto all = Utilities::MPI::gather(system.get_communicator(), rows, 0);
      std::vector<ContactFaceValues<dim>> values;
      if (system.get_distributed_mesh().this_rank() != 0)
        return values;
      values.resize(system.n_faces());
      for (const auto &part : all)
        for (const auto &[f, v] : part)
          {
            for (unsigned int d = 0; d < dim; ++d)
              {
                values[f].jump[d]   = v[d];
                values[f].lambda[d] = v[dim + d];
              }
            values[f].state    = static_cast<FaceState>(static_cast<unsigned int>(v[2 * dim]));
            values[f].friction = v[2 * dim + 1];
          }
      return values;
    }



    template <int dim>
    Vector<double>
    DistributedContactProblem<dim>::gather_displacement(const DoFHandler<dim> *serial_dofs) const
    {
      // Each process sends the dof values of its cells with the serial cell index; the local
      // dof order of a cell is the same in both DoFHandlers (same FE, same vertex order).
      const auto      &mesh    = system.get_distributed_mesh();
      const VectorType ghosted = ghosted_displacement();
      using CellValues         = std::pair<unsigned int, std::vector<double>>;
      std::vector<CellValues> mine;
      Vector<double>          local(system.get_fe().n_dofs_per_cell());
      for (const auto &cell : system.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_values(ghosted, local);
            mine.emplace_back(mesh.serial_cell(cell)->active_cell_index(),
                              std::vector<double>(local.begin(), local.end()));
          }
      const auto     all = Utilities::MPI::gather(system.get_communicator(), mine, 0);
      Vector<double> result;
      if (mesh.this_rank() != 0 || serial_dofs == nullptr)
        return result;
      result.reinit(serial_dofs->n_dofs());
      std::vector<typename DoFHandler<dim>::active_cell_iterator> cells(
        serial_dofs->get_triangulation().n_active_cells());
      for (const auto &cell : serial_dofs->active_cell_iterators())
        cells[cell->active_cell_index()] = cell;
      for (const auto &part : all)
        for (const auto &[index, values] : part)
          {
            for (unsigned int i = 0; i < values.size(); ++i)
              local[i] = values[i];
            cells[index]->set_dof_values(local, result);
          }
      return result;
    }



    template <int dim>
    Vector<double>
    DistributedContactProblem<dim>::gather_multipliers() const
    {
      std::vector<std::pair<unsigned int, double>> mine;
      for (const auto i : system.owned_multipliers())
        mine.emplace_back(i, lambda(i));
      const auto     all = Utilities::MPI::gather(system.get_communicator(), mine, 0);
      Vector<double> result;
      if (system.get_distributed_mesh().this_rank() != 0)
        return result;
      result.reinit(dim * system.n_faces());
      for (const auto &part : all)
        for (const auto &[i, v] : part)
          result(i) = v;
      return result;
    }



    template <int dim>
    void
    write_distributed_displacement(const DistributedContactProblem<dim> &problem,
                                   const std::string                    &directory,
                                   const std::string                    &basename,
                                   const std::string                    &format)
    {
      const auto        &system = problem.get_system();
      const unsigned int rank   = system.get_distributed_mesh().this_rank();
      const auto         u      = problem.ghosted_displacement();
      DataOut<dim>       data_out;
      data_out.attach_dof_handler(system.get_dof_handler());
      std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
        dim, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(u,
                               std::vector<std::string>(dim, "displacement"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
      geometry::OutputPieces pieces;
      pieces.own_cells_only = true;
      pieces.rank           = rank;
      pieces.n_ranks        = Utilities::MPI::n_mpi_processes(system.get_communicator());
      const auto &mesh      = system.get_distributed_mesh();
      geometry::write_field_file(data_out,
                                 mesh.triangulation,
                                 mesh.mapping(),
                                 2,
                                 directory + "/" + basename,
                                 format,
                                 pieces);
    }

    template class DistributedContactProblem<2>;
    template class DistributedContactProblem<3>;
    template void
    write_distributed_displacement(const DistributedContactProblem<2> &,
                                   const std::string &,
                                   const std::string &,
                                   const std::string &);
    template void
    write_distributed_displacement(const DistributedContactProblem<3> &,
                                   const std::string &,
                                   const std::string &,
                                   const std::string &);
  } // namespace mechanics
} // namespace porofrac
