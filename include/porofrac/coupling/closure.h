// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_COUPLING_CLOSURE_H
#define POROFRAC_COUPLING_CLOSURE_H

#include <porofrac/flow/laws.h>

#include <array>

namespace porofrac
{
  namespace coupling
  {
    /**
     * Equivalent pressure of paper eq. (11d): p_E = p^nw S^nw + p^w (1 - S^nw) - U(p_c), with
     * p_c = p^nw - p^w. With @p capillary_energy = false it is the modified definition (8) of
     * Remark 3.1 (no U), to pair with the partially linearized accumulation (7).
     */
    double
    equivalent_pressure(const flow::SaturationLaw &law,
                        const double               p_w,
                        const double               p_nw,
                        const bool                 capillary_energy = true);

    /// d p_E / d p^w and d p_E / d p^nw (for Jacobians of the coupled map).
    std::array<double, 2>
    equivalent_pressure_derivatives(const flow::SaturationLaw &law,
                                    const double               p_w,
                                    const double               p_nw,
                                    const bool                 capillary_energy = true);

    /// Matrix porosity of (11d): phi = phi0 + b (div u - div u0) + (p_E - p_E0) / M.
    inline double
    porosity(const double phi0,
             const double b,
             const double div_u_change,
             const double p_E_change,
             const double M)
    {
      return phi0 + b * div_u_change + p_E_change / M;
    }

    /// Fracture aperture of (11d): d_f = d_0 - [u]_n ([u]_n <= 0, so d_f >= d_0 when admissible).
    inline double
    aperture(const double d0, const double jump_n)
    {
      return d0 - jump_n;
    }
  } // namespace coupling
} // namespace porofrac

#endif
