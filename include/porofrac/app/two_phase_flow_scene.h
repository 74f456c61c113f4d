// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_TWO_PHASE_FLOW_SCENE_H
#define POROFRAC_APP_TWO_PHASE_FLOW_SCENE_H

#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/run_context.h>

namespace porofrac
{
  namespace app
  {
    /**
     * A "two-phase flow" deck: the flow-only time loop (porosity and apertures frozen), with
     * history.csv per accepted step, the field series flow-NNNNN + flow.pvd, and the phase
     * volumes, saturation ranges and mass balance in the report.
     */
    template <int dim>
    void
    run_two_phase_flow_scene(const PhysicsParameters      &parameters,
                             const geometry::CutMesh<dim> &mesh,
                             io::RunContext               &context);
  } // namespace app
} // namespace porofrac

#endif
