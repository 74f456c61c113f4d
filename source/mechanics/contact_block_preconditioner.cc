// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/contact_block_preconditioner.h>
#include <porofrac/mechanics/trilinos_tools.h>

#include <algorithm>
#include <map>

#include <ml_MultiLevelPreconditioner.h>

namespace porofrac
{
  namespace mechanics
  {



    template <int dim>
    ContactBlockPreconditioner<dim>::ContactBlockPreconditioner(
      const DistributedElasticitySystem<dim> &system,
      const bool                              smoothed_prolongator)
        : system(system)
        , schur_lu("contact preconditioner (multiplier Schur complement)")
    {
      const MPI_Comm comm = system.get_communicator();
      const auto    &K    = system.get_constrained_matrix();
      make_rigid_body_modes();
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
      amg.initialize(K, ml);

      // G = B_0 diag(K)^-1 B_0^T, and the pattern of S~: per owned face, the union of the G
      // rows of its components and its diagonal block.
      VectorType inverse_diagonal(system.owned_displacements(), comm);
      for (const auto i : system.owned_displacements())
        inverse_diagonal(i) = 1. / K.diag_element(i);
      inverse_diagonal.compress(VectorOperation::insert);
      const auto &Bt = system.get_free_coupling_transpose();
      Bt.Tmmult(G, Bt, inverse_diagonal);
      const IndexSet        &rows = system.owned_multipliers();
      DynamicSparsityPattern dsp(rows.size(), rows.size(), rows);
      // The multiplier stabilization (doc/algorithms.md §2.2) adds its S to the face rows.
      const MultiplierStabilization &S = system.get_multiplier_stabilization();
      for (const unsigned int f : system.get_distributed_mesh().locally_owned_faces())
        for (unsigned int k = 0; k < dim; ++k)
          {
            for_entries_of_row(G, dim * f + k, [&](const auto, const auto column, const double) {
              for (unsigned int i = 0; i < dim; ++i)
                dsp.add(dim * f + i, column);
            });
            for (unsigned int i = 0; i < dim; ++i)
              {
                dsp.add(dim * f + i, dim * f + k);
                for (unsigned int n = 0; !S.empty() && n < S[f].size(); ++n)
                  dsp.add(dim * f + i, dim * S[f][n].first + k);
              }
          }
      schur.reinit(rows, rows, dsp, comm);
      r_u.reinit(system.owned_displacements(), comm);
      y_u.reinit(r_u);
      r_lambda.reinit(rows, comm);
      y_lambda.reinit(r_lambda);
    }



    template <int dim>
    ContactBlockPreconditioner<dim>::~ContactBlockPreconditioner() = default;



    template <int dim>
    void
    ContactBlockPreconditioner<dim>::make_rigid_body_modes()
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



    template <int dim>
    void
    ContactBlockPreconditioner<dim>::set_rows(const FaceRows<dim> &rows)
    {
      schur = 0;
      for (const unsigned int f : system.get_distributed_mesh().locally_owned_faces())
        {
          const double m = system.face_measure(f);
          for (unsigned int i = 0; i < dim; ++i)
            {
              const types::global_dof_index row = dim * f + i;
              for (unsigned int j = 0; j < dim; ++j)
                schur.add(row, dim * f + j, rows.lambda[f][i][j]);
              for (unsigned int k = 0; k < dim; ++k)
                {
                  const double w = rows.jump[f][i][k] / m;
                  if (w != 0)
                    for_entries_of_row(G,
                                       dim * f + k,
                                       [&](const auto, const auto column, const double g) {
                                         schur.add(row, column, -w * g);
                                       });
                }
            }
          for_stabilization_entries<dim>(
            system.get_multiplier_stabilization(),
            f,
            rows.jump[f],
            [&](const unsigned int i, const unsigned int g, const unsigned int k, const double v) {
              schur.add(dim * f + i, dim * g + k, v);
            });
        }
      schur.compress(VectorOperation::add);
      schur_lu.factorize(schur);
    }



    template <int dim>
    void
    ContactBlockPreconditioner<dim>::vmult(VectorType &dst, const VectorType &src) const
    {
      split(src, r_u, r_lambda);
      schur_lu.solve(y_lambda, r_lambda);
      system.get_free_coupling_transpose().vmult(y_u, y_lambda);
      r_u -= y_u;
      amg.vmult(y_u, r_u);
      join(y_u, y_lambda, dst);
    }

    template class ContactBlockPreconditioner<2>;
    template class ContactBlockPreconditioner<3>;
  } // namespace mechanics
} // namespace porofrac
