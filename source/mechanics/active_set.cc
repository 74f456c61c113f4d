// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/mechanics/contact_method.h>

#include <algorithm>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /**
       * The active-set method of paper Section 5.1: stick faces get [u]_tau = 0, slip faces
       * lambda_tau = F lambda_n w(a) with the slip direction w = a / |a|, a = lambda_tau + c
       * [u]_tau. In 2D w is a sign and the slip row is linear. In 3D the row is Newton-linearized
       * in a as well (doc/algorithms.md §2): with gamma = F lambda_n^k / |a^k| and the projection
       * P = I - w w^T onto the tangent orthogonal to w,
       *   (I - gamma P) lambda_tau^{k+1} - F w lambda_n^{k+1} - c gamma P [u]_tau^{k+1} = 0;
       * freezing w instead (gamma = 0) converges only linearly. Where gamma >= 1 the linearized
       * row loses its invertible lambda_tau block, and w is frozen.
       */
      template <int dim>
      class ActiveSet : public ContactMethod<dim>
      {
      protected:
        void
        stick_rows(const LocalContactLaw<dim> &law,
                   const Tensor<1, dim> &,
                   const double,
                   LocalRows<dim> &rows) const override
        {
          for (unsigned int i = 1; i < dim; ++i)
            rows.A_jump[i][i] = law.c;
        }

        void
        slip_rows(const LocalContactLaw<dim> &law,
                  const Tensor<1, dim>       &lambda,
                  const Tensor<1, dim>       &a,
                  const double,
                  LocalRows<dim> &rows) const override
        {
          this->frozen_direction_slip_rows(law, a, rows);
          const double na    = a.norm();
          const double gamma = (na > 0 ? law.F * std::max(lambda[0], 0.) / na : 0.);
          if (dim == 2 || gamma <= 0 || gamma >= 1)
            return;
          for (unsigned int i = 1; i < dim; ++i)
            for (unsigned int j = 1; j < dim; ++j)
              {
                const double P = (i == j ? 1. : 0.) - a[i] * a[j] / (na * na);
                rows.A_lambda[i][j] -= gamma * P;
                rows.A_jump[i][j] -= law.c * gamma * P;
              }
        }
      };

      const std::string description =
        "the active-set method of paper Section 5.1 (stick: [u]_tau = 0; slip: lambda_tau = F "
        "lambda_n w(a), in 3D with the slip direction w Newton-linearized).";
    } // namespace

    POROFRAC_REGISTER(ContactMethodRegistry<2>, "active set", description, [] {
      return std::make_unique<ActiveSet<2>>();
    })
    POROFRAC_REGISTER(ContactMethodRegistry<3>, "active set", description, [] {
      return std::make_unique<ActiveSet<3>>();
    })
  } // namespace mechanics
} // namespace porofrac
