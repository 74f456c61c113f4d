// SPDX-License-Identifier: LGPL-2.1-or-later
// The fixed-point solvers of the coupling on maps whose fixed points are known:
// 1. a contraction g(x) = A x + b + 0.1 sin(x) (Lipschitz constant at most 0.8): plain iterations
// and
//    Newton-Krylov converge to the same point, Newton-Krylov in far fewer iterations;
// 2. an expansive affine map g(x) = -1.5 x + c (plain iterations diverge): Newton-Krylov finds
//    x* = c / 2.5 in one Newton step (the second iteration only confirms it), since the
//    finite-difference Jacobian of an affine map is exact;
// 3. Anderson acceleration on both: the contraction's fixed point in fewer map evaluations
//    than plain iterations, and the expansive affine map (where plain iterations diverge), since
//    one secant difference captures a scalar multiple of the identity.
#include <deal.II/lac/vector.h>

#include <porofrac/coupling/newton_krylov.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace porofrac::coupling;

int
main()
{
  std::cout << std::scientific << std::setprecision(3);
  const unsigned int n = 50;

  // 1. A contraction: A is tridiagonal with 0.4 on the diagonal and 0.15 off it.
  auto contraction = [n](const Vector<double> &x, Vector<double> &gx) {
    for (unsigned int i = 0; i < n; ++i)
      {
        gx[i] = 0.4 * x[i] + 1.0 + 0.1 * std::sin(x[i]) + 0.01 * i;
        if (i > 0)
          gx[i] += 0.15 * x[i - 1];
        if (i + 1 < n)
          gx[i] += 0.15 * x[i + 1];
      }
  };
  FixedPointParameters parameters;
  parameters.tolerance      = 1e-10;
  parameters.max_iterations = 500;
  Vector<double> x_plain(n), x_nk(n), check(n);
  parameters.method = "fixed point";
  const auto plain  = FixedPointSolver(parameters).solve(contraction, x_plain);
  parameters.method = "newton-krylov";
  const auto nk     = FixedPointSolver(parameters).solve(contraction, x_nk);
  contraction(x_nk, check);
  check -= x_nk;
  Vector<double> difference = x_nk;
  difference -= x_plain;
  std::cout << "contraction: fixed point converged " << plain.converged << " in "
            << plain.iterations << " iterations" << std::endl
            << "contraction: Newton-Krylov converged " << nk.converged << " in " << nk.iterations
            << " Newton iterations, fewer than fixed point: " << (nk.iterations < plain.iterations)
            << std::endl
            << "contraction: |x - g(x)| at the Newton-Krylov solution: "
            << (check.l2_norm() < 1e-9 ? "below 1e-9" : "too large") << std::endl
            << "contraction: |x_NK - x_FP| / |x_FP| below 1e-8: "
            << (difference.l2_norm() / x_plain.l2_norm() < 1e-8) << std::endl;

  // 2. An expansive affine map.
  auto expansive = [n](const Vector<double> &x, Vector<double> &gx) {
    for (unsigned int i = 0; i < n; ++i)
      gx[i] = -1.5 * x[i] + (1.0 + i);
  };
  Vector<double> y_plain(n), y_nk(n);
  parameters.method         = "fixed point";
  parameters.max_iterations = 40;
  const auto plain2         = FixedPointSolver(parameters).solve(expansive, y_plain);
  parameters.method         = "newton-krylov";
  const auto nk2            = FixedPointSolver(parameters).solve(expansive, y_nk);
  double     error          = 0;
  for (unsigned int i = 0; i < n; ++i)
    error = std::max(error, std::abs(y_nk[i] - (1.0 + i) / 2.5));
  std::cout << "expansive map: fixed point converged " << plain2.converged << std::endl
            << "expansive map: Newton-Krylov converged " << nk2.converged << " in "
            << nk2.iterations << " Newton iterations, max error below 1e-8: " << (error < 1e-8)
            << std::endl;

  // 3. Anderson acceleration.
  parameters.method         = "anderson";
  parameters.max_iterations = 500;
  Vector<double> x_and(n), y_and(n);
  const auto     and1 = FixedPointSolver(parameters).solve(contraction, x_and);
  difference          = x_and;
  difference -= x_plain;
  std::cout << "contraction: Anderson converged " << and1.converged << " in "
            << and1.map_evaluations << " map evaluations, fewer than fixed point: "
            << (and1.map_evaluations < plain.map_evaluations)
            << ", |x_A - x_FP| / |x_FP| below 1e-8: "
            << (difference.l2_norm() / x_plain.l2_norm() < 1e-8) << std::endl;
  parameters.max_iterations = 40;
  const auto and2           = FixedPointSolver(parameters).solve(expansive, y_and);
  error                     = 0;
  for (unsigned int i = 0; i < n; ++i)
    error = std::max(error, std::abs(y_and[i] - (1.0 + i) / 2.5));
  std::cout << "expansive map: Anderson converged " << and2.converged << " in "
            << and2.map_evaluations << " map evaluations, max error below 1e-8: " << (error < 1e-8)
            << std::endl;
}
