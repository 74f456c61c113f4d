// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/flow/saturation_law.h>
#include <porofrac/io/text.h>

#include <algorithm>

namespace porofrac
{
  namespace flow
  {
    SaturationLaw::SaturationLaw(const double entry_pressure, const double pressure_scale)
        : p_e(entry_pressure)
        , scale(pressure_scale)
    {
    }

    double
    SaturationLaw::entry_slope() const
    {
      const double tangent = derivative_above_entry(p_e + 1e-12 * scale);
      const double secant  = saturation_above_entry(p_e + scale) / scale;
      return std::max(tangent, secant);
    }

    double
    SaturationLaw::inverse(const double s, const std::string &parameter) const
    {
      check_input(
        s >= 0 && s < 1,
        parameter,
        "a non-wetting saturation must lie in [0, 1) to define a capillary pressure, got " +
          io::to_text(s));
      if (s == 0)
        return p_e;
      return inverse_above_entry(s);
    }
  } // namespace flow
} // namespace porofrac
