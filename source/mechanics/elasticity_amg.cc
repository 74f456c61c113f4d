// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/mechanics/elasticity_amg.h>

#include <map>

#include <ml_MultiLevelPreconditioner.h>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    template <int dim>
    ElasticityAmg<dim>::ElasticityAmg(const DistributedElasticitySystem<dim> &system,
                                      const bool                              smoothed_prolongator)
    {
      make_rigid_body_modes(system);
      Teuchos::ParameterList ml;
      ML_Epetra::SetDefaults("SA", ml);
      ml.set("ML output", 0);
      ml.set("PDE equations", dim);
      ml.set("null space: type", "pre-computed");
      ml.set("null space: dimension", dim == 2 ? 3 : 6);
      ml.set("null space: vectors", modes.data());
      ml.set("smoother: type", "Chebyshev");
      ml.set("smoother: sweeps", 2);
      ml.set("aggregation: threshold", 1e-4);
      ml.set("coarse: type", "Amesos-KLU");
      if (!smoothed_prolongator)
        ml.set("aggregation: damping factor", 0.);
      check_memory(system.get_constrained_matrix(), smoothed_prolongator);
      amg.initialize(system.get_constrained_matrix(), ml);
    }



    template <int dim>
    void
    ElasticityAmg<dim>::check_memory(const TrilinosWrappers::SparseMatrix &K,
                                     const bool                            smoothed_prolongator)
    {
      // ML ends the process where an allocation fails, so its set-up is checked first, on
      // every process together. Measured on the penny (h = 0.1 and 0.05, one process;
      // doc/benchmarks/penny.md §5.1), the hierarchy takes 51-54 (smoothed prolongator) and 15
      // (unsmoothed) bytes of resident memory per nonzero of K and maps 72-76 and 22 bytes of
      // address space: nine tenths of each are the bounds.
      const double nonzeros = K.trilinos_matrix().NumMyNonzeros() / (1024. * 1024.);
      require_memory_on_every_process((smoothed_prolongator ? 48. : 13.5) * nonzeros,
                                      "the AMG hierarchy of the elasticity block (" +
                                        std::to_string(K.m()) + " rows, " +
                                        std::to_string(K.n_nonzero_elements()) +
                                        " nonzeros) would need at least %",
                                      "use more processes or a coarser mesh",
                                      K.get_mpi_communicator(),
                                      0.,
                                      (smoothed_prolongator ? 65. : 19.5) * nonzeros);
    }



    template <int dim>
    void
    ElasticityAmg<dim>::make_rigid_body_modes(const DistributedElasticitySystem<dim> &system)
    {
      const auto                                   &dof_handler = system.get_dof_handler();
      const IndexSet                               &owned       = system.owned_displacements();
      std::map<types::global_dof_index, Point<dim>> points;
      DoFTools::map_dofs_to_support_points(system.get_distributed_mesh().mapping(),
                                           dof_handler,
                                           points);
      std::vector<unsigned int>            component(owned.n_elements());
      std::vector<types::global_dof_index> local(system.get_fe().n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(local);
            for (unsigned int i = 0; i < local.size(); ++i)
              if (owned.is_element(local[i]))
                component[owned.index_within_set(local[i])] =
                  system.get_fe().system_to_component_index(i).first;
          }
      // Rotations about the centre of the domain, so that they are of the size of the
      // translations times the domain's radius rather than of its distance to the origin.
      const auto         box     = GridTools::compute_bounding_box(system.get_mesh().triangulation);
      const auto         centre  = box.center();
      const unsigned int n_modes = (dim == 2 ? 3 : 6), n = owned.n_elements();
      modes.assign(n_modes * n, 0.);
      for (unsigned int k = 0; k < n; ++k)
        {
          const unsigned int   c = component[k];
          const Tensor<1, dim> x = points[owned.nth_index_in_set(k)] - centre;
          modes[c * n + k]       = 1; // translation along c
          if constexpr (dim == 2)
            modes[2 * n + k] = (c == 0 ? -x[1] : x[0]);
          else
            {
              // Rotations about x, y, z: (0, -z, y), (z, 0, -x), (-y, x, 0).
              const double r[3][3] = {{0, -x[2], x[1]}, {x[2], 0, -x[0]}, {-x[1], x[0], 0}};
              for (unsigned int m = 0; m < 3; ++m)
                modes[(3 + m) * n + k] = r[m][c];
            }
        }
    }

    template class ElasticityAmg<2>;
    template class ElasticityAmg<3>;
  } // namespace mechanics
} // namespace porofrac
