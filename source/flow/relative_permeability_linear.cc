// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/registry.h>
#include <porofrac/flow/relative_permeability.h>

#include <algorithm>
#include <memory>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      /// k_r^alpha(s^alpha) = s^alpha, clipped to [0, 1] (paper 5.3, fractures).
      class LinearRelativePermeability : public RelativePermeability
      {
      public:
        double
        value(const unsigned int phase, const double s_nw) const override
        {
          const double s = (phase == 0 ? 1. - s_nw : s_nw);
          return std::clamp(s, 0., 1.);
        }

        double
        derivative(const unsigned int phase, const double s_nw) const override
        {
          const double s = (phase == 0 ? 1. - s_nw : s_nw);
          if (s < 0 || s > 1)
            return 0.;
          return phase == 0 ? -1. : 1.;
        }
      };
    } // namespace

    POROFRAC_REGISTER(RelativePermeabilityRegistry,
                      "linear",
                      "k_r^alpha = s^alpha.",
                      [](const dealii::ParameterHandler &, const std::vector<std::string> &) {
                        return std::make_unique<LinearRelativePermeability>();
                      })
  } // namespace flow
} // namespace porofrac
