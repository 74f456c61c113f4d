// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_MODEL_H
#define POROFRAC_FLOW_MODEL_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/flow/laws.h>
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
    /// Time stepping of deck subsection "Flow": dt_{k+1/2} = min(rho dt_{k-1/2}, dt_max).
    struct TimeStepping
    {
      double       final_time   = 1;
      double       initial_step = 1;
      double       maximum_step = 1;
      double       growth       = 1.1;
      unsigned int maximum_cuts = 20;
      unsigned int output_every = 1;
    };

    /**
     * Everything a scene needs to run two-phase flow on a cut mesh, built from deck subsection
     * "Flow": the two rock types, the TPFA grid with the initial porosity, permeability and
     * aperture, the Newton solver with its Dirichlet data and the initial state.
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
    };

    /**
     * Reads and validates subsection "Flow" and builds the model on @p mesh. @p adjust_newton,
     * if given, may change the Newton settings read from the deck before the solver is built
     * (coupled scenes tighten the tolerances).
     */
    template <int dim>
    FlowModel<dim>
    make_flow_model(const dealii::ParameterHandler                &prm,
                    const geometry::CutMesh<dim>                  &mesh,
                    const std::function<void(NewtonParameters &)> &adjust_newton = {});
  } // namespace flow
} // namespace porofrac

#endif
