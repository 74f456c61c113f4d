// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_BOUNDARY_ENTRIES_H
#define POROFRAC_GEOMETRY_BOUNDARY_ENTRIES_H

#include <deal.II/base/types.h>

#include <string>
#include <utility>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    /**
     * Splits "id: rest; id: rest; ..." (empty entries skipped) into (outer boundary id, rest)
     * pairs, in order. An entry without ':' (@p form names what one should look like), an id that
     * is not an integer in [0, first_fracture_boundary_id) or an id given twice is an InputError
     * naming @p parameter.
     */
    std::vector<std::pair<dealii::types::boundary_id, std::string>>
    split_boundary_entries(const std::string &text,
                           const std::string &parameter,
                           const std::string &form);
  } // namespace geometry
} // namespace porofrac

#endif
