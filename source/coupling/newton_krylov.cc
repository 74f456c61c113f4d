// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/coupling/newton_krylov.h>

#include <cmath>
#include <limits>

namespace porofrac
{
  namespace coupling
  {



    namespace
    {
      /// Records r = |g(x_k) - x_k| of iteration result.iterations (r0 at the first) and whether
      /// the plain or Anderson iteration stops: relative increment r/|x_k| or relative residual
      /// r/r0 below the tolerance.
      bool
      record_and_test(FixedPointResult &result,
                      const double      r,
                      double           &r0,
                      const double      x_norm,
                      const double      tolerance)
      {
        if (result.iterations == 1)
          r0 = r;
        result.residual_history.push_back(r);
        result.relative_residual  = r0 > 0 ? r / r0 : 0.;
        result.relative_increment = r / std::max(x_norm, std::numeric_limits<double>::min());
        return r == 0 || result.relative_increment <= tolerance ||
               (result.iterations > 1 && result.relative_residual <= tolerance);
      }
    } // namespace



    FixedPointSolver::FixedPointSolver(const FixedPointParameters &parameters)
        : parameters(parameters)
    {
    }



    FixedPointResult
    FixedPointSolver::solve(const Map &g, Vector<double> &x) const
    {
      if (parameters.method == "fixed point")
        return solve_plain(g, x);
      if (parameters.method == "anderson")
        return solve_anderson(g, x);
      return solve_newton_krylov(g, x);
    }



    FixedPointResult
    FixedPointSolver::solve_anderson(const Map &g, Vector<double> &x) const
    {
      // Anderson acceleration (Walker and Ni 2011, type II, no damping): with f_k = g(x_k) - x_k
      // and the differences dF, dG of the last m residuals and images,
      // gamma = argmin |f_k - dF gamma|, x_{k+1} = g(x_k) - dG gamma. Same stopping rules and
      // final state as the plain iteration (x = g(x_k) once |f_k| is small).
      FixedPointResult            result;
      const unsigned int          n = x.size();
      Vector<double>              gx(n), f(n), f_prev(n), g_prev(n);
      std::vector<Vector<double>> dF, dG;
      double                      r0 = 0;
      for (result.iterations = 1; result.iterations <= parameters.max_iterations;
           ++result.iterations)
        {
          g(x, gx);
          ++result.map_evaluations;
          f = gx;
          f -= x;
          if (record_and_test(result, f.l2_norm(), r0, x.l2_norm(), parameters.tolerance))
            {
              x                            = gx;
              result.converged             = true;
              result.evaluated_at_solution = true;
              return result;
            }
          if (result.iterations > 1)
            {
              dF.emplace_back(f);
              dF.back() -= f_prev;
              dG.emplace_back(gx);
              dG.back() -= g_prev;
              if (dF.size() > parameters.anderson_depth)
                {
                  dF.erase(dF.begin());
                  dG.erase(dG.begin());
                }
            }
          f_prev               = f;
          g_prev               = gx;
          x                    = gx;
          const unsigned int m = dF.size();
          if (m == 0)
            continue;
          // Normal equations of the small least-squares problem, with a relative Tikhonov
          // shift that keeps them solvable when the differences become dependent.
          FullMatrix<double> M(m, m);
          Vector<double>     b(m), gamma(m);
          double             trace = 0;
          for (unsigned int i = 0; i < m; ++i)
            {
              b(i) = dF[i] * f;
              for (unsigned int j = 0; j < m; ++j)
                M(i, j) = dF[i] * dF[j];
              trace += M(i, i);
            }
          for (unsigned int i = 0; i < m; ++i)
            M(i, i) += 1e-10 * trace / m;
          M.gauss_jordan();
          M.vmult(gamma, b);
          for (unsigned int i = 0; i < m; ++i)
            x.add(-gamma(i), dG[i]);
        }
      result.iterations = parameters.max_iterations;
      return result;
    }



