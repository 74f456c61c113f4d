// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_SCENE_H
#define POROFRAC_MECHANICS_SCENE_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/run_context.h>
#include <porofrac/mechanics/parameters.h>

namespace porofrac
{
  namespace mechanics
  {
    /// Declares subsection "Mechanics" (elasticity data, boundary conditions, contact solver).
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Reads and validates subsection "Mechanics" into ContactParameters.
    ContactParameters
    parse_parameters(const dealii::ParameterHandler &prm, const unsigned int dim);

    /**
     * Solves the static frictional contact problem of a "contact mechanics" deck, reports
     * iterations, face states and (5.2.1) errors against the analytical solution, writes
     * fractures.csv and a VTU of the displacement.
     */
    template <int dim>
    void
    run_scene(const dealii::ParameterHandler         &prm,
              const porofrac::geometry::CutMesh<dim> &mesh,
              porofrac::io::RunContext               &context);
  } // namespace mechanics
} // namespace porofrac

#endif
