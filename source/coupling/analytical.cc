// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/numbers.h>

#include <porofrac/coupling/analytical.h>

#include <cmath>

namespace porofrac
{
  namespace coupling
  {
    double
    Terzaghi::coefficient(const double permeability,
                          const double viscosity,
                          const double young_modulus,
                          const double poisson_ratio,
                          const double biot,
                          const double biot_modulus)
    {
      const double lambda =
        young_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
      const double mu = young_modulus / (2 * (1 + poisson_ratio));
      return permeability / viscosity / (biot * biot / (lambda + 2 * mu) + 1. / biot_modulus);
    }



    double
    Terzaghi::pressure(const double z, const double t) const
    {
      const double T   = consolidation * t / (height * height);
      double       sum = 0;
      for (unsigned int m = 0; m < 100000; ++m)
        {
          const double Mm   = (2 * m + 1) * dealii::numbers::PI / 2;
          const double term = 2. / Mm * std::sin(Mm * z / height) * std::exp(-Mm * Mm * T);
          sum += term;
          // Terms decay like exp(-Mm^2 T) / Mm: stop once they are negligible.
          if (std::exp(-Mm * Mm * T) / Mm < 1e-14)
            break;
        }
      return drained_pressure + (initial_pressure - drained_pressure) * sum;
    }
  } // namespace coupling
} // namespace porofrac
