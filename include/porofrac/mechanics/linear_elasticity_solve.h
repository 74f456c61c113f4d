// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_LINEAR_ELASTICITY_SOLVE_H
#define POROFRAC_MECHANICS_LINEAR_ELASTICITY_SOLVE_H

#include <deal.II/lac/trilinos_vector.h>

#include <porofrac/mechanics/distributed_elasticity_system.h>
#include <porofrac/mechanics/parameters.h>

#include <string>

namespace porofrac
{
  namespace mechanics
  {
    /// One linear elasticity solve and what it cost.
    struct LinearElasticitySolve
    {
      /// "AMG-CG" or "MUMPS".
      std::string solver;
      /// Wall times (s) of the preconditioner or factorization, and of the solve.
      double set_up_time = 0, solve_time = 0;
      /// CG iterations (0 for MUMPS).
      unsigned int iterations = 0;
      /// False if CG did not reach the tolerance in Max linear iterations, or MUMPS failed;
      /// then @p failure says which.
      bool        converged = true;
      std::string failure;
      /// The displacement (owned dofs); the Dirichlet values where CG did not converge.
      dealii::TrilinosWrappers::MPI::Vector displacement;
    };

    /**
     * One linear elasticity solve on the mesh of @p system with every fracture open and
     * lambda = 0 (K u = f), by the distributed solver the contact iterations use (deck entry
     * Mechanics/Distributed linear solver): with "iterative", CG preconditioned by the same
     * AMG (ElasticityAmg) to the relative residual Linear solver tolerance in at most Max
     * linear iterations; otherwise one MUMPS factorization and solve of K. The reference of
     * the cost of a contact solve (Mechanics/Report linear solve time). Collective.
     */
    template <int dim>
    LinearElasticitySolve
    solve_linear_elasticity(const DistributedElasticitySystem<dim> &system,
                            const ContactParameters                &parameters);
  } // namespace mechanics
} // namespace porofrac

#endif
