// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_CONTACT_LAW_H
#define POROFRAC_MECHANICS_CONTACT_LAW_H

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    /// Contact state of a fracture face (paper eq. (28)).
    enum class FaceState : unsigned int
    {
      open  = 0,
      stick = 1,
      slip  = 2
    };

    /**
     * Local Coulomb law of one fracture face in local coordinates: component 0 is normal (along
     * n+), components 1..dim-1 tangential. lambda = -T+ (lambda_n >= 0 in contact), jump = [u]
     * (the face mean, paper eq. (10)), so [u]_n <= 0. Since the problems are static, the slip
     * increment is the jump itself (u at the previous time is zero).
     */
    template <int dim>
    struct LocalContactLaw
    {
      double F; ///< friction coefficient
      double c; ///< complementarity parameter

      static Tensor<1, dim>
      tangential(const Tensor<1, dim> &v)
      {
        Tensor<1, dim> t = v;
        t[0]             = 0;
        return t;
      }

      /// b = lambda_n + c [u]_n and a = lambda_tau + c [u]_tau.
      double
      b(const Tensor<1, dim> &lambda, const Tensor<1, dim> &jump) const
      {
        return lambda[0] + c * jump[0];
      }

      /// State from the current iterate (paper eq. (28); ties |a| = F b count as stick,
      /// doc/algorithms.md §3).
      FaceState
      state(const Tensor<1, dim> &lambda, const Tensor<1, dim> &jump) const
      {
        const double bb = b(lambda, jump);
        if (bb <= 0)
          return FaceState::open;
        // Frictionless contact (F = 0) is slip: the tangential multiplier is zero.
        if (F * bb <= 0)
          return FaceState::slip;
        const double na = tangential(lambda + c * jump).norm();
        return (na - F * bb > 1e-10 * F * bb) ? FaceState::slip : FaceState::stick;
      }

      /**
       * Complementarity functions (25)-(26): C_n = lambda_n - max(0, b),
       * C_tau = lambda_tau max(F b, |a|) - a max(0, F b). Returned in stress units (C_tau divided
       * by max(F b, |a|) when that is positive) for the stopping criterion when @p scaled is true.
       */
      Tensor<1, dim>
      residual(const Tensor<1, dim> &lambda,
               const Tensor<1, dim> &jump,
               const bool            scaled = false) const
      {
        const double         bb = b(lambda, jump);
        const Tensor<1, dim> a  = tangential(lambda + c * jump);
        const Tensor<1, dim> lt = tangential(lambda);
        const double         m  = std::max(F * bb, a.norm());
        Tensor<1, dim>       C  = lt * m - a * std::max(0., F * bb);
        if (scaled && m > 0)
          C /= m;
        C[0] = lambda[0] - std::max(0., bb);
        return C;
      }

      /**
       * Generalized Jacobian of residual() (unscaled): J_lambda = dC/dlambda, J_jump = dC/d[u].
       * Used by the unit test against finite differences.
       */
      void
      jacobian(const Tensor<1, dim> &lambda,
               const Tensor<1, dim> &jump,
               Tensor<2, dim>       &J_lambda,
               Tensor<2, dim>       &J_jump) const
      {
        J_lambda                = 0;
        J_jump                  = 0;
        const double         bb = b(lambda, jump);
        const Tensor<1, dim> a  = tangential(lambda + c * jump);
        const Tensor<1, dim> lt = tangential(lambda);
        const double         na = a.norm();
        if (bb > 0)
          J_jump[0][0] = -c;
        else
          J_lambda[0][0] = 1;
        const bool a_wins = na >= F * bb; // max(F b, |a|) = |a|
        for (unsigned int i = 1; i < dim; ++i)
          {
            if (a_wins)
              {
                J_lambda[i][i] += na;
                if (na > 0)
                  for (unsigned int j = 1; j < dim; ++j)
                    {
                      J_lambda[i][j] += lt[i] * a[j] / na;
                      J_jump[i][j] += lt[i] * a[j] / na * c;
                    }
              }
            else
              {
                J_lambda[i][i] += F * bb;
                J_lambda[i][0] += lt[i] * F;
                J_jump[i][0] += lt[i] * F * c;
              }
            if (bb > 0)
              {
                J_lambda[i][i] -= F * bb;
                J_jump[i][i] -= F * bb * c;
                J_lambda[i][0] -= a[i] * F;
                J_jump[i][0] -= a[i] * F * c;
              }
          }
      }
    };
  } // namespace mechanics
} // namespace porofrac

#endif
