// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/parameter_handler.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/registry.h>
#include <porofrac/flow/rock_type.h>
#include <porofrac/flow/saturation_law.h>
#include <porofrac/io/text.h>

#include <cmath>
#include <memory>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      /// van Genuchten law: S = 1 - (1 + (p_c/P_r)^n)^(-m), m = 1 - 1/n, for p_c > 0; U by
      /// Gauss quadrature; pressure scale P_r, no entry pressure.
      class VanGenuchtenSaturation : public SaturationLaw
      {
      public:
        VanGenuchtenSaturation(const double P_r, const double n)
            : SaturationLaw(0., P_r)
            , P_r(P_r)
            , n(n)
        {
        }

      protected:
        double
        saturation_above_entry(const double p_c) const override
        {
          const double m = 1. - 1. / n;
          return 1. - std::pow(1. + std::pow(p_c / P_r, n), -m);
        }

        double
        derivative_above_entry(const double p_c) const override
        {
          const double m = 1. - 1. / n;
          const double x = p_c / P_r;
          return m * std::pow(1. + std::pow(x, n), -m - 1.) * n * std::pow(x, n - 1.) / P_r;
        }

        double
        energy_above_entry(const double p_c) const override
        {
          // U = p_c S(p_c) - int_0^{p_c} S; composite 5-point Gauss-Legendre on 200 intervals
          // (S'(q) ~ q^(n-1) near 0 is smooth for n > 1).
          static const double xg[5] = {
            -0.9061798459386640, -0.5384693101056831, 0., 0.5384693101056831, 0.9061798459386640};
          static const double wg[5]       = {0.2369268850561891,
                                             0.4786286704993665,
                                             0.5688888888888889,
                                             0.4786286704993665,
                                             0.2369268850561891};
          const unsigned int  n_intervals = 200;
          double              integral    = 0;
          for (unsigned int k = 0; k < n_intervals; ++k)
            {
              const double a = p_c * k / n_intervals, b = p_c * (k + 1) / n_intervals;
              for (unsigned int g = 0; g < 5; ++g)
                integral +=
                  0.5 * (b - a) * wg[g] * saturation(0.5 * (a + b) + 0.5 * (b - a) * xg[g]);
            }
          return p_c * saturation(p_c) - integral;
        }

        double
        inverse_above_entry(const double s) const override
        {
          const double m = 1. - 1. / n;
          return P_r * std::pow(std::pow(1. - s, -1. / m) - 1., 1. / n);
        }

      private:
        const double P_r;
        const double n;
      };

      void
      declare(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("van Genuchten P_r",
                          "1e6",
                          dealii::Patterns::Double(),
                          "van Genuchten pressure scale P_r (Pa).");
        prm.declare_entry("van Genuchten n",
                          "2",
                          dealii::Patterns::Double(),
                          "van Genuchten exponent n > 1 (-).");
      }

      std::unique_ptr<SaturationLaw>
      create(const dealii::ParameterHandler &prm, const std::vector<std::string> &path)
      {
        const double P_r = prm.get_double(path, "van Genuchten P_r");
        const double n   = prm.get_double(path, "van Genuchten n");
        check_input(P_r > 0 && std::isfinite(P_r),
                    entry_name(path, "van Genuchten P_r"),
                    "the van Genuchten pressure scale P_r must be positive, got " +
                      io::to_text(P_r));
        check_input(n > 1 && std::isfinite(n),
                    entry_name(path, "van Genuchten n"),
                    "the van Genuchten exponent n must be > 1, got " + io::to_text(n));
        return std::make_unique<VanGenuchtenSaturation>(P_r, n);
      }
    } // namespace

    POROFRAC_REGISTER(SaturationLawRegistry,
                      "van genuchten",
                      "S = 1 - (1 + (p_c/P_r)^n)^(1/n - 1) for p_c > 0, P_r = van Genuchten P_r, "
                      "n = van Genuchten n.",
                      create,
                      declare)
  } // namespace flow
} // namespace porofrac
