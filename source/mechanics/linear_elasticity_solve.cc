// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/mumps_factorization.h>
#include <porofrac/mechanics/elasticity_amg.h>
#include <porofrac/mechanics/linear_elasticity_solve.h>

#include <memory>
#include <sstream>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    namespace
    {
      using VectorType = TrilinosWrappers::MPI::Vector;

      /// CG with ElasticityAmg on K_constrained delta = rhs.
      template <int dim>
      void
      solve_by_amg_cg(const DistributedElasticitySystem<dim> &system,
                      const ContactParameters                &parameters,
                      const VectorType                       &rhs,
                      VectorType                             &delta,
                      LinearElasticitySolve                  &result)
      {
        Timer                    clock;
        const ElasticityAmg<dim> amg(system, parameters.amg_smoothed_prolongator);
        result.set_up_time = clock.wall_time();
        clock.restart();
        SolverControl        control(parameters.max_linear_iterations,
                              parameters.linear_tolerance * rhs.l2_norm(),
                              false,
                              false);
        SolverCG<VectorType> cg(control);
        try
          {
            cg.solve(system.get_constrained_matrix(), delta, rhs, amg);
          }
        catch (const SolverControl::NoConvergence &)
          {
            std::ostringstream failure;
            failure << "CG did not reach " << parameters.linear_tolerance << " in "
                    << parameters.max_linear_iterations << " iterations";
            result.converged = false;
            result.failure   = failure.str();
            delta            = 0;
          }
        result.solve_time = clock.wall_time();
        result.iterations = control.last_step();
      }

      /// MUMPS factorization and solve of K_constrained delta = rhs.
      template <int dim>
      void
      solve_by_mumps(const DistributedElasticitySystem<dim> &system,
                     const VectorType                       &rhs,
                     VectorType                             &delta,
                     LinearElasticitySolve                  &result)
      {
        Timer              clock;
        MumpsFactorization lu("linear elasticity (open fractures)");
        try
          {
            lu.factorize(system.get_constrained_matrix());
            result.set_up_time = clock.wall_time();
            clock.restart();
            lu.solve(delta, rhs);
          }
        catch (const SolverFailure &failure)
          {
            result.converged = false;
            result.failure   = failure.what();
            delta            = 0;
          }
        result.solve_time = clock.wall_time();
      }
    } // namespace

    template <int dim>
    LinearElasticitySolve
    solve_linear_elasticity(const DistributedElasticitySystem<dim> &system,
                            const ContactParameters                &parameters)
    {
      // u = u_D + delta with K_constrained delta = f - K u_D (zero on constrained rows): one
      // Newton step of the problem without contact, exact since it is linear.
      LinearElasticitySolve result;
      VectorType           &u = result.displacement;
      VectorType            lambda, rhs(system.owned_displacements(), system.get_communicator());
      system.initial_displacement(u);
      system.reinit_multipliers(lambda);
      system.mechanical_rhs(u, lambda, rhs);
      rhs.compress(VectorOperation::insert);
      VectorType delta(rhs);
      delta         = 0;
      result.solver = parameters.distributed_linear_solver == "iterative" ? "AMG-CG" : "MUMPS";
      if (result.solver == "AMG-CG")
        solve_by_amg_cg(system, parameters, rhs, delta, result);
      else
        solve_by_mumps(system, rhs, delta, result);
      u += delta;
      return result;
    }

    template LinearElasticitySolve
    solve_linear_elasticity(const DistributedElasticitySystem<2> &, const ContactParameters &);
    template LinearElasticitySolve
    solve_linear_elasticity(const DistributedElasticitySystem<3> &, const ContactParameters &);
  } // namespace mechanics
} // namespace porofrac
