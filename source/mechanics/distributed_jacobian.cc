// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <porofrac/mechanics/distributed_contact_linear_solver.h>
#include <porofrac/mechanics/trilinos_tools.h>

namespace porofrac
{
  namespace mechanics
  {



    template <int dim>
    DistributedJacobian<dim>::DistributedJacobian(const DistributedElasticitySystem<dim> &system,
                                                  const Storage                           storage)
        : system(system)
        , storage(storage)
        , coupling(system.n_faces())
    {
      const types::global_dof_index n_u   = system.n_displacement_dofs();
      const auto                   &K     = system.get_constrained_matrix();
      const auto                   &B     = system.get_free_coupling();
      const auto                   &Bt    = system.get_free_coupling_transpose();
      const MPI_Comm                comm  = system.get_communicator();
      const bool                    whole = storage == Storage::whole_matrix;
      for_owned_entries(B, [&](const auto row, const auto column, const double value) {
        if (value != 0)
          coupling[row / dim].push_back({column, static_cast<unsigned int>(row % dim), value});
      });
      // The face rows' pattern: a face row couples to the dofs of every component of the
      // face's jump, and to the face's multipliers. Its rows are offset by n_u in the whole
      // matrix.
      const IndexSet        &rows   = whole ? system.owned_unknowns() : system.owned_multipliers();
      const auto             offset = whole ? n_u : 0;
      DynamicSparsityPattern dsp(rows.size(), system.n_dofs(), rows);
      for_owned_entries(B, [&](const auto r, const auto c, const double) {
        for (unsigned int i = 0; i < dim; ++i)
          dsp.add(offset + dim * (r / dim) + i, c);
      });
      // ... and, with the multiplier stabilization, to the multipliers of its neighbours.
      const MultiplierStabilization &S = system.get_multiplier_stabilization();
      for (const unsigned int f : system.get_distributed_mesh().locally_owned_faces())
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              dsp.add(offset + dim * f + i, n_u + dim * f + j);
              for (unsigned int n = 0; !S.empty() && n < S[f].size(); ++n)
                dsp.add(offset + dim * f + i, n_u + dim * S[f][n].first + j);
            }
      if (!whole)
        {
          matrix_.reinit(rows, system.owned_unknowns(), dsp, comm);
          x_u.reinit(system.owned_displacements(), comm);
          y_u.reinit(x_u);
          x_lambda.reinit(rows, comm);
          y_lambda.reinit(x_lambda);
          return;
        }
      for_owned_entries(K, [&](const auto r, const auto c, const double) { dsp.add(r, c); });
      for_owned_entries(Bt, [&](const auto r, const auto c, const double) { dsp.add(r, n_u + c); });
      matrix_.reinit(rows, rows, dsp, comm);
      for_owned_entries(K,
                        [&](const auto r, const auto c, const double v) { matrix_.set(r, c, v); });
      for_owned_entries(Bt, [&](const auto r, const auto c, const double v) {
        matrix_.set(r, n_u + c, v);
      });
      matrix_.compress(VectorOperation::insert);
    }



    template <int dim>
    template <typename Visit>
    void
    DistributedJacobian<dim>::for_face_row_entries(const FaceRows<dim> &rows,
                                                   const unsigned int   f,
                                                   const Visit         &visit) const
    {
      const types::global_dof_index n_u = system.n_displacement_dofs();
      const double                  m   = system.face_measure(f);
      for (unsigned int i = 0; i < dim; ++i)
        {
          for (unsigned int k = 0; k < dim; ++k)
            visit(i, n_u + dim * f + k, rows.lambda[f][i][k]);
          for (const CouplingEntry &e : coupling[f])
            visit(i, e.dof, rows.jump[f][i][e.component] * e.value / m);
        }
      for_stabilization_entries<dim>(system.get_multiplier_stabilization(),
                                     f,
                                     rows.jump[f],
                                     [&](const unsigned int i,
                                         const unsigned int g,
                                         const unsigned int k,
                                         const double       v) { visit(i, n_u + dim * g + k, v); });
    }



    template <int dim>
    void
    DistributedJacobian<dim>::assemble(const FaceRows<dim> &rows)
    {
      const types::global_dof_index offset =
        storage == Storage::whole_matrix ? system.n_displacement_dofs() : 0;
      for (const unsigned int f : system.get_distributed_mesh().locally_owned_faces())
        {
          for (unsigned int i = 0; i < dim; ++i)
            zero_row(matrix_, offset + dim * f + i);
          for_face_row_entries(rows, f, [&](const unsigned int i, const auto column, double v) {
            matrix_.add(offset + dim * f + i, column, v);
          });
        }
      matrix_.compress(VectorOperation::add);
    }



    template <int dim>
    const TrilinosWrappers::SparseMatrix &
    DistributedJacobian<dim>::matrix() const
    {
      Assert(storage == Storage::whole_matrix, ExcInternalError());
      return matrix_;
    }



    template <int dim>
    void
    DistributedJacobian<dim>::vmult(VectorType &dst, const VectorType &src) const
    {
      if (storage == Storage::whole_matrix)
        {
          matrix_.vmult(dst, src);
          return;
        }
      split(src, x_u, x_lambda);
      system.get_constrained_matrix().vmult(y_u, x_u);
      system.get_free_coupling_transpose().vmult_add(y_u, x_lambda);
      matrix_.vmult(y_lambda, src);
      join(y_u, y_lambda, dst);
    }



    template <int dim>
    bool
    same_owned_rows(const DistributedElasticitySystem<dim> &system,
                    const FaceRows<dim>                    &a,
                    const FaceRows<dim>                    &b)
    {
      bool same = a.lambda.size() == b.lambda.size() && a.jump.size() == b.jump.size();
      if (same)
        for (const unsigned int f : system.get_distributed_mesh().locally_owned_faces())
          same = same && a.lambda[f] == b.lambda[f] && a.jump[f] == b.jump[f];
      return system.all_processes(same);
    }

    template class DistributedJacobian<2>;
    template class DistributedJacobian<3>;
    template bool
    same_owned_rows(const DistributedElasticitySystem<2> &,
                    const FaceRows<2> &,
                    const FaceRows<2> &);
    template bool
    same_owned_rows(const DistributedElasticitySystem<3> &,
                    const FaceRows<3> &,
                    const FaceRows<3> &);
  } // namespace mechanics
} // namespace porofrac
