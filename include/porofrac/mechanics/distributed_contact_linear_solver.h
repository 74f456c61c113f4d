// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_DISTRIBUTED_CONTACT_LINEAR_SOLVER_H
#define POROFRAC_MECHANICS_DISTRIBUTED_CONTACT_LINEAR_SOLVER_H

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

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
     * The Jacobian of the contact iterations (27) on the (u, lambda) unknowns of a
     * DistributedElasticitySystem: the constrained K and B_0^T in the displacement rows, the
     * face rows A_lambda R lambda + A_jump R B_0 u / |sigma| in the multiplier rows. Every row is
     * written by its owner, so assembling needs no communication.
     *
     * Storage::whole_matrix holds it as one Trilinos matrix (matrix(), for the direct
     * solvers); assemble() rewrites the face rows in place. Storage::face_rows holds only the
     * face rows and applies K and B_0^T of the system (vmult(), for Krylov solvers): two fewer
     * copies of the elasticity matrix.
     */
    template <int dim>
    class DistributedJacobian
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;

      enum class Storage
      {
        whole_matrix,
        face_rows
      };

      DistributedJacobian(const DistributedElasticitySystem<dim> &system, Storage storage);

      /// The face rows become @p rows.
      void
      assemble(const FaceRows<dim> &rows);

      /// The whole Jacobian (Storage::whole_matrix only).
      const TrilinosWrappers::SparseMatrix &
      matrix() const;

      /// dst = J src on (u, lambda) vectors.
      void
      vmult(VectorType &dst, const VectorType &src) const;

    private:
      /// Calls @p visit(i, column, value) for the entries of the face rows of the owned face
      /// @p f (i its multiplier component, column in the numbering of (u, lambda)).
      template <typename Visit>
      void
      for_face_row_entries(const FaceRows<dim> &rows,
                           const unsigned int   f,
                           const Visit         &visit) const;

      const DistributedElasticitySystem<dim> &system;
      const Storage                           storage;
      std::vector<std::vector<CouplingEntry>> coupling;
      /// Storage::whole_matrix: the Jacobian; Storage::face_rows: the face rows alone (rows
      /// numbered as the multipliers, columns as (u, lambda)).
      TrilinosWrappers::SparseMatrix matrix_;
      mutable VectorType             x_u, x_lambda, y_u, y_lambda;
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
