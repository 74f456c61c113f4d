// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/mechanics/contact_method.h>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /// The active-set method of paper Section 5.1: stick faces get [u]_tau = 0, slip faces
      /// lambda_tau = F lambda_n w with the slip direction w = a / |a| of the current iterate.
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
                  const Tensor<1, dim> &,
                  const Tensor<1, dim> &a,
                  const double,
                  LocalRows<dim> &rows) const override
        {
          this->frozen_direction_slip_rows(law, a, rows);
        }
      };

      const std::string description =
        "the active-set method of paper Section 5.1 (stick: [u]_tau = 0; slip: lambda_tau = F "
        "lambda_n w with the slip direction w of the current iterate).";
    } // namespace

    POROFRAC_REGISTER(ContactMethodRegistry<2>, "active set", description, [] {
      return std::make_unique<ActiveSet<2>>();
    })
    POROFRAC_REGISTER(ContactMethodRegistry<3>, "active set", description, [] {
      return std::make_unique<ActiveSet<3>>();
    })
  } // namespace mechanics
} // namespace porofrac
