// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_FRACTURE_TABLE_H
#define POROFRAC_MECHANICS_FRACTURE_TABLE_H

#include <porofrac/mechanics/contact_problem.h>

#include <ostream>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /// "open", "stick" or "slip".
    const char *
    state_name(const FaceState state);

    /// Header of fractures.csv (design.md output contract), with a trailing `time` column if
    /// @p with_time.
    void
    write_fracture_table_header(std::ostream &out, const unsigned int dim, const bool with_time);

    /**
     * One row per fracture face: fracture_id, face_id, s, x, y[, z], jump_n, jump_t, lambda_n,
     * lambda_t, state, aperture[, time] in the local frame (n+, tangent) of the paper. The
     * aperture is @p aperture[f] when given, else max(0, -[u]_n) (the opening).
     */
    template <int dim>
    void
    write_fracture_table_rows(std::ostream              &out,
                              const ContactProblem<dim> &problem,
                              const std::vector<double> *aperture = nullptr,
                              const double              *time     = nullptr);
  } // namespace mechanics
} // namespace porofrac

#endif
