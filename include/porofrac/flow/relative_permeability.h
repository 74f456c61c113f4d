// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_RELATIVE_PERMEABILITY_H
#define POROFRAC_FLOW_RELATIVE_PERMEABILITY_H

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace porofrac
{
  template <typename Interface, typename... Arguments>
  class Registry;

  namespace flow
  {
    /**
     * Relative permeabilities k_r^w, k_r^nw of one rock type as functions of the non-wetting
     * saturation s^nw (the mobilities eta^alpha = k_r^alpha / mu^alpha of scheme (11a)), with
     * their derivatives with respect to s^nw.
     *
     * An implementation is one source file that registers a factory in
     * RelativePermeabilityRegistry with the deck entries it declares and parses (in the rock
     * subsection).
     */
    class RelativePermeability
    {
    public:
      virtual ~RelativePermeability() = default;

      /// k_r of phase @p phase (0 = wetting, 1 = non-wetting) at s^nw = @p s_nw.
      virtual double
      value(const unsigned int phase, const double s_nw) const = 0;

      /// d k_r / d s^nw of phase @p phase.
      virtual double
      derivative(const unsigned int phase, const double s_nw) const = 0;
    };

    /**
     * The relative permeability laws by name (deck entry "Relative permeability" of a rock
     * subsection); factories as in SaturationLawRegistry.
     */
    using RelativePermeabilityRegistry = Registry<RelativePermeability,
                                                  const dealii::ParameterHandler &,
                                                  const std::vector<std::string> &>;
  } // namespace flow
} // namespace porofrac

#endif
