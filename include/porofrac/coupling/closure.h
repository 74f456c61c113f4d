// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_COUPLING_CLOSURE_H
#define POROFRAC_COUPLING_CLOSURE_H

#include <porofrac/flow/saturation_law.h>

#include <array>

namespace porofrac
{
  namespace coupling
  {
    /**
     * @name The closure (11d) of the coupled model: equivalent pressure, porosity, aperture, and
     * the Kozeny-Carman permeability of the porosity. These functions are the one place where
     * the coupled scene evaluates them.
     */
    /// @{

    /**
     * Equivalent pressure of eq. (11d), p_E = p^w (1 - S) + p^nw S - U(p_c)
     * = p^w + p_c S(p_c) - U(p_c), from the absolute wetting pressure @p p_w and the capillary
     * pressure @p p_c = p^nw - p^w, with the saturation law @p law and its capillary energy U of
     * eq. (6). With @p capillary_energy = false it is the modified definition of Remark 3.1 (no
     * U), to pair with the partially linearized accumulation of that remark.
     */
    double
    equivalent_pressure(const flow::SaturationLaw &law,
                        const double               p_w,
                        const double               p_c,
                        const bool                 capillary_energy = true);

    /// d p_E / d p^w and d p_E / d p^nw at capillary pressure @p p_c: (1 - S, S) with U (since
    /// U' = p_c S'), (1 - S - p_c S', S + p_c S') without.
    std::array<double, 2>
    equivalent_pressure_derivatives(const flow::SaturationLaw &law,
                                    const double               p_c,
                                    const bool                 capillary_energy = true);

    /// The part of the matrix porosity (11d) that the displacement sets: phi_0 + b div(u - u_0),
    /// @p div_u_change = div u - div u_0.
    inline double
    displacement_porosity(const double phi0, const double b, const double div_u_change)
    {
      return phi0 + b * div_u_change;
    }

    /// Matrix porosity of (11d): phi = phi_0 + b div(u - u_0) + (p_E - p_E0) / M, from
    /// @p phi_u = displacement_porosity() and @p p_E_change = p_E - p_E0.
    inline double
    porosity(const double phi_u, const double p_E_change, const double inverse_biot_modulus)
    {
      return phi_u + p_E_change * inverse_biot_modulus;
    }

    /// Fracture aperture of (11d): d_f = d_0 - [u]_n ([u]_n <= 0, so d_f >= d_0 when admissible).
    inline double
    aperture(const double d0, const double jump_n)
    {
      return d0 - jump_n;
    }

    /// Kozeny-Carman permeability K(phi) = K0 (1 - phi0)^2 / phi0^3 phi^3 / (1 - phi)^2, so that
    /// K(phi0) = K0, and dK/dphi.
    double
    kozeny_carman(const double K0, const double phi0, const double phi);
    double
    kozeny_carman_derivative(const double K0, const double phi0, const double phi);

    /// @}
  } // namespace coupling
} // namespace porofrac

#endif
