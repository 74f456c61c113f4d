// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_FLOW_OUTPUT_H
#define POROFRAC_FLOW_FLOW_OUTPUT_H

#include <porofrac/flow/tpfa_grid.h>
#include <porofrac/flow/two_phase_solver.h>
#include <porofrac/geometry/mesh_output.h>
#include <porofrac/io/checkpoint.h>
#include <porofrac/io/json.h>

#include <ostream>
#include <string>

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

    /// summary.json's flow_linear_solver: the solver of the Newton systems (@p name), its
    /// solves, Krylov iterations (0 for direct solvers), iterations per solve and direct
    /// fallbacks, over the whole run (a restarted run continues the counts of its checkpoint).
    io::Json
    linear_solver_summary(const std::string &name, const LinearSolverStatistics &statistics);

    /// The linear-solver statistics in a checkpoint (restarted runs continue the counts).
    void
    save_linear_statistics(io::CheckpointWriter &w, const LinearSolverStatistics &statistics);
    LinearSolverStatistics
    load_linear_statistics(io::CheckpointReader &r);

    /// Report lines of an iterative solver of the Newton systems (none for a direct one): the
    /// direct fallbacks, and whether the Krylov iterations per solve stayed below 30.
    void
    report_linear_solver(const std::string            &name,
                         const LinearSolverStatistics &statistics,
                         std::ostream                 &report);
  } // namespace flow
} // namespace porofrac

#endif
