// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/contact_block_preconditioner.h>
#include <porofrac/mechanics/trilinos_tools.h>

#include <algorithm>

namespace porofrac
{
  namespace mechanics
  {



    template <int dim>
    ContactBlockPreconditioner<dim>::ContactBlockPreconditioner(
      const DistributedElasticitySystem<dim> &system,
      const bool                              smoothed_prolongator,
      const double                            schur_scaling)
        : system(system)
        , amg(system, smoothed_prolongator)
        , schur_lu("contact preconditioner (multiplier Schur complement)")
    {
      const MPI_Comm comm = system.get_communicator();
      const auto    &K    = system.get_constrained_matrix();

      // G = gamma B_0 diag(K)^-1 B_0^T, and the pattern of S~: per owned face, the union of the G
      // rows of its components and its diagonal block.
      VectorType inverse_diagonal(system.owned_displacements(), comm);
      for (const auto i : system.owned_displacements())
        inverse_diagonal(i) = 1. / K.diag_element(i);
      inverse_diagonal.compress(VectorOperation::insert);
      const auto &Bt = system.get_free_coupling_transpose();
      Bt.Tmmult(G, Bt, inverse_diagonal);
      G *= schur_scaling;
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
