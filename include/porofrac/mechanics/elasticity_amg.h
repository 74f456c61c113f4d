// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_ELASTICITY_AMG_H
#define POROFRAC_MECHANICS_ELASTICITY_AMG_H

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_vector.h>

#include <porofrac/mechanics/distributed_elasticity_system.h>

#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /**
     * One V-cycle of aggregation AMG (Trilinos ML) on the constrained elasticity matrix K of a
     * DistributedElasticitySystem, with the rigid-body modes of the owned displacement dofs as
     * near null space: smoothed aggregation, or with @p smoothed_prolongator false the plain
     * (tentative) prolongator (deck entry Mechanics/AMG prolongator). Two Chebyshev sweeps,
     * KLU on the coarsest level. The K~^-1 of the contact preconditioner and the preconditioner
     * of the linear elasticity solve it is compared with. (doc/parallel.md)
     */
    template <int dim>
    class ElasticityAmg
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      ElasticityAmg(const DistributedElasticitySystem<dim> &system, bool smoothed_prolongator);

      /// dst = K~^-1 src on owned displacement vectors.
      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        amg.vmult(dst, src);
      }

    private:
      /// Throws InsufficientMemory on every process if the AMG set-up of @p K would not fit
      /// (require_memory_on_every_process(); per nonzero of K, 48 bytes of resident memory and
      /// 65 of address space with the smoothed prolongator, 13.5 and 19.5 without).
      static void
      check_memory(const dealii::TrilinosWrappers::SparseMatrix &K, bool smoothed_prolongator);

      /// The rigid-body modes, mode by mode, rotations about the centre of the domain.
      void
      make_rigid_body_modes(const DistributedElasticitySystem<dim> &system);

      std::vector<double>                       modes;
      dealii::TrilinosWrappers::PreconditionAMG amg;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
