// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_SCENE_H
#define POROFRAC_FLOW_SCENE_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/flow/laws.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/run_context.h>

#include <array>
#include <map>
#include <string>

namespace porofrac
{
  namespace flow
  {
    /// Declares subsection "Flow" (laws, data, boundary conditions, Newton, time stepping).
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Reads the rock type in subsection Flow/@p name (Matrix or Fracture), validated.
    RockType
    parse_rock(const dealii::ParameterHandler &prm,
               const std::string              &name,
               const double                    mu_w,
               const double                    mu_nw);

    /**
     * Parses "id: p_w = v, p_nw = v; id: s_nw = v, p_nw = v; ..." (two of p_w, p_nw, s_nw, s_w
     * per id) into phase pressures with the saturation law of @p rock. Errors name @p parameter.
     */
    std::map<dealii::types::boundary_id, std::array<double, 2>>
    parse_dirichlet(const std::string &text, const RockType &rock, const std::string &parameter);

    /// Runs the flow-only time loop of a two-phase flow deck (Physics = two-phase flow).
    template <int dim>
    void
    run_scene(const dealii::ParameterHandler         &prm,
              const porofrac::geometry::CutMesh<dim> &mesh,
              porofrac::io::RunContext               &context);
  } // namespace flow
} // namespace porofrac

#endif
