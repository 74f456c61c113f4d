// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/mechanics/friction_law.h>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /// Coulomb friction with the deck's coefficient field: F = F0(x, d).
      class CoulombFriction : public FrictionLaw
      {
      public:
        double
        coefficient(const double F0, const double) const override
        {
          return F0;
        }

        bool
        depends_on_slip() const override
        {
          return false;
        }
      };
    } // namespace

    POROFRAC_REGISTER(FrictionLawRegistry,
                      "coulomb",
                      "F = Friction coefficient, an expression of x, y (, z) and d.",
                      [] { return std::make_unique<CoulombFriction>(); })
  } // namespace mechanics
} // namespace porofrac
