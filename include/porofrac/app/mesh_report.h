// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_MESH_REPORT_H
#define POROFRAC_APP_MESH_REPORT_H

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/run_context.h>

namespace porofrac
{
  namespace app
  {
    /// Prints the mesh report (cells, vertices, fracture faces per fracture, angles, TPFA
    /// admissibility) to context.report and stores it in context.summary["mesh"].
    template <int dim>
    void
    report_mesh(const geometry::CutMesh<dim> &mesh, io::RunContext &context);
  } // namespace app
} // namespace porofrac

#endif
