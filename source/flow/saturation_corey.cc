// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/parameter_handler.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/registry.h>
#include <porofrac/flow/rock_type.h>
#include <porofrac/flow/saturation_law.h>
#include <porofrac/io/text.h>

#include <cmath>
#include <memory>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      /// Corey law of the paper's Section 5.3: S = 1 - exp(-p_c/R) for p_c > 0, with
      /// U = R - (R + p_c) exp(-p_c/R); pressure scale R, no entry pressure.
      class CoreySaturation : public SaturationLaw
      {
      public:
        explicit CoreySaturation(const double R)
            : SaturationLaw(0., R)
            , R(R)
        {
        }

      protected:
        double
        saturation_above_entry(const double p_c) const override
        {
          return 1. - std::exp(-p_c / R);
        }

        double
        derivative_above_entry(const double p_c) const override
        {
          return std::exp(-p_c / R) / R;
        }

        double
        energy_above_entry(const double p_c) const override
        {
          // U = R - (R + p_c) exp(-p_c/R), written without the cancellation that loses all
          // digits for p_c << R (the matrix at p_c ~ 1 kPa has R = 2e8 Pa).
          const double x = p_c / R;
          if (x < 1e-3)
            return R * x * x * (0.5 - x * (1. / 3. - x * (0.125 - x / 30.)));
          return R * (-std::expm1(-x) - x * std::exp(-x));
        }

        double
        inverse_above_entry(const double s) const override
        {
          return -R * std::log(1. - s);
        }

      private:
        const double R;
      };

      void
      declare(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Corey R",
                          rock_default("2e8", "1e2"),
                          dealii::Patterns::Double(),
                          "Corey pressure scale R (Pa).");
      }

      std::unique_ptr<SaturationLaw>
      create(const dealii::ParameterHandler &prm, const std::vector<std::string> &path)
      {
        const double R = prm.get_double(path, "Corey R");
        check_input(R > 0 && std::isfinite(R),
                    entry_name(path, "Corey R"),
                    "the Corey capillary pressure scale R must be positive, got " + io::to_text(R));
        return std::make_unique<CoreySaturation>(R);
      }
    } // namespace

    POROFRAC_REGISTER(SaturationLawRegistry,
                      "corey",
                      "S = max(1 - exp(-p_c/R), 0) (paper 5.3), R = Corey R.",
                      create,
                      declare)
  } // namespace flow
} // namespace porofrac
