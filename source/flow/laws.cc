// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/flow/laws.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      std::string
      str(const double x)
      {
        std::ostringstream s;
        s << x;
        return s.str();
      }
    } // namespace

    SaturationLaw
    SaturationLaw::corey(const double R, const std::string &parameter)
    {
      check_input(R > 0 && std::isfinite(R),
                  parameter,
                  "the Corey capillary pressure scale R must be positive, got " + str(R));
      SaturationLaw law;
      law.type = Type::corey;
      law.R    = R;
      return law;
    }

    SaturationLaw
    SaturationLaw::van_genuchten(const double P_r, const double n, const std::string &parameter)
    {
      check_input(P_r > 0 && std::isfinite(P_r),
                  parameter,
                  "the van Genuchten pressure scale P_r must be positive, got " + str(P_r));
      check_input(n > 1 && std::isfinite(n),
                  parameter,
                  "the van Genuchten exponent n must be > 1, got " + str(n));
      SaturationLaw law;
      law.type = Type::van_genuchten;
      law.P_r  = P_r;
      law.n    = n;
      return law;
    }

    double
    SaturationLaw::saturation(const double p_c) const
    {
      if (p_c <= 0)
        return 0.;
      if (type == Type::corey)
        return 1. - std::exp(-p_c / R); // paper 5.3
      const double m = 1. - 1. / n;
      return 1. - std::pow(1. + std::pow(p_c / P_r, n), -m);
    }

    double
    SaturationLaw::derivative(const double p_c) const
    {
      if (p_c <= 0)
        return 0.;
      if (type == Type::corey)
        return std::exp(-p_c / R) / R;
      const double m = 1. - 1. / n;
      const double x = p_c / P_r;
      return m * std::pow(1. + std::pow(x, n), -m - 1.) * n * std::pow(x, n - 1.) / P_r;
    }

    double
    SaturationLaw::energy(const double p_c) const
    {
      if (p_c <= 0)
        return 0.;
      if (type == Type::corey)
        {
          // U = R - (R + p_c) exp(-p_c/R) (specs.md 1.2), written without the cancellation that
          // loses all digits for p_c << R (the matrix at p_c ~ 1 kPa has R = 2e8 Pa).
          const double x = p_c / R;
          if (x < 1e-3)
            return R * x * x * (0.5 - x * (1. / 3. - x * (0.125 - x / 30.)));
          return R * (-std::expm1(-x) - x * std::exp(-x));
        }
      // U = p_c S(p_c) - int_0^{p_c} S; composite 5-point Gauss-Legendre on a graded partition
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
            integral += 0.5 * (b - a) * wg[g] * saturation(0.5 * (a + b) + 0.5 * (b - a) * xg[g]);
        }
      return p_c * saturation(p_c) - integral;
    }

    double
    SaturationLaw::inverse(const double s, const std::string &parameter) const
    {
      check_input(
        s >= 0 && s < 1,
        parameter,
        "a non-wetting saturation must lie in [0, 1) to define a capillary pressure, got " +
          str(s));
      if (s == 0)
        return 0.;
      if (type == Type::corey)
        return -R * std::log(1. - s);
      const double m = 1. - 1. / n;
      return P_r * std::pow(std::pow(1. - s, -1. / m) - 1., 1. / n);
    }

    RelativePermeability
    RelativePermeability::linear()
    {
      return RelativePermeability();
    }

    RelativePermeability
    RelativePermeability::van_genuchten_mualem(const double       q,
                                               const double       S_lr,
                                               const double       S_gr,
                                               const std::string &parameter)
    {
      check_input(q > 0 && q < 1,
                  parameter + "/q",
                  "the Mualem exponent q must lie in (0, 1), got " + str(q));
      check_input(S_lr >= 0 && S_gr >= 0,
                  parameter + "/S_lr",
                  "residual saturations must be non-negative, got S_lr = " + str(S_lr) +
                    ", S_gr = " + str(S_gr));
      check_input(S_lr + S_gr < 1,
                  parameter + "/S_lr",
                  "S_lr + S_gr must be < 1, got S_lr + S_gr = " + str(S_lr + S_gr));
      RelativePermeability kr;
      kr.type = Type::van_genuchten_mualem;
      kr.q    = q;
      kr.S_lr = S_lr;
      kr.S_gr = S_gr;
      return kr;
    }

    double
    RelativePermeability::value(const unsigned int phase, const double s_nw) const
    {
      if (type == Type::linear)
        {
          const double s = (phase == 0 ? 1. - s_nw : s_nw);
          return std::clamp(s, 0., 1.);
        }
      const double s = std::clamp((1. - s_nw - S_lr) / (1. - S_lr - S_gr), 0., 1.);
      const double B = 1. - std::pow(s, 1. / q);
      if (phase == 0)
        {
          const double A = 1. - std::pow(B, q);
          return std::sqrt(s) * A * A;
        }
      return std::sqrt(1. - s) * std::pow(B, 2. * q);
    }

    double
    RelativePermeability::derivative(const unsigned int phase, const double s_nw) const
    {
      if (type == Type::linear)
        {
          const double s = (phase == 0 ? 1. - s_nw : s_nw);
          if (s < 0 || s > 1)
            return 0.;
          return phase == 0 ? -1. : 1.;
        }
      const double s_raw = (1. - s_nw - S_lr) / (1. - S_lr - S_gr);
      if (s_raw <= 0 || s_raw >= 1)
        return 0.;
      // The curves have infinite slopes at s -> 1 (q < 1): evaluate the slope slightly inside.
      const double s     = std::min(s_raw, 1. - 1e-12);
      const double ds    = -1. / (1. - S_lr - S_gr);
      const double sq    = std::pow(s, 1. / q);
      const double B     = 1. - sq;
      const double dB_ds = -sq / (q * s);
      if (phase == 0)
        {
          const double A     = 1. - std::pow(B, q);
          const double dA_ds = -q * std::pow(B, q - 1.) * dB_ds;
          return ds * (0.5 / std::sqrt(s) * A * A + std::sqrt(s) * 2. * A * dA_ds);
        }
      return ds * (-0.5 / std::sqrt(1. - s) * std::pow(B, 2. * q) +
                   std::sqrt(1. - s) * 2. * q * std::pow(B, 2. * q - 1.) * dB_ds);
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

    void
    RockType::validate(const std::string &prefix) const
    {
      check_input(viscosity[0] > 0,
                  prefix + "/Viscosity w",
                  "viscosities must be positive, got " + str(viscosity[0]));
      check_input(viscosity[1] > 0,
                  prefix + "/Viscosity nw",
                  "viscosities must be positive, got " + str(viscosity[1]));
      check_input(mobility_floor >= 0,
                  prefix + "/Mobility floor",
                  "must be non-negative, got " + str(mobility_floor));
    }
  } // namespace flow
} // namespace porofrac
