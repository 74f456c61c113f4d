// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_SCENE_H
#define POROFRAC_FLOW_SCENE_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/run_context.h>


namespace porofrac
{
  namespace flow
  {
    /// Runs the flow-only time loop of a two-phase flow deck (Physics = two-phase flow).
    template <int dim>
    void
    run_scene(const dealii::ParameterHandler         &prm,
              const porofrac::geometry::CutMesh<dim> &mesh,
              porofrac::io::RunContext               &context);
  } // namespace flow
} // namespace porofrac

#endif
