// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/io/text.h>
#include <porofrac/mechanics/friction_law.h>

#include <algorithm>
#include <cmath>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /**
       * Linear slip weakening (Ida 1972; Palmer and Rice 1973): the coefficient falls from its
       * static value F0(x, d) (Mechanics/Friction coefficient) to the dynamic value F_d over
       * the critical slip distance D_c,
       *   F(s) = F_d + (F0 - F_d) max(0, 1 - s / D_c),  s = |[u]_tau|.
       */
      class SlipWeakeningFriction : public FrictionLaw
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          prm.declare_entry("Dynamic friction coefficient",
                            "0",
                            dealii::Patterns::Double(0),
                            "Slip weakening: F_d, the coefficient once the slip exceeds the "
                            "critical slip distance (-); at most the static Friction coefficient.");
          prm.declare_entry("Critical slip distance",
                            "1e-3",
                            dealii::Patterns::Double(0),
                            "Slip weakening: D_c > 0, the slip over which F falls linearly from "
                            "the Friction coefficient to the dynamic one (m).");
        }

        void
        parse_parameters(const dealii::ParameterHandler &prm) override
        {
          dynamic_coefficient = prm.get_double({"Mechanics"}, "Dynamic friction coefficient");
          critical_slip       = prm.get_double({"Mechanics"}, "Critical slip distance");
          check_input(critical_slip > 0 && std::isfinite(critical_slip),
                      "Mechanics/Critical slip distance",
                      "must be positive, got " + io::to_text(critical_slip));
        }

        double
        coefficient(const double F0, const double slip) const override
        {
          return dynamic_coefficient +
                 (F0 - dynamic_coefficient) * std::max(0., 1. - slip / critical_slip);
        }

        bool
        depends_on_slip() const override
        {
          return true;
        }

        void
        check_coefficient(const double F0, const unsigned int fracture_id) const override
        {
          FrictionLaw::check_coefficient(F0, fracture_id);
          check_input(F0 >= dynamic_coefficient,
                      "Mechanics/Dynamic friction coefficient",
                      io::to_text(dynamic_coefficient) +
                        " exceeds the static Friction coefficient " + io::to_text(F0) +
                        " on fracture " + std::to_string(fracture_id));
        }

        double dynamic_coefficient = 0;
        double critical_slip       = 1e-3;
      };
    } // namespace

    POROFRAC_REGISTER(
      FrictionLawRegistry,
      "slip weakening",
      "F = F_d + (F0 - F_d) max(0, 1 - |[u]_tau| / D_c), F0 the Friction "
      "coefficient, F_d and D_c the entries below (linear slip weakening).",
      [] { return std::make_unique<SlipWeakeningFriction>(); },
      SlipWeakeningFriction::declare_parameters)
  } // namespace mechanics
} // namespace porofrac
