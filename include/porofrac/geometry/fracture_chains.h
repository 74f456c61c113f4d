// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_FRACTURE_CHAINS_H
#define POROFRAC_GEOMETRY_FRACTURE_CHAINS_H

#include <porofrac/geometry/raw_mesh.h>

#include <array>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    /**
     * Orders the faces of each fracture along its polyline (2D): for each raw fracture face,
     * its (first, second) vertices in the direction of travel and the abscissa of the first.
     * The start is the end nearest the deck's first point, else the lexicographically smallest.
     * In 3D the faces keep their vertex order and abscissa 0. Fills @p fracture_ids with the
     * fracture ids in increasing order.
     */
    template <int dim>
    void
    chain_fractures(const RawMesh<dim>                         &raw,
                    std::vector<std::array<unsigned int, dim>> &oriented,
                    std::vector<double>                        &s_begin,
                    std::vector<unsigned int>                  &fracture_ids);
  } // namespace geometry
} // namespace porofrac

#endif
