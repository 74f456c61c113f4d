// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/full_system_solver.h>
#include <porofrac/mechanics/multiplier_schur_complement.h>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /**
       * The Schur complement on the multipliers (deck: Linear solver = schur complement,
       * multiplier_schur_complement.h): one Cholesky factorization of K and W = J K^{-1} B^T,
       * then per set of face rows a dense LU, and per solve two sparse triangular solve pairs.
       * Needs K positive definite, i.e. Dirichlet conditions that hold the body without the
       * contact rows.
       */
      template <int dim>
      class SchurComplementSolver : public ContactLinearSolver<dim>
      {
      public:
        SchurComplementSolver(const ElasticitySystem<dim> &system,
                              ConditionalOStream          &progress,
                              TimerOutput                 &timer)
            : system(system)
        {
          TimerOutput::Scope t(timer, "Mechanics: Schur complement setup");
          const unsigned int n_u = system.n_displacement_dofs();
          std::vector<bool>  constrained(n_u);
          for (unsigned int i = 0; i < n_u; ++i)
            constrained[i] = system.get_homogeneous_constraints().is_constrained(i);
          schur =
            std::make_unique<MultiplierSchurComplement<dim>>(system.get_constrained_matrix(),
                                                             n_u,
                                                             system.get_coupling(),
                                                             system.get_face_measures(),
                                                             constrained,
                                                             system.get_multiplier_stabilization());
          this->stats.time_cholesky = schur->time_cholesky;
          this->stats.time_form_W   = schur->time_form_W;
          progress << "    Schur complement: Cholesky of K (" << n_u << " dofs, "
                   << schur->cholesky().factor_nonzeros() << " nonzeros in L) "
                   << schur->time_cholesky << " s, W (" << dim * system.get_coupling().size()
                   << "^2, " << schur->reach_entries << " nonzeros in L^{-1} P J^T) "
                   << schur->time_form_W << " s" << std::endl;
        }

        void
        solve(const FaceRows<dim> &rows,
              const unsigned int,
              const Vector<double> &rhs,
              Vector<double>       &x) override
        {
          const double lu0 = schur->time_dense_lu, s0 = schur->time_solves;
          if (!schur->set_rows(rows.lambda, rows.jump))
            ++this->stats.factorizations;
          schur->solve(rhs, x);
          // Iterative refinement on the full system: the dense multiplier system is worse
          // conditioned than the full one (stick rows against W ~ h/E), and a solve error of
          // ~1e-7 stalls warm-started coupled solves and spoils the finite-difference products
          // of Newton-Krylov.
          Vector<double> defect(rhs.size()), correction(rhs.size());
          for (unsigned int k = 0; k < 3; ++k)
            {
              system.apply_jacobian(rows, x, defect);
              defect.sadd(-1., 1., rhs);
              if (defect.l2_norm() <= 1e-14 * rhs.l2_norm())
                break;
              schur->solve(defect, correction);
              x += correction;
            }
          this->stats.time_factorization += schur->time_dense_lu - lu0;
          this->stats.time_solves += schur->time_solves - s0;
        }

        void
        reset() override
        {
          schur->clear_rows();
        }

        std::string
        name() const override
        {
          return "schur complement";
        }

      private:
        const ElasticitySystem<dim>                    &system;
        std::unique_ptr<MultiplierSchurComplement<dim>> schur;
      };

      /// The Schur complement solver, or the full system if K alone is singular (a body held
      /// in place by the contact rows only: the full system is still regular).
      template <int dim>
      std::unique_ptr<ContactLinearSolver<dim>>
      make_schur_complement_solver(const ElasticitySystem<dim> &system,
                                   const ContactParameters     &parameters,
                                   ConditionalOStream          &progress,
                                   TimerOutput                 &timer)
      {
        try
          {
            return std::make_unique<SchurComplementSolver<dim>>(system, progress, timer);
          }
        catch (const InsufficientMemory &)
          {
            throw;
          }
        catch (const SolverFailure &e)
          {
            if (parameters.multiplier_stabilization > 0)
              throw SolverFailure(std::string(e.what()) +
                                  "; Mechanics/Multiplier stabilization needs the Schur "
                                  "complement, i.e. Dirichlet conditions that hold the body "
                                  "without the contact rows");
            progress << "    Schur complement unavailable (" << e.what()
                     << "); solving the full system" << std::endl;
            return std::make_unique<FullSystemSolver<dim>>(system, parameters);
          }
      }

      const std::string description =
        "schur complement: one Cholesky factorization of the elasticity block K (it never "
        "changes), W = J K^{-1} B^T formed once (dim x fracture faces square, dense), then per "
        "iteration a dense LU of A_l - A_j W and two sparse triangular solve pairs (needs K "
        "positive definite, i.e. enough Dirichlet conditions without the contact rows; the full "
        "system is solved otherwise).";
    } // namespace

    POROFRAC_REGISTER(ContactLinearSolverRegistry<2>,
                      "schur complement",
                      description,
                      make_schur_complement_solver<2>)
    POROFRAC_REGISTER(ContactLinearSolverRegistry<3>,
                      "schur complement",
                      description,
                      make_schur_complement_solver<3>)
  } // namespace mechanics
} // namespace porofrac
