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
      /**
       * Brooks-Corey law with entry pressure p_e > 0 and pore-size index lambda > 0:
       * S = 1 - (p_e/p_c)^lambda for p_c > p_e, S' = (lambda/p_c) (p_e/p_c)^lambda, and, with
       * x = p_c/p_e, the capillary energy U = int_{p_e}^{p_c} q S'(q) dq
       *   = lambda p_e (x^(1 - lambda) - 1) / (1 - lambda)   (lambda != 1),
       *   = p_e ln x                                          (lambda = 1).
       * Pressure scale p_e.
       */
      class BrooksCoreySaturation : public SaturationLaw
      {
      public:
        BrooksCoreySaturation(const double p_e, const double lambda)
            : SaturationLaw(p_e, p_e)
            , p_e(p_e)
            , lambda(lambda)
        {
        }

      protected:
        double
        saturation_above_entry(const double p_c) const override
        {
          return 1. - std::pow(p_e / p_c, lambda);
        }

        double
        derivative_above_entry(const double p_c) const override
        {
          return lambda / p_c * std::pow(p_e / p_c, lambda);
        }

        double
        energy_above_entry(const double p_c) const override
        {
          const double log_x = std::log(p_c / p_e);
          if (lambda == 1.)
            return p_e * log_x;
          // x^(1 - lambda) - 1 = expm1((1 - lambda) ln x), accurate for lambda near 1 as well.
          return lambda * p_e * std::expm1((1. - lambda) * log_x) / (1. - lambda);
        }

        double
        inverse_above_entry(const double s) const override
        {
          return p_e * std::pow(1. - s, -1. / lambda);
        }

      private:
        const double p_e;
        const double lambda;
      };

      void
      declare(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Brooks-Corey entry pressure",
                          "1e4",
                          dealii::Patterns::Double(),
                          "Brooks-Corey entry pressure p_e > 0 (Pa).");
        prm.declare_entry("Brooks-Corey lambda",
                          "2",
                          dealii::Patterns::Double(),
                          "Brooks-Corey pore-size distribution index lambda > 0 (-).");
      }

      std::unique_ptr<SaturationLaw>
      create(const dealii::ParameterHandler &prm, const std::vector<std::string> &path)
      {
        const double p_e    = prm.get_double(path, "Brooks-Corey entry pressure");
        const double lambda = prm.get_double(path, "Brooks-Corey lambda");
        check_input(p_e > 0 && std::isfinite(p_e),
                    entry_name(path, "Brooks-Corey entry pressure"),
                    "the entry pressure must be positive, got " + io::to_text(p_e));
        check_input(lambda > 0 && std::isfinite(lambda),
                    entry_name(path, "Brooks-Corey lambda"),
                    "the pore-size distribution index must be positive, got " +
                      io::to_text(lambda));
        return std::make_unique<BrooksCoreySaturation>(p_e, lambda);
      }
    } // namespace

    POROFRAC_REGISTER(SaturationLawRegistry,
                      "brooks corey",
                      "S = 1 - (p_e/p_c)^lambda for p_c > p_e, 0 below, p_e = Brooks-Corey entry "
                      "pressure, lambda = Brooks-Corey lambda.",
                      create,
                      declare)
  } // namespace flow
} // namespace porofrac
