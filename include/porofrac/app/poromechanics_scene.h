// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_POROMECHANICS_SCENE_H
#define POROFRAC_APP_POROMECHANICS_SCENE_H

#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/geometry/distributed_cut_mesh.h>
#include <porofrac/io/run_context.h>

#include <vector>

namespace porofrac
{
  namespace app
  {
    /**
     * A "poromechanics" deck: the coupled time loop of the paper's Section 4.2 (contact
     * mechanics and two-phase flow linked by (11d)), with history.csv per accepted step (the
     * energy estimate (19) among its columns), fractures.csv rows at t = 0, at the fracture
     * output times and at the final time, the field series poromechanics-NNNNN +
     * poromechanics.pvd, and the postprocessors the deck asks for.
     *
     * On the processes of a distributed context (context.communicator), @p cell_owner gives
     * the process of every cell: the flow's Newton systems are distributed as in a two-phase
     * flow scene, every process solves the same serial contact problem (or, given
     * @p distributed_mesh, the contact problem is distributed over its partition, which must be
     * @p cell_owner), and rank 0 writes the files (doc/parallel.md).
     */
    template <int dim>
    void
    run_poromechanics_scene(const PhysicsParameters                 &parameters,
                            const geometry::CutMesh<dim>            &mesh,
                            io::RunContext                          &context,
                            const std::vector<unsigned int>         &cell_owner       = {},
                            const geometry::DistributedCutMesh<dim> *distributed_mesh = nullptr);
  } // namespace app
} // namespace porofrac

#endif
