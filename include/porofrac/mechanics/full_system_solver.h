// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_FULL_SYSTEM_SOLVER_H
#define POROFRAC_MECHANICS_FULL_SYSTEM_SOLVER_H

#include <deal.II/lac/sparse_matrix.h>

#include <porofrac/base/sparse_lu.h>
#include <porofrac/mechanics/contact_linear_solver.h>

#include <memory>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /**
     * UMFPACK LU of the whole (u, lambda) Jacobian (deck: Linear solver = full system). The
     * factorization is reused while no face row changes (the active-set method with an
     * unchanged active set, e.g. warm-started coupled solves); with `reuse_iterations` > 0 and
     * few changed faces, GMRES preconditioned by the old factors is tried first (it needs
     * about one step per changed row).
     */
    template <int dim>
    class FullSystemSolver : public ContactLinearSolver<dim>
    {
    public:
      FullSystemSolver(const ElasticitySystem<dim> &system, const ContactParameters &parameters);

      void
      solve(const FaceRows<dim>  &rows,
            const unsigned int    n_changed_faces,
            const Vector<double> &rhs,
            Vector<double>       &x) override;

      void
      reset() override;

      std::string
      name() const override
      {
        return "full system";
      }

    private:
      /// system_matrix = constrained K + B^T + the face rows.
      void
      assemble(const FaceRows<dim> &rows);
      void
      factorize_and_solve(const FaceRows<dim> &rows, const Vector<double> &rhs, Vector<double> &x);

      const ElasticitySystem<dim> &system;
      const unsigned int           reuse_iterations;
      /// Allocated on first use (the other solvers never need the full matrix).
      SparseMatrix<double>      system_matrix;
      std::unique_ptr<SparseLU> factorization;
      FaceRows<dim>             factorized_rows;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
