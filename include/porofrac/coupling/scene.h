// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_COUPLING_SCENE_H
#define POROFRAC_COUPLING_SCENE_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/run_context.h>

namespace porofrac
{
  namespace coupling
  {
    /// Declares subsection "Coupling" (Biot data, fixed point, outputs of coupled scenes).
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Runs a poromechanics deck (paper Section 5.3): the initial contact state, then the time
     * loop of coupled steps with time-step cuts on failure; writes history.csv (iterations, mean
     * width, mass and energy balance per step), fractures.csv at the output times, VTU/PVD of the
     * bulk and fracture fields, and summary.json entries.
     */
    template <int dim>
    void
    run_scene(dealii::ParameterHandler               &prm,
              const porofrac::geometry::CutMesh<dim> &mesh,
              porofrac::io::RunContext               &context);
  } // namespace coupling
} // namespace porofrac

#endif
