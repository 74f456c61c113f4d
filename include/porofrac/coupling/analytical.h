// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_COUPLING_ANALYTICAL_H
#define POROFRAC_COUPLING_ANALYTICAL_H

namespace porofrac
{
  namespace coupling
  {
    /**
     * Terzaghi's one-dimensional consolidation with the storage law of (11d): a column of height
     * H, drained (p = p_top) at z = 0, impervious and fixed at z = H, laterally confined, under a
     * constant total vertical load, starting from a uniform excess pressure p0 - p_top. With
     * phi - phi_0 = b div(u - u_0) + (p - p_0)/M and Darcy velocity -k/mu grad p, the pressure
     * solves dp/dt = c_v d2p/dz2 with the consolidation coefficient
     *   c_v = (k / mu) / (b^2 / (lambda + 2 mu_s) + 1 / M),
     * and p(z, t) = p_top + sum_m (2 (p0 - p_top) / M_m) sin(M_m z / H) exp(-M_m^2 c_v t / H^2),
     * M_m = (2m + 1) pi / 2.
     */
    struct Terzaghi
    {
      double height;           ///< H (m)
      double consolidation;    ///< c_v (m^2/s)
      double initial_pressure; ///< p0 (Pa)
      double drained_pressure; ///< p_top (Pa)

      static double
      coefficient(const double permeability,
                  const double viscosity,
                  const double young_modulus,
                  const double poisson_ratio,
                  const double biot,
                  const double biot_modulus);

      /// Pressure at depth z below the drained boundary and time t (series to 1e-14 relative).
      double
      pressure(const double z, const double t) const;
    };
  } // namespace coupling
} // namespace porofrac

#endif
