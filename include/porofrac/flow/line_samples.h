// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_LINE_SAMPLES_H
#define POROFRAC_FLOW_LINE_SAMPLES_H

#include <deal.II/base/point.h>

#include <porofrac/geometry/cut_mesh.h>

#include <string>
#include <vector>

namespace porofrac
{
  namespace flow
  {
    using namespace dealii;

    /// A segment along which cell values are sampled at equispaced points (end points included).
    template <int dim>
    struct SampleLine
    {
      std::string  name;
      Point<dim>   start, end;
      unsigned int n_points = 1000;
    };

    /// Parses "name: (x, y[, z]) (x, y[, z]) [n]; ..." (n >= 2, default 1000; names of letters,
    /// digits, '_' and '-'); errors name @p parameter.
    template <int dim>
    std::vector<SampleLine<dim>>
    parse_sample_lines(const std::string &text, const std::string &parameter);

    /**
     * The active cell index of a matrix cell containing each point of @p line (on a shared face,
     * any of its cells), numbers::invalid_unsigned_int for points outside the mesh. The search
     * starts from the previous point's cell and its neighbours and falls back to all cells.
     */
    template <int dim>
    std::vector<unsigned int>
    cells_along_line(const geometry::CutMesh<dim> &mesh, const SampleLine<dim> &line);
  } // namespace flow
} // namespace porofrac

#endif
