// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/parameter_handler.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/registry.h>
#include <porofrac/flow/relative_permeability.h>
#include <porofrac/flow/rock_type.h>
#include <porofrac/io/text.h>

#include <cmath>
#include <memory>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      /// Corey power laws k_r^alpha = (s^alpha)^(n_alpha), s^alpha clipped to [0, 1], with
      /// exponents n_alpha >= 1 (n_w = n_nw = 1 is the linear law).
      class CoreyRelativePermeability : public RelativePermeability
      {
      public:
        CoreyRelativePermeability(const double n_w, const double n_nw)
            : exponent{n_w, n_nw}
        {
        }

        double
        value(const unsigned int phase, const double s_nw) const override
        {
          const double s = phase == 0 ? 1. - s_nw : s_nw;
          if (s <= 0)
            return 0.;
          return s >= 1 ? 1. : std::pow(s, exponent[phase]);
        }

        double
        derivative(const unsigned int phase, const double s_nw) const override
        {
          const double s = phase == 0 ? 1. - s_nw : s_nw;
          if (s < 0 || s > 1)
            return 0.;
          const double dk_ds = exponent[phase] * std::pow(s, exponent[phase] - 1.);
          return phase == 0 ? -dk_ds : dk_ds;
        }

      private:
        const double exponent[2];
      };

      void
      declare(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Corey exponent w",
                          "2",
                          dealii::Patterns::Double(),
                          "Exponent n_w >= 1 of the Corey wetting relative permeability (-).");
        prm.declare_entry("Corey exponent nw",
                          "2",
                          dealii::Patterns::Double(),
                          "Exponent n_nw >= 1 of the Corey non-wetting relative permeability (-).");
      }

      std::unique_ptr<RelativePermeability>
      create(const dealii::ParameterHandler &prm, const std::vector<std::string> &path)
      {
        double n[2];
        for (unsigned int phase = 0; phase < 2; ++phase)
          {
            const std::string entry = phase == 0 ? "Corey exponent w" : "Corey exponent nw";
            n[phase]                = prm.get_double(path, entry);
            check_input(n[phase] >= 1 && std::isfinite(n[phase]),
                        entry_name(path, entry),
                        "the exponent must be >= 1 (a bounded slope at s = 0), got " +
                          io::to_text(n[phase]));
          }
        return std::make_unique<CoreyRelativePermeability>(n[0], n[1]);
      }
    } // namespace

    POROFRAC_REGISTER(RelativePermeabilityRegistry,
                      "corey",
                      "k_r^alpha = (s^alpha)^(n_alpha), n_w = Corey exponent w, n_nw = Corey "
                      "exponent nw.",
                      create,
                      declare)
  } // namespace flow
} // namespace porofrac
