// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/mechanics/contact_method.h>

namespace porofrac
{
  namespace mechanics
  {
    template <int dim>
    FaceState
    ContactMethod<dim>::rows(const LocalContactLaw<dim> &law,
                             const Tensor<1, dim>       &lambda,
                             const Tensor<1, dim>       &jump,
                             LocalRows<dim>             &rows) const
    {
      rows.A_lambda      = 0;
      rows.A_jump        = 0;
      rows.rhs           = 0;
      const FaceState st = law.state(lambda, jump);
      const double    b  = law.b(lambda, jump);
      if (st == FaceState::open)
        {
          for (unsigned int i = 0; i < dim; ++i)
            rows.A_lambda[i][i] = 1; // lambda = 0
          return st;
        }
      rows.A_jump[0][0] = 1; // [u]_n = 0, scaled by c to balance units
      rows.A_jump[0][0] *= law.c;
      if (st == FaceState::stick)
        stick_rows(law, jump, b, rows);
      else
        slip_rows(law, lambda, LocalContactLaw<dim>::tangential(lambda + law.c * jump), b, rows);
      return st;
    }



    template <int dim>
    void
    ContactMethod<dim>::frozen_direction_slip_rows(const LocalContactLaw<dim> &law,
                                                   const Tensor<1, dim>       &a,
                                                   LocalRows<dim>             &rows)
    {
      const double na = a.norm();
      for (unsigned int i = 1; i < dim; ++i)
        {
          rows.A_lambda[i][i] = 1;
          rows.A_lambda[i][0] = (na > 0 ? -law.F * a[i] / na : 0.);
        }
    }

    template class ContactMethod<2>;
    template class ContactMethod<3>;
  } // namespace mechanics
} // namespace porofrac
