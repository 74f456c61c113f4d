// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_COUPLING_NEWTON_KRYLOV_H
#define POROFRAC_COUPLING_NEWTON_KRYLOV_H


#include <deal.II/lac/vector.h>

#include <functional>
#include <vector>

namespace porofrac
{
  namespace coupling
  {
    using namespace dealii;

    /// Settings of the fixed-point solvers (deck subsection "Coupling", CouplingParameters).
    struct FixedPointParameters
    {
      /// "newton-krylov" (accelerated) or "fixed point" (plain Picard iterations).
      std::string method = "newton-krylov";
      /// Stop when ||x_{k+1} - x_k|| / ||x_k|| or ||R(x_k)|| / ||R(x_0)|| drops below this
      /// (paper, Section 5: 1e-6).
      double       tolerance      = 1e-6;
      unsigned int max_iterations = 30;
      /// GMRES restart length and iteration cap per Newton step.
      unsigned int gmres_restart        = 30;
      unsigned int max_gmres_iterations = 30;
      /// Eisenstat-Walker forcing terms (choice 2): eta_k = gamma (|R_k| / |R_{k-1}|)^alpha,
      /// capped by eta_max.
      double eta_max = 0.1;
      /// Anderson acceleration: number of stored differences.
      unsigned int anderson_depth = 5;
      double       ew_gamma       = 0.9;
      double       ew_alpha       = 2.0;
    };

    /// What a fixed-point solve did.
    struct FixedPointResult
    {
      bool                converged          = false;
      unsigned int        iterations         = 0; ///< Newton (or Picard) iterations
      unsigned int        map_evaluations    = 0; ///< calls of g, each a full subproblem solve
      unsigned int        gmres_iterations   = 0; ///< total Krylov iterations
      double              relative_residual  = 0; ///< ||R(x)|| / ||R(x_0)|| at the end
      double              relative_increment = 0; ///< last ||dx|| / ||x||
      std::vector<double> residual_history;       ///< ||R(x_k)||
      /// Whether the states inside g are those of the returned x: true for Newton-Krylov stopping
      /// on the residual (last evaluation at x) and for Picard (x = g(x_prev) within the
      /// tolerance); false for Newton-Krylov stopping on the increment, whose last evaluation
      /// was a shifted point of a Jacobian-vector product: a caller must evaluate g(x) again.
      bool evaluated_at_solution = false;
    };

    /**
     * Solves x = g(x), e.g. p_E = g_p(p_E) or u = g_u(u) of the paper's Section 5, either by plain
     * fixed-point iterations or by Jacobian-free Newton-Krylov on R(x) = x - g(x): each Newton
     * step solves (I - g'(x_k)) dx = g(x_k) - x_k by GMRES with the finite-difference products
     * g'(x) v ~ (g(x + eps v) - g(x)) / eps, eps = sqrt(eps_mach) (1 + |x|) / |v|, to the
     * Eisenstat-Walker relative tolerance. Each product costs one evaluation of g, so inner
     * solvers must be converged tightly (well below sqrt(eps_mach) relative) for the differences
     * to be meaningful.
     */
    class FixedPointSolver
    {
    public:
      /// g(x) -> gx. May throw (e.g. SolverFailure of an inner solve); the exception propagates.
      using Map = std::function<void(const Vector<double> &x, Vector<double> &gx)>;

      explicit FixedPointSolver(const FixedPointParameters &parameters);

      /// Iterates from @p x (the initial guess) and leaves the last iterate in @p x.
      FixedPointResult
      solve(const Map &g, Vector<double> &x) const;

    private:
      FixedPointResult
      solve_plain(const Map &g, Vector<double> &x) const;
      FixedPointResult
      solve_newton_krylov(const Map &g, Vector<double> &x) const;
      FixedPointResult
      solve_anderson(const Map &g, Vector<double> &x) const;

      const FixedPointParameters parameters;
    };
  } // namespace coupling
} // namespace porofrac

#endif
