// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_FRICTION_LAW_H
#define POROFRAC_MECHANICS_FRICTION_LAW_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/base/registry.h>

namespace porofrac
{
  namespace mechanics
  {
    /**
     * The friction coefficient F of the Coulomb conditions (25)-(26) on a fracture face. Every
     * law starts from the coefficient field F0(x, d) of the deck (Mechanics/Friction
     * coefficient: an expression of the coordinates and of the distance d to the fracture's
     * tips, per fracture id) and may make it depend on the face's slip |[u]_tau|; the contact
     * iterations then evaluate F at the slip of the current iterate (a lagged, fixed-point
     * treatment inside the nonlinear iteration).
     *
     * Implementations register in their own file with FrictionLawRegistry (deck entry
     * Mechanics/Friction law) and may declare and parse entries of their own in subsection
     * Mechanics; "coulomb" (F = F0) and "slip weakening" are built in.
     */
    class FrictionLaw
    {
    public:
      virtual ~FrictionLaw() = default;

      /// Reads this law's own entries of subsection Mechanics (those its registration
      /// declares) and checks them; InputError naming the entry.
      virtual void
      parse_parameters(const dealii::ParameterHandler &prm);

      /// F on a face with coefficient field value @p F0 and slip @p slip = |[u]_tau|.
      virtual double
      coefficient(const double F0, const double slip) const = 0;

      /// Whether coefficient() depends on the slip.
      virtual bool
      depends_on_slip() const = 0;

      /// Throws an InputError (naming Mechanics/Friction coefficient) if @p F0, the field's
      /// value on a face of fracture @p fracture_id, is not admissible for this law.
      virtual void
      check_coefficient(const double F0, const unsigned int fracture_id) const;
    };

    using FrictionLawRegistry = Registry<FrictionLaw>;
  } // namespace mechanics
} // namespace porofrac

#endif
