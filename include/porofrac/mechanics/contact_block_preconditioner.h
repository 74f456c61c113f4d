// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_CONTACT_BLOCK_PRECONDITIONER_H
#define POROFRAC_MECHANICS_CONTACT_BLOCK_PRECONDITIONER_H

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <porofrac/base/mumps_factorization.h>
#include <porofrac/mechanics/distributed_elasticity_system.h>
#include <porofrac/mechanics/elasticity_amg.h>

#include <memory>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /**
     * Block upper-triangular preconditioner of the contact Jacobian
     *   J = [K    B_0^T]
     *       [W B_0  D  ]
     * (K the constrained elasticity matrix, B_0 the coupling, W and D block-diagonal per face:
     * the jump and multiplier parts of the face rows, W = A_jump R / |sigma|, D = A_lambda R):
     *   P^-1 r: y_lambda = S~^-1 r_lambda,  y_u = K~^-1 (r_u - B_0^T y_lambda).
     *
     * The displacements are eliminated first, so that the preconditioner holds where D is zero
     * (stick faces, the normal rows of slip faces): the multiplier block is the Schur
     * complement S = D - W B_0 K^-1 B_0^T, approximated by S~ = D - W G with
     * G = gamma B_0 diag(K)^-1 B_0^T (gamma: Mechanics/Schur complement scaling), formed once (the
     * approximation PyLith uses for its fault blocks). S~ couples the faces that share displacement
     * dofs; it is small (dim per face) and is factorized by MUMPS whenever the face rows change.
     * K~^-1 is one V-cycle of ElasticityAmg (aggregation AMG on K with the rigid-body modes).
     * (doc/parallel.md)
     */
    template <int dim>
    class ContactBlockPreconditioner
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;

      /// Builds the AMG hierarchy of K (smoothed aggregation, or plain aggregation without
      /// @p smoothed_prolongator) and G, scaled by @p schur_scaling.
      ContactBlockPreconditioner(const DistributedElasticitySystem<dim> &system,
                                 bool                                    smoothed_prolongator,
                                 double                                  schur_scaling = 1);
      ~ContactBlockPreconditioner();

      /// S~ for the face rows @p rows; factorizes it.
      void
      set_rows(const FaceRows<dim> &rows);

      /// dst = P^-1 src on (u, lambda) vectors.
      void
      vmult(VectorType &dst, const VectorType &src) const;

      /// Factorizations of the Schur complement repeated with a larger MUMPS workspace.
      unsigned int
      workspace_retries() const
      {
        return schur_lu.workspace_retries();
      }

    private:
      const DistributedElasticitySystem<dim> &system;
      ElasticityAmg<dim>                      amg;
      TrilinosWrappers::SparseMatrix          G, schur;
      MumpsFactorization                      schur_lu;
      mutable VectorType                      r_u, r_lambda, y_u, y_lambda;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
