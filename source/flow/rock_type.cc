// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/flow/rock_type.h>
#include <porofrac/io/text.h>

namespace porofrac
{
  namespace flow
  {
    void
    RockType::validate(const std::string &viscosity_section, const std::string &rock_section) const
    {
      check_input(viscosity[0] > 0,
                  viscosity_section + "/Viscosity w",
                  "viscosities must be positive, got " + io::to_text(viscosity[0]));
      check_input(viscosity[1] > 0,
                  viscosity_section + "/Viscosity nw",
                  "viscosities must be positive, got " + io::to_text(viscosity[1]));
      check_input(mobility_floor >= 0,
                  rock_section + "/Mobility floor",
                  "must be non-negative, got " + io::to_text(mobility_floor));
      check_input(saturation != nullptr, rock_section + "/Saturation law", "no law given");
      check_input(relative_permeability != nullptr,
                  rock_section + "/Relative permeability",
                  "no law given");
    }

    std::string
    entry_name(const std::vector<std::string> &path, const std::string &entry)
    {
      std::string name;
      for (const std::string &p : path)
        name += p + "/";
      return name + entry;
    }
  } // namespace flow
} // namespace porofrac
