// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_MODEL_H
#define POROFRAC_FLOW_MODEL_H

#include <porofrac/flow/parameters.h>
#include <porofrac/flow/rock_type.h>
#include <porofrac/flow/tpfa_grid.h>
#include <porofrac/flow/two_phase_solver.h>
#include <porofrac/geometry/cut_mesh.h>

#include <array>
#include <functional>
#include <memory>

namespace porofrac
{
  namespace flow
  {
    /**
     * Everything a scene needs to run two-phase flow on a cut mesh, built from FlowParameters:
     * the two rock types, the TPFA grid with the initial porosity, permeability and aperture,
     * the Newton solver with its Dirichlet data and the initial state.
     */
    template <int dim>
    struct FlowModel
    {
      std::array<RockType, 2>              rocks;
      std::unique_ptr<TpfaGrid<dim>>       grid;
      std::unique_ptr<TwoPhaseSolver<dim>> solver;
      NewtonParameters                     newton;
      TimeStepping                         stepping;
      double                               initial_porosity     = 0; ///< phi_0
      double                               initial_permeability = 0; ///< K_0 (m^2)
      double                               initial_aperture     = 0; ///< d_0 (m)
      /// Neumann inflow through matrix boundary faces per face area (m/s by boundary id; total
      /// rates divided by the faces' area).
      FaceFlux matrix_flux;
    };

    /**
     * Builds the model of @p parameters on @p mesh, with the checks that need the mesh:
     * Dirichlet boundary ids on the mesh, source expressions of x, y (, z) finite at the cell
     * centres (InputErrors naming the parameter). @p adjust_newton, if given, may change the
     * Newton settings before the solver is built (coupled scenes tighten the tolerances). With
     * @p distributed the solver builds no serial Newton matrix: TwoPhaseSolver::distribute()
     * must follow.
     */
    template <int dim>
    FlowModel<dim>
    make_flow_model(const FlowParameters                          &parameters,
                    const geometry::CutMesh<dim>                  &mesh,
                    const std::function<void(NewtonParameters &)> &adjust_newton = {},
                    const bool                                     distributed   = false);
  } // namespace flow
} // namespace porofrac

#endif
