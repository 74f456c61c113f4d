// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_LAWS_H
#define POROFRAC_FLOW_LAWS_H

#include <string>

namespace porofrac
{
  namespace flow
  {
    /**
     * Saturation law S^nw(p_c) of one rock type (paper, Section 3, eq. (1)), with its derivative
     * and its capillary energy U(p_c) = int_0^{p_c} q S'(q) dq (paper eq. (6)).
     *
     * - Corey (paper 5.3): S = max(1 - exp(-p_c/R), 0); U = R - (R + p_c) exp(-p_c/R), p_c > 0.
     * - van Genuchten: S = 1 - (1 + (p_c/P_r)^n)^(-m), m = 1 - 1/n, p_c > 0; U by Gauss quadrature
     *   of U = p_c S(p_c) - int_0^{p_c} S(q) dq.
     * Both vanish for p_c <= 0. Pressures in Pa.
     */
    class SaturationLaw
    {
    public:
      enum class Type
      {
        corey,
        van_genuchten
      };

      static SaturationLaw
      corey(const double R, const std::string &parameter = "Flow/Corey R");
      static SaturationLaw
      van_genuchten(const double       P_r,
                    const double       n,
                    const std::string &parameter = "Flow/van Genuchten");

      /// Non-wetting saturation S^nw(p_c).
      double
      saturation(const double p_c) const;
      /// dS^nw/dp_c.
      double
      derivative(const double p_c) const;
      /// Capillary energy U(p_c); U'(p_c) = p_c S'(p_c).
      double
      energy(const double p_c) const;
      /// The p_c >= 0 with S^nw(p_c) = s (s in [0, 1); s = 0 gives 0).
      double
      inverse(const double s, const std::string &parameter) const;

      Type   type = Type::corey;
      double R    = 1.;
      double P_r  = 1.;
      double n    = 2.;
    };

    /**
     * Relative permeabilities k_r^w, k_r^nw as functions of the non-wetting saturation s^nw,
     * with derivatives with respect to s^nw.
     * - linear: k_r^alpha(s^alpha) = s^alpha (paper 5.3, fractures);
     * - van Genuchten-Mualem with exponent q and residual saturations S_lr (liquid), S_gr (gas),
     *   s = (s^w - S_lr)/(1 - S_lr - S_gr) clipped to [0,1]:
     *   k_r^w = sqrt(s) (1 - (1 - s^(1/q))^q)^2, k_r^nw = sqrt(1 - s) (1 - s^(1/q))^(2q).
     */
    class RelativePermeability
    {
    public:
      enum class Type
      {
        linear,
        van_genuchten_mualem
      };

      static RelativePermeability
      linear();
      static RelativePermeability
      van_genuchten_mualem(const double       q,
                           const double       S_lr,
                           const double       S_gr,
                           const std::string &parameter = "Flow/Relative permeability");

      /// Phase 0 = wetting, 1 = non-wetting. Value and d/ds^nw.
      double
      value(const unsigned int phase, const double s_nw) const;
      double
      derivative(const unsigned int phase, const double s_nw) const;

      Type   type = Type::linear;
      double q    = 0.5;
      double S_lr = 0.;
      double S_gr = 0.;
    };

    /// Kozeny-Carman K(phi) = K0 (1-phi0)^2/phi0^3 phi^3/(1-phi)^2 (specs.md 1.1) and dK/dphi.
    double
    kozeny_carman(const double K0, const double phi0, const double phi);
    double
    kozeny_carman_derivative(const double K0, const double phi0, const double phi);

    /// One rock type: saturation law, relative permeabilities, and the two viscosities (Pa s).
    struct RockType
    {
      SaturationLaw        saturation;
      RelativePermeability relative_permeability;
      double               viscosity[2] = {1e-3, 1e-3};
      /// Added to k_r inside the mobility to keep the phase-pressure system non-singular where a
      /// phase is absent (specs.md 3b, item 3); 0 gives the exact law.
      double mobility_floor = 0.;
      /// The floor of the non-wetting phase (negative: mobility_floor).
      double mobility_floor_nw = -1.;

      /// Mobility eta^alpha = (k_r^alpha(s^nw) + floor) / mu^alpha and d eta/d s^nw.
      double
      mobility(const unsigned int phase, const double s_nw) const
      {
        const double floor =
          phase == 1 && mobility_floor_nw >= 0 ? mobility_floor_nw : mobility_floor;
        return (relative_permeability.value(phase, s_nw) + floor) / viscosity[phase];
      }
      double
      mobility_derivative(const unsigned int phase, const double s_nw) const
      {
        return relative_permeability.derivative(phase, s_nw) / viscosity[phase];
      }

      /// Throws InputError naming @p prefix + "/Viscosity ..." for non-positive viscosities.
      void
      validate(const std::string &prefix) const;
    };
  } // namespace flow
} // namespace porofrac

#endif
