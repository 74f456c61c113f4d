// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/coupling/closure.h>

namespace porofrac
{
  namespace coupling
  {
    double
    equivalent_pressure(const flow::SaturationLaw &law,
                        const double               p_w,
                        const double               p_nw,
                        const bool                 capillary_energy)
    {
      const double p_c = p_nw - p_w;
      const double S   = law.saturation(p_c);
      return p_nw * S + p_w * (1 - S) - (capillary_energy ? law.energy(p_c) : 0.);
    }



    std::array<double, 2>
    equivalent_pressure_derivatives(const flow::SaturationLaw &law,
                                    const double               p_w,
                                    const double               p_nw,
                                    const bool                 capillary_energy)
    {
      // d/dp_c of (p_w + p_c S - U) = S + p_c S' - U' = S, since U' = p_c S'.
      const double p_c  = p_nw - p_w;
      const double S    = law.saturation(p_c);
      const double dSdp = law.derivative(p_c);
      const double d_pc = capillary_energy ? S : S + p_c * dSdp;
      return {{1. - d_pc, d_pc}};
    }
  } // namespace coupling
} // namespace porofrac
