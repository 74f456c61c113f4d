// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_TWO_PHASE_FLOW_SCENE_H
#define POROFRAC_APP_TWO_PHASE_FLOW_SCENE_H

#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/run_context.h>

#include <vector>

namespace porofrac
{
  namespace app
  {
    /**
     * A "two-phase flow" deck: the flow-only time loop (porosity and apertures frozen), with
     * history.csv per accepted step, the field series flow-NNNNN + flow.pvd, and the phase
     * volumes, saturation ranges and mass balance in the report.
     *
     * On the processes of a distributed context (context.communicator), @p cell_owner gives
     * the process of every active cell and the Newton systems are shared
     * (TwoPhaseSolver::distribute()); every process runs the same time loop and rank 0 writes
     * the files.
     */
    template <int dim>
    void
    run_two_phase_flow_scene(const PhysicsParameters         &parameters,
                             const geometry::CutMesh<dim>    &mesh,
                             io::RunContext                  &context,
                             const std::vector<unsigned int> &cell_owner = {});
  } // namespace app
} // namespace porofrac

#endif
