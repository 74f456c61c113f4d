// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/sparse_lu.h>
#include <porofrac/mechanics/sparse_cholesky.h>

#include <stdexcept>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /**
       * The cost of one linear elasticity solve (every fracture open, lambda = 0) on the
       * scene's mesh, to compare with the contact solve (deck entry Mechanics/Report linear
       * solve time): with the UMFPACK LU of the full system, and with the sparse Cholesky
       * factorization of K that the Schur complement solver uses (factorization + solve).
       */
      template <int dim>
      class LinearSolveTime : public Postprocessor<dim>
      {
      public:
        bool
        needs_system_matrices() const override
        {
          return true;
        }

        void
        execute(SceneView<dim> &scene, io::RunContext &context) override
        {
          const auto &system = scene.mechanics->get_system();
          // A static scene records its contact solve's time; a coupled one solves many.
          const bool   one_solve = context.summary.has("contact_solve_time_s");
          const double contact_time =
            one_solve ? context.summary["contact_solve_time_s"].as_number() : 0.;
          io::Json &m = context.summary["mechanics"];
          try
            {
              const double lu_time     = time_full_system(system);
              m["linear_solve_time_s"] = lu_time;
              if (one_solve)
                m["contact_linear_ratio"] = contact_time / lu_time;
              context.progress << "    one linear elasticity solve (UMFPACK): " << lu_time << " s"
                               << std::endl;
            }
          catch (const std::runtime_error &e)
            {
              // Not enough memory, or K singular without the contact rows (a body held by its
              // fractures): no reference, and the scene's own results stand.
              m["linear_solve_failure"] = e.what();
              context.progress << "    one linear elasticity solve (UMFPACK): not timed ("
                               << e.what() << ")" << std::endl;
            }
          try
            {
              const double cholesky_time = time_cholesky(system);
              context.progress << "    one linear elasticity solve (Cholesky): " << cholesky_time
                               << " s" << std::endl;
              m["linear_solve_time_cholesky_s"] = cholesky_time;
              if (one_solve)
                m["contact_linear_ratio_cholesky"] = contact_time / cholesky_time;
            }
          catch (const SolverFailure &e)
            {
              // K singular alone, or its factor beyond the memory the run has.
              m["linear_solve_failure_cholesky"] = e.what();
              context.progress << "    one linear elasticity solve (Cholesky): not timed ("
                               << e.what() << ")" << std::endl;
            }
        }

      private:
        /// The right-hand side f on unconstrained dofs.
        static Vector<double>
        load(const mechanics::ElasticitySystem<dim> &system, const unsigned int size)
        {
          Vector<double> b(size);
          for (unsigned int i = 0; i < system.n_displacement_dofs(); ++i)
            b(i) = system.get_homogeneous_constraints().is_constrained(i) ? 0. : system.load()(i);
          return b;
        }

        static double
        time_full_system(const mechanics::ElasticitySystem<dim> &system)
        {
          // The multiplier rows read lambda = 0.
          Timer                clock;
          SparseMatrix<double> A(system.get_sparsity_pattern());
          A.copy_from(system.get_constrained_matrix());
          for (unsigned int i = system.n_displacement_dofs(); i < system.n_dofs(); ++i)
            A.set(i, i, 1.);
          const Vector<double> rhs = load(system, system.n_dofs());
          Vector<double>       x(system.n_dofs());
          clock.restart();
          SparseLU direct;
          direct.factorize(A);
          direct.vmult(x, rhs);
          return clock.wall_time();
        }

        static double
        time_cholesky(const mechanics::ElasticitySystem<dim> &system)
        {
          Vector<double>            x = load(system, system.n_displacement_dofs());
          Timer                     clock;
          mechanics::SparseCholesky cholesky;
          cholesky.factorize(system.get_constrained_matrix(),
                             system.n_displacement_dofs(),
                             [](const double factor_mb) {
                               require_memory(factor_mb, "its factor", "factorize it", "");
                             });
          cholesky.solve(x);
          return clock.wall_time();
        }
      };

      template <int dim>
      std::unique_ptr<Postprocessor<dim>>
      make(const PhysicsParameters &p)
      {
        if (!p.mechanics.reports.linear_solve_time)
          return nullptr;
        return std::make_unique<LinearSolveTime<dim>>();
      }

      const std::string description = "the time of one linear elasticity solve on the mesh";
    } // namespace

    POROFRAC_REGISTER(PostprocessorRegistry<2>, "linear solve time", description, make<2>)
    POROFRAC_REGISTER(PostprocessorRegistry<3>, "linear solve time", description, make<3>)
  } // namespace app
} // namespace porofrac
