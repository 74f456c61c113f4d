// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/full_system_solver.h>

#include <new>

namespace porofrac
{
  namespace mechanics
  {
    template <int dim>
    FullSystemSolver<dim>::FullSystemSolver(const ElasticitySystem<dim> &system,
                                            const ContactParameters     &parameters)
        : system(system)
        , reuse_iterations(parameters.reuse_iterations)
    {
    }



    template <int dim>
    void
    FullSystemSolver<dim>::reset()
    {
      factorization.reset();
      factorized_rows = FaceRows<dim>();
    }



    template <int dim>
    void
    FullSystemSolver<dim>::assemble(const FaceRows<dim> &rows)
    {
      if (system_matrix.empty())
        system_matrix.reinit(system.get_sparsity_pattern());
      system_matrix.copy_from(system.get_constrained_matrix());
      const unsigned int n_u         = system.n_displacement_dofs();
      const auto        &coupling    = system.get_coupling();
      const auto        &constraints = system.get_homogeneous_constraints();
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        {
          const double m = system.face_measure(fi);
          for (unsigned int i = 0; i < dim; ++i)
            {
              const unsigned int row = n_u + dim * fi + i;
              for (unsigned int k = 0; k < dim; ++k)
                system_matrix.add(row, n_u + dim * fi + k, rows.lambda[fi][i][k]);
              for (const auto &e : coupling[fi])
                if (!constraints.is_constrained(e.dof))
                  system_matrix.add(row, e.dof, rows.jump[fi][i][e.component] * e.value / m);
            }
        }
    }



    template <int dim>
    void
    FullSystemSolver<dim>::factorize_and_solve(const FaceRows<dim>  &rows,
                                               const Vector<double> &rhs,
                                               Vector<double>       &x)
    {
      Timer clock;
      // One LU object for every solve: the symbolic analysis of the fixed pattern is reused.
      // No iterative refinement: the contact iteration corrects the solve error itself.
      if (!factorization)
        factorization = std::make_unique<SparseLU>(/*refinement_steps=*/0);
      try
        {
          factorization->factorize(system_matrix);
        }
      catch (const InsufficientMemory &e)
        {
          factorization.reset();
          throw InsufficientMemory(std::string("contact mechanics: ") + e.what());
        }
      catch (const std::bad_alloc &)
        {
          factorization.reset();
          throw;
        }
      catch (const std::exception &e)
        {
          factorization.reset();
          throw SolverFailure(std::string("contact mechanics: ") + e.what());
        }
      factorized_rows = rows;
      ++this->stats.factorizations;
      this->stats.time_factorization += clock.wall_time();
      clock.restart();
      factorization->vmult(x, rhs);
      this->stats.time_solves += clock.wall_time();
    }



    template <int dim>
    void
    FullSystemSolver<dim>::solve(const FaceRows<dim>  &rows,
                                 const unsigned int    n_changed_faces,
                                 const Vector<double> &rhs,
                                 Vector<double>       &x)
    {
      // The Jacobian depends on the face rows only: while none changed, the factors are exact.
      const bool same_matrix =
        factorization && rows.lambda == factorized_rows.lambda && rows.jump == factorized_rows.jump;
      if (same_matrix)
        {
          Timer clock;
          factorization->vmult(x, rhs);
          this->stats.time_solves += clock.wall_time();
          return;
        }
      assemble(rows);
      if (factorization && reuse_iterations > 0 && dim * n_changed_faces < reuse_iterations &&
          this->solve_with_old_factors(system_matrix, *factorization, rhs, x, reuse_iterations))
        return;
      factorize_and_solve(rows, rhs, x);
    }

    template class FullSystemSolver<2>;
    template class FullSystemSolver<3>;

    namespace
    {
      const std::string description =
        "full system: UMFPACK LU of the whole (u, lambda) Jacobian, refactorized whenever a face "
        "row changed.";
    } // namespace

    POROFRAC_REGISTER(ContactLinearSolverRegistry<2>,
                      "full system",
                      description,
                      [](const ElasticitySystem<2> &s,
                         const ContactParameters   &p,
                         ConditionalOStream &,
                         TimerOutput &) { return std::make_unique<FullSystemSolver<2>>(s, p); })
    POROFRAC_REGISTER(ContactLinearSolverRegistry<3>,
                      "full system",
                      description,
                      [](const ElasticitySystem<3> &s,
                         const ContactParameters   &p,
                         ConditionalOStream &,
                         TimerOutput &) { return std::make_unique<FullSystemSolver<3>>(s, p); })
  } // namespace mechanics
} // namespace porofrac
