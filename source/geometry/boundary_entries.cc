// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/boundary_entries.h>
#include <porofrac/geometry/cut_mesh.h>

#include <set>

namespace porofrac
{
  namespace geometry
  {
    std::vector<std::pair<types::boundary_id, std::string>>
    split_boundary_entries(const std::string &text,
                           const std::string &parameter,
                           const std::string &form)
    {
      std::vector<std::pair<types::boundary_id, std::string>> result;
      std::set<int>                                           seen;
      for (const std::string &entry : Utilities::split_string_list(text, ';'))
        {
          if (entry.empty())
            continue;
          const auto colon = entry.find(':');
          check_input(colon != std::string::npos,
                      parameter,
                      "expected '" + form + "', got '" + entry + "'");
          int id = -1;
          try
            {
              id = Utilities::string_to_int(Utilities::trim(entry.substr(0, colon)));
            }
          catch (...)
            {
            }
          check_input(id >= 0 && id < int(first_fracture_boundary_id),
                      parameter,
                      "bad boundary id in '" + entry + "' (0-" +
                        std::to_string(first_fracture_boundary_id - 1) + ")");
          check_input(seen.insert(id).second,
                      parameter,
                      "boundary id " + std::to_string(id) + " is given twice");
          result.emplace_back(id, Utilities::trim(entry.substr(colon + 1)));
        }
      return result;
    }
  } // namespace geometry
} // namespace porofrac
