// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/mechanics/contact_method.h>

#include <algorithm>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /// The regularized semi-smooth Newton method (Hueber, Stadler, Wohlmuth 2008; Berge et
      /// al. 2020; doc/algorithms.md §3).
      template <int dim>
      class SemismoothNewton : public ContactMethod<dim>
      {
      protected:
        /// du^{k+1} + (du^k / b^k) lambda_n^{k+1} = du^k, scaled by c.
        void
        stick_rows(const LocalContactLaw<dim> &law,
                   const Tensor<1, dim>       &jump,
                   const double                b,
                   LocalRows<dim>             &rows) const override
        {
          for (unsigned int i = 1; i < dim; ++i)
            {
              rows.A_jump[i][i]   = law.c;
              rows.A_lambda[i][0] = law.c * jump[i] / b;
              rows.rhs[i]         = law.c * jump[i];
            }
        }

        /**
         * The regularized slip row, also in 2D: there I - n n^T = 0, so the unregularized exact
         * row would coincide with the active-set row, but M = (s/|a|)(1 - sign(a) lambda_tau /
         * max(s, |lambda_tau|)) does not vanish while lambda_tau^k is off the friction bound.
         * With the active-set row instead, semi-smooth Newton from the open guess does not
         * converge at c = 1e11 on the 5.2.2 scene (doc/benchmarks/mechanics.md).
         */
        void
        slip_rows(const LocalContactLaw<dim> &law,
                  const Tensor<1, dim>       &lambda,
                  const Tensor<1, dim>       &a,
                  const double                b,
                  LocalRows<dim>             &rows) const override
        {
          const double F = law.F, c = law.c;
          const double s = F * b;
          if (s <= 1e-10)
            {
              // Degenerate friction bound (frictionless faces): lambda_tau = F lambda_n w.
              this->frozen_direction_slip_rows(law, a, rows);
              return;
            }
          const double         na  = a.norm();
          const Tensor<1, dim> lt  = LocalContactLaw<dim>::tangential(lambda);
          const double         nlt = lt.norm();
          // h: lambda_tau^k projected onto the ball of radius s.
          const Tensor<1, dim> h = lt * (s / std::max(s, nlt));
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
              rows.A_lambda[i][i] = 1;
              rows.A_lambda[i][0] = -F * v[i];
              for (unsigned int j = 1; j < dim; ++j)
                rows.A_jump[i][j] = -c * (Q[i][j] - (i == j ? 1. : 0.));
              rows.rhs[i] = Qh[i] - s * v[i];
            }
        }
      };

      const std::string description =
        "the regularized semi-smooth Newton method (Hueber, Stadler, Wohlmuth 2008; stick rows "
        "coupled to lambda_n, slip rows with the projected multiplier and damping).";
    } // namespace

    POROFRAC_REGISTER(ContactMethodRegistry<2>, "semismooth newton", description, [] {
      return std::make_unique<SemismoothNewton<2>>();
    })
    POROFRAC_REGISTER(ContactMethodRegistry<3>, "semismooth newton", description, [] {
      return std::make_unique<SemismoothNewton<3>>();
    })
  } // namespace mechanics
} // namespace porofrac
