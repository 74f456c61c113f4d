// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_FLOW_OUTPUT_H
#define POROFRAC_FLOW_FLOW_OUTPUT_H

#include <porofrac/flow/tpfa_grid.h>
#include <porofrac/flow/two_phase_solver.h>
#include <porofrac/geometry/mesh_output.h>

namespace porofrac
{
  namespace flow
  {
    /// Matrix cell fields of the current state: p_w, p_nw, p_c, s_nw (Pa, Pa, Pa, -).
    template <int dim>
    geometry::CellFields
    matrix_fields(const TwoPhaseSolver<dim> &solver, const TpfaGrid<dim> &grid);

    /// Fracture cell fields of the current state, one value per fracture face: p_w, p_nw, p_c,
    /// s_nw and the aperture d_f (m).
    template <int dim>
    geometry::FractureFields
    fracture_fields(const TwoPhaseSolver<dim> &solver, const TpfaGrid<dim> &grid);

    /// The area-weighted mean of the fracture apertures d_f (paper Fig. 15); 0 without fractures.
    template <int dim>
    double
    mean_aperture(const geometry::CutMesh<dim> &mesh, const TpfaGrid<dim> &grid);
  } // namespace flow
} // namespace porofrac

#endif
