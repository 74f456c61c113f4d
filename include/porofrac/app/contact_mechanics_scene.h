// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_CONTACT_MECHANICS_SCENE_H
#define POROFRAC_APP_CONTACT_MECHANICS_SCENE_H

#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/run_context.h>

namespace porofrac
{
  namespace app
  {
    /**
     * A "contact mechanics" deck: solves the static frictional contact problem, reports
     * iterations, face states and value ranges, writes fractures.csv and the VTU of the
     * fracture fields and the displacement, and runs the postprocessors the deck asks for.
     */
    template <int dim>
    void
    run_contact_mechanics_scene(const PhysicsParameters      &parameters,
                                const geometry::CutMesh<dim> &mesh,
                                io::RunContext               &context);
  } // namespace app
} // namespace porofrac

#endif
