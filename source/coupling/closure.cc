// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/coupling/closure.h>

namespace porofrac
{
  namespace coupling
  {
    double
    equivalent_pressure(const flow::SaturationLaw &law,
                        const double               p_w,
                        const double               p_c,
                        const bool                 capillary_energy)
    {
      return p_w + p_c * law.saturation(p_c) - (capillary_energy ? law.energy(p_c) : 0.);
    }

    std::array<double, 2>
    equivalent_pressure_derivatives(const flow::SaturationLaw &law,
                                    const double               p_c,
                                    const bool                 capillary_energy)
    {
      // d/dp_c of p^w + p_c S - U = S + p_c S' - U' = S, since U' = p_c S'.
      const double S = law.saturation(p_c);
      const double x = capillary_energy ? 0. : p_c * law.derivative(p_c);
      return {{1. - S - x, S + x}};
    }

    double
    kozeny_carman(const double K0, const double phi0, const double phi)
    {
      return K0 * (1. - phi0) * (1. - phi0) / (phi0 * phi0 * phi0) * phi * phi * phi /
             ((1. - phi) * (1. - phi));
    }

    double
    kozeny_carman_derivative(const double K0, const double phi0, const double phi)
    {
      const double c = K0 * (1. - phi0) * (1. - phi0) / (phi0 * phi0 * phi0);
      return c * (3. * phi * phi / ((1. - phi) * (1. - phi)) +
                  2. * phi * phi * phi / ((1. - phi) * (1. - phi) * (1. - phi)));
    }
  } // namespace coupling
} // namespace porofrac