    FixedPointResult
    FixedPointSolver::solve_plain(const Map &g, Vector<double> &x) const
    {
      FixedPointResult result;
      Vector<double>   gx(x.size());
      double           r0 = 0;
      for (result.iterations = 1; result.iterations <= parameters.max_iterations;
           ++result.iterations)
        {
          g(x, gx);
          ++result.map_evaluations;
          gx -= x; // now g(x) - x = -R(x) = the increment
          const bool done =
            record_and_test(result, gx.l2_norm(), r0, x.l2_norm(), parameters.tolerance);
          x += gx;
          if (done)
            {
              // The last evaluation was at x_prev, with g(x_prev) = x within the tolerance: the
              // states inside g are those of the accepted Picard iterate.
              result.converged             = true;
              result.evaluated_at_solution = true;
              return result;
            }
        }
      result.iterations = parameters.max_iterations;
      return result;
    }



    namespace
    {
      /// The Jacobian-free operator v -> (I - g'(x)) v by a forward difference around x.
      class FiniteDifferenceOperator
      {
      public:
        FiniteDifferenceOperator(const FixedPointSolver::Map &g,
                                 const Vector<double>        &x,
                                 const Vector<double>        &gx,
                                 unsigned int                &evaluations)
            : g(g)
            , x(x)
            , gx(gx)
            , evaluations(evaluations)
            , shifted(x.size())
            , g_shifted(x.size())
        {
        }

        void
        vmult(Vector<double> &dst, const Vector<double> &v) const
        {
          const double v_norm = v.l2_norm();
          if (v_norm == 0)
            {
              dst = 0;
              return;
            }
          const double eps =
            std::sqrt(std::numeric_limits<double>::epsilon()) * (1 + x.l2_norm()) / v_norm;
          shifted = x;
          shifted.add(eps, v);
          g(shifted, g_shifted);
          ++evaluations;
          // dst = v - (g(x + eps v) - g(x)) / eps
          dst = v;
          dst.add(-1. / eps, g_shifted, 1. / eps, gx);
        }

      private:
        const FixedPointSolver::Map &g;
        const Vector<double>        &x;
        const Vector<double>        &gx;
        unsigned int                &evaluations;
        mutable Vector<double>       shifted, g_shifted;
      };
    } // namespace



    FixedPointResult
    FixedPointSolver::solve_newton_krylov(const Map &g, Vector<double> &x) const
    {
      FixedPointResult result;
      Vector<double>   gx(x.size()), minus_residual(x.size()), dx(x.size());
      double           r0 = 0, r_previous = 0, eta = parameters.eta_max;
      for (result.iterations = 0; result.iterations < parameters.max_iterations;
           ++result.iterations)
        {
          g(x, gx);
          ++result.map_evaluations;
          minus_residual = gx;
          minus_residual -= x; // -R(x) = g(x) - x
          const double r = minus_residual.l2_norm();
          if (result.iterations == 0)
            r0 = r;
          result.residual_history.push_back(r);
          result.relative_residual = r0 > 0 ? r / r0 : 0.;
          if (r == 0 || (result.iterations > 0 && result.relative_residual <= parameters.tolerance))
            {
              result.converged             = true;
              result.evaluated_at_solution = true;
              return result;
            }

          // Eisenstat-Walker choice 2 with the usual safeguard.
          if (result.iterations > 0)
            {
              const double eta_new =
                parameters.ew_gamma * std::pow(r / r_previous, parameters.ew_alpha);
              const double floor = parameters.ew_gamma * std::pow(eta, parameters.ew_alpha);
              eta = std::min(parameters.eta_max, floor > 0.1 ? std::max(eta_new, floor) : eta_new);
            }
          r_previous = r;

          FiniteDifferenceOperator                    op(g, x, gx, result.map_evaluations);
          SolverControl                               control(parameters.max_gmres_iterations,
                                std::max(eta * r, 1e-300),
                                false,
                                false);
          SolverGMRES<Vector<double>>::AdditionalData data(parameters.gmres_restart + 2);
          SolverGMRES<Vector<double>>                 gmres(control, data);
          dx = 0;
          try
            {
              gmres.solve(op, dx, minus_residual, PreconditionIdentity());
            }
          catch (const SolverControl::NoConvergence &)
            {
              // Inexact Newton: use the best Krylov iterate reached.
            }
          result.gmres_iterations += control.last_step();
          x += dx;
          result.relative_increment =
            dx.l2_norm() / std::max(x.l2_norm(), std::numeric_limits<double>::min());
          if (result.relative_increment <= parameters.tolerance)
            {
              result.converged = true;
              ++result.iterations;
              return result;
            }
        }
      return result;
    }
  } // namespace coupling
} // namespace porofrac
