// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/parameter_handler.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/registry.h>
#include <porofrac/flow/relative_permeability.h>
#include <porofrac/flow/rock_type.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      /**
       * van Genuchten-Mualem relative permeabilities with exponent q and residual saturations
       * S_lr (liquid), S_gr (gas): with s = (s^w - S_lr)/(1 - S_lr - S_gr) clipped to [0, 1],
       *   k_r^w = sqrt(s) (1 - (1 - s^(1/q))^q)^2,   k_r^nw = sqrt(1 - s) (1 - s^(1/q))^(2q).
       */
      class VanGenuchtenMualem : public RelativePermeability
      {
      public:
        VanGenuchtenMualem(const double q, const double S_lr, const double S_gr)
            : q(q)
            , S_lr(S_lr)
            , S_gr(S_gr)
        {
        }

        double
        value(const unsigned int phase, const double s_nw) const override
        {
          const double s = std::clamp((1. - s_nw - S_lr) / (1. - S_lr - S_gr), 0., 1.);
          const double B = 1. - std::pow(s, 1. / q);
          if (phase == 0)
            {
              const double A = 1. - std::pow(B, q);
              return std::sqrt(s) * A * A;
            }
          return std::sqrt(1. - s) * std::pow(B, 2. * q);
        }

        double
        derivative(const unsigned int phase, const double s_nw) const override
        {
          const double s_raw = (1. - s_nw - S_lr) / (1. - S_lr - S_gr);
          if (s_raw <= 0 || s_raw >= 1)
            return 0.;
          // The curves have infinite slopes at s -> 1 (q < 1): evaluate the slope slightly
          // inside.
          const double s     = std::min(s_raw, 1. - 1e-12);
          const double ds    = -1. / (1. - S_lr - S_gr);
          const double sq    = std::pow(s, 1. / q);
          const double B     = 1. - sq;
          const double dB_ds = -sq / (q * s);
          if (phase == 0)
            {
              const double A     = 1. - std::pow(B, q);
              const double dA_ds = -q * std::pow(B, q - 1.) * dB_ds;
              return ds * (0.5 / std::sqrt(s) * A * A + std::sqrt(s) * 2. * A * dA_ds);
            }
          return ds * (-0.5 / std::sqrt(1. - s) * std::pow(B, 2. * q) +
                       std::sqrt(1. - s) * 2. * q * std::pow(B, 2. * q - 1.) * dB_ds);
        }

      private:
        const double q, S_lr, S_gr;
      };

      void
      declare(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Mualem q",
                          "0.328",
                          dealii::Patterns::Double(),
                          "Mualem exponent q in (0,1) (-).");
        prm.declare_entry("S_lr",
                          "0.35",
                          dealii::Patterns::Double(),
                          "Residual liquid saturation (-).");
        prm.declare_entry("S_gr", "0", dealii::Patterns::Double(), "Residual gas saturation (-).");
      }

      std::unique_ptr<RelativePermeability>
      create(const dealii::ParameterHandler &prm, const std::vector<std::string> &path)
      {
        const double q    = prm.get_double(path, "Mualem q");
        const double S_lr = prm.get_double(path, "S_lr");
        const double S_gr = prm.get_double(path, "S_gr");
        check_input(q > 0 && q < 1,
                    entry_name(path, "Mualem q"),
                    "the Mualem exponent q must lie in (0, 1), got " + io::to_text(q));
        check_input(S_lr >= 0 && S_gr >= 0,
                    entry_name(path, "S_lr"),
                    "residual saturations must be non-negative, got S_lr = " + io::to_text(S_lr) +
                      ", S_gr = " + io::to_text(S_gr));
        check_input(S_lr + S_gr < 1,
                    entry_name(path, "S_lr"),
                    "S_lr + S_gr must be < 1, got S_lr + S_gr = " + io::to_text(S_lr + S_gr));
        return std::make_unique<VanGenuchtenMualem>(q, S_lr, S_gr);
      }
    } // namespace

    POROFRAC_REGISTER(RelativePermeabilityRegistry,
                      "van genuchten-mualem",
                      "k_r^w = sqrt(s) (1 - (1 - s^(1/q))^q)^2, k_r^nw = sqrt(1 - s) (1 - "
                      "s^(1/q))^(2q), s = (s^w - S_lr)/(1 - S_lr - S_gr) clipped to [0, 1], q = "
                      "Mualem q.",
                      create,
                      declare)
  } // namespace flow
} // namespace porofrac
