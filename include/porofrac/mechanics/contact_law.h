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

    /// The nonlinear solver of the contact problem (paper Section 5.1, specs.md 3a).
    enum class ContactMethod
    {
      active_set,
      semismooth_newton
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

      /// State from the current iterate (specs.md 3a, ties |a| = F b count as stick).
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

      /**
       * Linear rows A_lambda lambda^{k+1} + A_jump [u]^{k+1} = rhs of the next iterate, with
       * coefficients at the current iterate (lambda, jump): Section 5.1 (active set) or the
       * regularized semi-smooth Newton of specs.md 3a.
       */
      FaceState
      rows(const ContactMethod   method,
           const Tensor<1, dim> &lambda,
           const Tensor<1, dim> &jump,
           Tensor<2, dim>       &A_lambda,
           Tensor<2, dim>       &A_jump,
           Tensor<1, dim>       &rhs) const
      {
        A_lambda                = 0;
        A_jump                  = 0;
        rhs                     = 0;
        const FaceState      st = state(lambda, jump);
        const double         bb = b(lambda, jump);
        const Tensor<1, dim> a  = tangential(lambda + c * jump);
        const double         na = a.norm();
        if (st == FaceState::open)
          {
            for (unsigned int i = 0; i < dim; ++i)
              A_lambda[i][i] = 1; // lambda = 0
            return st;
          }
        A_jump[0][0] = 1; // [u]_n = 0 (scaled by c below to balance units)
        A_jump[0][0] *= c;
        if (st == FaceState::stick)
          {
            for (unsigned int i = 1; i < dim; ++i)
              {
                A_jump[i][i] = c;
                if (method == ContactMethod::semismooth_newton)
                  {
                    // du^{k+1} + (du^k / b^k) lambda_n^{k+1} = du^k (specs.md 3a, stick)
                    A_lambda[i][0] = c * jump[i] / bb;
                    rhs[i]         = c * jump[i];
                  }
              }
            return st;
          }
        // slip
        const double s = F * bb;
        if (method == ContactMethod::active_set || s <= 1e-10)
          {
            // lambda_tau - F lambda_n w = 0, w = a^k/|a^k| frozen (Section 5.1).
            for (unsigned int i = 1; i < dim; ++i)
              {
                A_lambda[i][i] = 1;
                A_lambda[i][0] = (na > 0 ? -F * a[i] / na : 0.);
              }
            return st;
          }
        // Regularized semi-smooth Newton slip row (HSW 2008; specs.md 3a item 3), also in 2D:
        // there I - n n^T = 0, so the unregularized exact row would coincide with the active-set
        // row (specs.md 3a item 5), but M = (s/|a|)(1 - sign(a) lambda_tau / max(s, |lambda_tau|))
        // does not vanish while lambda_tau^k is off the friction bound. With the active-set row
        // instead, semi-smooth Newton from the open guess did not converge at c = 1e11 on 5.2.2
        // (paper: 9-10 iterations); with this one it takes 8 (doc/benchmarks/mechanics.md 8.7).
        const Tensor<1, dim> lt  = tangential(lambda);
        const double         nlt = lt.norm();
        const Tensor<1, dim> h   = lt * (s / std::max(s, nlt));
        Tensor<2, dim>       M;
        for (unsigned int i = 1; i < dim; ++i)
          for (unsigned int j = 1; j < dim; ++j)
            M[i][j] = (s / na) * ((i == j ? 1. : 0.) - lt[i] * a[j] / (std::max(s, nlt) * na));
        double beta = 1;
        if (nlt > 0)
          {
            const double alpha = (lt * a) / (nlt * na);
            const double delta = std::min(nlt / s, 1.);
            if (alpha < 0)
              beta = 1. / (1. - alpha * delta);
          }
        // Q = (I - beta M)^{-1} on the tangential block
        Tensor<2, dim> IbM;
        IbM[0][0] = 1;
        for (unsigned int i = 1; i < dim; ++i)
          for (unsigned int j = 1; j < dim; ++j)
            IbM[i][j] = (i == j ? 1. : 0.) - beta * M[i][j];
        const Tensor<2, dim> Q  = invert(IbM);
        const Tensor<1, dim> v  = Q * a / na;
        const Tensor<1, dim> Qh = Q * h;
        for (unsigned int i = 1; i < dim; ++i)
          {
            A_lambda[i][i] = 1;
            A_lambda[i][0] = -F * v[i];
            for (unsigned int j = 1; j < dim; ++j)
              A_jump[i][j] = -c * (Q[i][j] - (i == j ? 1. : 0.));
            rhs[i] = Qh[i] - s * v[i];
          }
        return st;
      }
    };
  } // namespace mechanics
} // namespace porofrac

#endif
