// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_DISTRIBUTED_CONTACT_LINEAR_SOLVER_H
#define POROFRAC_MECHANICS_DISTRIBUTED_CONTACT_LINEAR_SOLVER_H

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <porofrac/mechanics/contact_linear_solver.h>
#include <porofrac/mechanics/coupling_entry.h>
#include <porofrac/mechanics/distributed_elasticity_system.h>

#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /// The linear solvers of distributed contact iterations (deck entry Mechanics/Distributed
    /// linear solver): the ContactLinearSolver interface on Trilinos vectors.
    template <int dim>
    using DistributedContactLinearSolver =
      ContactLinearSolver<dim, DistributedElasticitySystem<dim>>;

    template <int dim>
    using DistributedContactLinearSolverRegistry =
      ContactLinearSolverRegistry<dim, DistributedElasticitySystem<dim>>;

    /**
     * The Jacobian of the contact iterations (27) as one Trilinos matrix on the (u, lambda)
     * unknowns of a DistributedElasticitySystem: the constrained K and B_0^T in the displacement
     * rows (assembled once, `base`), the face rows A_lambda R lambda + A_jump R B_0 u / |sigma|
     * in the multiplier rows (assemble()). Every row is written by its owner, so assembling
     * needs no communication.
     */
    template <int dim>
    class DistributedJacobian
    {
    public:
      explicit DistributedJacobian(const DistributedElasticitySystem<dim> &system);

      /// matrix() = base + the face rows @p rows.
      void
      assemble(const FaceRows<dim> &rows);

      const TrilinosWrappers::SparseMatrix &
      matrix() const
      {
        return jacobian;
      }

      /// The entries of B_0 of an owned face (dof, component, int phi), nonzero only.
      const std::vector<CouplingEntry> &
      face_coupling(const unsigned int f) const
      {
        return coupling[f];
      }

    private:
      const DistributedElasticitySystem<dim> &system;
      std::vector<std::vector<CouplingEntry>> coupling;
      TrilinosWrappers::SparseMatrix          base, jacobian;
    };

    /// Whether @p a and @p b have the same rows on the faces this process owns.
    template <int dim>
    bool
    same_owned_rows(const DistributedElasticitySystem<dim> &system,
                    const FaceRows<dim>                    &a,
                    const FaceRows<dim>                    &b);
  } // namespace mechanics
} // namespace porofrac

#endif
