// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <porofrac/mechanics/distributed_contact_linear_solver.h>
#include <porofrac/mechanics/trilinos_tools.h>

namespace porofrac
{
  namespace mechanics
  {



    template <int dim>
    DistributedJacobian<dim>::DistributedJacobian(const DistributedElasticitySystem<dim> &system)
        : system(system)
        , coupling(system.n_faces())
    {
      const types::global_dof_index n_u  = system.n_displacement_dofs();
      const auto                   &K    = system.get_constrained_matrix();
      const auto                   &B    = system.get_free_coupling();
      const auto                   &Bt   = system.get_free_coupling_transpose();
      const IndexSet               &rows = system.owned_unknowns();
      for_owned_entries(B, [&](const auto row, const auto column, const double value) {
        if (value != 0)
          coupling[row / dim].push_back({column, static_cast<unsigned int>(row % dim), value});
      });
      DynamicSparsityPattern dsp(rows.size(), rows.size(), rows);
      for_owned_entries(K, [&](const auto r, const auto c, const double) { dsp.add(r, c); });
      for_owned_entries(Bt, [&](const auto r, const auto c, const double) { dsp.add(r, n_u + c); });
      // A face row couples to the dofs of every component of the face's jump.
      for_owned_entries(B, [&](const auto r, const auto c, const double) {
        for (unsigned int i = 0; i < dim; ++i)
          dsp.add(n_u + dim * (r / dim) + i, c);
      });
      for (const unsigned int f : system.get_distributed_mesh().locally_owned_faces())
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            dsp.add(n_u + dim * f + i, n_u + dim * f + j);
      base.reinit(rows, rows, dsp, system.get_communicator());
      for_owned_entries(K, [&](const auto r, const auto c, const double v) { base.set(r, c, v); });
      for_owned_entries(Bt, [&](const auto r, const auto c, const double v) {
        base.set(r, n_u + c, v);
      });
      base.compress(VectorOperation::insert);
      jacobian.reinit(base);
    }



    template <int dim>
    void
    DistributedJacobian<dim>::assemble(const FaceRows<dim> &rows)
    {
      const types::global_dof_index n_u = system.n_displacement_dofs();
      jacobian.copy_from(base);
      for (const unsigned int f : system.get_distributed_mesh().locally_owned_faces())
        {
          const double m = system.face_measure(f);
          for (unsigned int i = 0; i < dim; ++i)
            {
              const types::global_dof_index row = n_u + dim * f + i;
              for (unsigned int k = 0; k < dim; ++k)
                jacobian.add(row, n_u + dim * f + k, rows.lambda[f][i][k]);
              for (const CouplingEntry &e : coupling[f])
                jacobian.add(row, e.dof, rows.jump[f][i][e.component] * e.value / m);
            }
        }
      jacobian.compress(VectorOperation::add);
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
