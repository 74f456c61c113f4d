// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_CONTACT_METHOD_H
#define POROFRAC_MECHANICS_CONTACT_METHOD_H

#include <deal.II/base/tensor.h>

#include <porofrac/base/registry.h>
#include <porofrac/mechanics/contact_law.h>

namespace porofrac
{
  namespace mechanics
  {
    /// The face rows A_lambda lambda^{k+1} + A_jump [u]^{k+1} = rhs of one fracture face, in the
    /// face's local frame (component 0 normal, the others tangential).
    template <int dim>
    struct LocalRows
    {
      Tensor<2, dim> A_lambda;
      Tensor<2, dim> A_jump;
      Tensor<1, dim> rhs;
    };

    /**
     * A nonlinear method for the contact conditions (25)-(26): how each iteration linearizes
     * the face conditions at the current iterate (paper Section 5.1). The iteration around it
     * (ContactSolver) is the same for every method. Implementations register in their own file
     * with ContactMethodRegistry (deck entry Mechanics/Solver):
     * - "active set" (active_set.cc): the active-set method of Section 5.1;
     * - "semismooth newton" (semismooth_newton.cc): the regularized semi-smooth Newton method
     *   (doc/algorithms.md §3).
     *
     * Rows common to both: an open face gets lambda = 0; a face in contact gets [u]_n = 0
     * (scaled by c to balance the units of the multiplier rows).
     */
    template <int dim>
    class ContactMethod
    {
    public:
      virtual ~ContactMethod() = default;

      /// The rows of a face with multiplier @p lambda and jump @p jump (local frame) under
      /// @p law; returns the face state at this iterate (eq. (28)).
      FaceState
      rows(const LocalContactLaw<dim> &law,
           const Tensor<1, dim>       &lambda,
           const Tensor<1, dim>       &jump,
           LocalRows<dim>             &rows) const;

    protected:
      /// Tangential rows of a sticking face (b = lambda_n + c [u]_n > 0).
      virtual void
      stick_rows(const LocalContactLaw<dim> &law,
                 const Tensor<1, dim>       &jump,
                 const double                b,
                 LocalRows<dim>             &rows) const = 0;

      /// Tangential rows of a slipping face, a = lambda_tau + c [u]_tau.
      virtual void
      slip_rows(const LocalContactLaw<dim> &law,
                const Tensor<1, dim>       &lambda,
                const Tensor<1, dim>       &a,
                const double                b,
                LocalRows<dim>             &rows) const = 0;

      /// The slip rows of Section 5.1: lambda_tau - F lambda_n w = 0 with w = a / |a| frozen.
      static void
      frozen_direction_slip_rows(const LocalContactLaw<dim> &law,
                                 const Tensor<1, dim>       &a,
                                 LocalRows<dim>             &rows);
    };

    template <int dim>
    using ContactMethodRegistry = Registry<ContactMethod<dim>>;
  } // namespace mechanics
} // namespace porofrac

#endif
