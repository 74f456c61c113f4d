// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/io/text.h>
#include <porofrac/mechanics/friction_law.h>

#include <cmath>

namespace porofrac
{
  namespace mechanics
  {
    void
    FrictionLaw::parse_parameters(const dealii::ParameterHandler &)
    {
    }



    void
    FrictionLaw::check_coefficient(const double F0, const unsigned int fracture_id) const
    {
      check_input(F0 >= 0 && std::isfinite(F0),
                  "Mechanics/Friction coefficient",
                  "negative or invalid value " + io::to_text(F0) + " on fracture " +
                    std::to_string(fracture_id));
    }
  } // namespace mechanics
} // namespace porofrac
