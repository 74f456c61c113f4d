// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_CONTACT_MECHANICS_SCENE_H
#define POROFRAC_APP_CONTACT_MECHANICS_SCENE_H

#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/geometry/distributed_cut_mesh.h>
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

    /**
     * The same on a distributed mesh (every process of context.communicator calls it): the
     * solve is distributed; the report, summary.json, fractures.csv and the fracture VTU come
     * from rank 0 (face values gathered there), the displacement is written as one VTU piece per
     * process with a .pvtu record. Postprocessors run on rank 0 on a serial ContactProblem that
     * holds the gathered state (doc/parallel.md).
     */
    template <int dim>
    void
    run_contact_mechanics_scene(const PhysicsParameters                 &parameters,
                                const geometry::DistributedCutMesh<dim> &mesh,
                                io::RunContext                          &context);
  } // namespace app
} // namespace porofrac

#endif
