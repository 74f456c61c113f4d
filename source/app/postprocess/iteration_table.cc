// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/app/contact_report.h>
#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/io/json.h>
#include <porofrac/mechanics/contact_method.h>

#include <iomanip>
#include <sstream>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /**
       * The paper's iteration tables (Tables 1-4) on the scene's mesh (deck entry
       * Mechanics/Iteration table): every contact method x c in {1e6, 1e9, 1e11} x initial
       * guess, each a cold solve (ContactProblem::set_contact_solver()) sharing the mesh-only
       * data of the problem (K, its factors, W). Leaves the last cell's solution in the problem.
       */
      template <int dim>
      class IterationTable : public Postprocessor<dim>
      {
      public:
        void
        execute(SceneView<dim> &scene, io::RunContext &context) override
        {
          context.progress << "*** Iteration table (12 cold solves)" << std::endl;
          io::Json table = io::Json::array();
          for (const std::string method : {"active set", "semismooth newton"})
            for (const bool stick : {true, false})
              for (const double c : {1e6, 1e9, 1e11})
                table.push_back(solve(*scene.mechanics, method, stick, c, context));
          context.summary["mechanics"]["iteration_table"] = table;
        }

        bool
        changes_state() const override
        {
          return true;
        }

        bool
        needs_system_matrices() const override
        {
          return true;
        }

      private:
        io::Json
        solve(mechanics::ContactProblem<dim> &problem,
              const std::string              &method,
              const bool                      stick,
              const double                    c,
              io::RunContext                 &context) const
        {
          problem.set_contact_solver(method, c, stick);
          Timer       clock;
          std::string failure;
          try
            {
              problem.solve();
            }
          catch (const SolverFailure &e)
            {
              failure = e.what();
            }
          const mechanics::ContactStatistics &s    = problem.statistics();
          mechanics::ContactParameters        cell = problem.get_parameters();
          cell.method                              = method;
          cell.stick_guess                         = stick;
          cell.c                                   = c;
          io::Json r                               = summarize_contact_iterations(cell, s);
          r["last_residual"] = s.residual_history.empty() ? 0. : s.residual_history.back();
          r["wall_time_s"]   = clock.wall_time();
          if (!failure.empty())
            r["failure"] = failure;
          std::ostringstream line;
          line << "Mechanics: iteration table: " << method << ", " << (stick ? "stick" : "open")
               << " guess, c = " << std::scientific << std::setprecision(0) << c << ": "
               << (s.converged ? "converged" : "not converged") << " in " << s.iterations
               << " iterations";
          context.report << line.str() << std::endl;
          context.progress << "    " << line.str() << " (" << std::defaultfloat
                           << std::setprecision(3) << clock.wall_time() << " s)" << std::endl;
          return r;
        }
      };

      template <int dim>
      std::unique_ptr<Postprocessor<dim>>
      make(const PhysicsParameters &p)
      {
        if (!p.mechanics.reports.iteration_table)
          return nullptr;
        return std::make_unique<IterationTable<dim>>();
      }

      const std::string description = "the iteration tables of paper Tables 1-4";
    } // namespace

    POROFRAC_REGISTER(PostprocessorRegistry<2>, "iteration table", description, make<2>)
    POROFRAC_REGISTER(PostprocessorRegistry<3>, "iteration table", description, make<3>)
  } // namespace app
} // namespace porofrac
