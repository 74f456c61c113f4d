// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_SATURATION_LAW_H
#define POROFRAC_FLOW_SATURATION_LAW_H

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
     * Saturation law S^nw(p_c) of one rock type (paper eq. (1)), with its derivative, its
     * capillary energy U(p_c) = int_0^{p_c} q S'(q) dq (paper eq. (6)) and its inverse.
     *
     * S vanishes up to the entry pressure p_e >= 0 and rises from 0 above it; S' jumps there (the
     * kink that the Newton iteration handles: kink stop, entry slope S'(p_e+), capillary bound
     * p_c >= p_e). Implementations give the law above p_e; this class returns S = S' = U = 0 for
     * p_c <= p_e. Pressures in Pa.
     *
     * An implementation is one source file that registers a factory in SaturationLawRegistry
     * with the deck entries it declares and parses (in the rock subsection, Flow/Matrix or
     * Flow/Fracture).
     */
    class SaturationLaw
    {
    public:
      virtual ~SaturationLaw() = default;

      /// Non-wetting saturation S^nw(p_c) in [0, 1).
      double
      saturation(const double p_c) const
      {
        return p_c <= p_e ? 0. : saturation_above_entry(p_c);
      }

      /// dS^nw/dp_c (0 for p_c <= p_e).
      double
      derivative(const double p_c) const
      {
        return p_c <= p_e ? 0. : derivative_above_entry(p_c);
      }

      /// The slope the Newton Jacobian uses where p_c <= p_e (Entry slope in Jacobian): the
      /// larger of the tangent S'(p_e+) and the secant S(p_e + scale)/scale. The secant keeps an
      /// absent phase's pressure coupled where the tangent vanishes (van Genuchten, n > 1).
      double
      entry_slope() const;

      /// Capillary energy U(p_c) of eq. (6); U'(p_c) = p_c S'(p_c).
      double
      energy(const double p_c) const
      {
        return p_c <= p_e ? 0. : energy_above_entry(p_c);
      }

      /// The p_c >= p_e with S^nw(p_c) = s, for s in [0, 1) (s = 0 gives p_e); an InputError
      /// naming @p parameter for any other s.
      double
      inverse(const double s, const std::string &parameter) const;

      /// Entry pressure p_e: S = 0 for p_c <= p_e (0 for laws without an entry pressure).
      double
      entry_pressure() const
      {
        return p_e;
      }

      /// The pressure over which S changes by O(1) (Corey R, van Genuchten P_r): the unit of the
      /// Newton iteration's capillary chop.
      double
      pressure_scale() const
      {
        return scale;
      }

    protected:
      SaturationLaw(const double entry_pressure, const double pressure_scale);

      /// S, S', U and the inverse for p_c > p_e, and for s in (0, 1).
      virtual double
      saturation_above_entry(const double p_c) const = 0;
      virtual double
      derivative_above_entry(const double p_c) const = 0;
      virtual double
      energy_above_entry(const double p_c) const = 0;
      virtual double
      inverse_above_entry(const double s) const = 0;

    private:
      const double p_e;
      const double scale;
    };

    /**
     * The saturation laws by name (deck entry "Saturation law" of a rock subsection). A factory
     * reads the law's entries in the rock subsection at @p path ({"Flow", "Matrix"}) and names
     * them in its InputErrors as "Flow/Matrix/<entry>".
     */
    using SaturationLawRegistry =
      Registry<SaturationLaw, const dealii::ParameterHandler &, const std::vector<std::string> &>;
  } // namespace flow
} // namespace porofrac

#endif
