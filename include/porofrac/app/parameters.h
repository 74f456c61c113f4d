// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_PARAMETERS_H
#define POROFRAC_APP_PARAMETERS_H

#include <deal.II/base/parameter_handler.h>

#include <set>
#include <string>
#include <vector>

namespace porofrac
{
  namespace app
  {
    /// Declares every parameter of every module: top level, Geometry, Output and the physics.
    void
    declare_all_parameters(dealii::ParameterHandler &prm);

    /// Of the @p assigned entry paths, those that a scene of @p physics never reads (entries
    /// of the subsections of other physics), for a warning.
    std::vector<std::string>
    unused_parameters(const std::set<std::string> &assigned, const std::string &physics);
  } // namespace app
} // namespace porofrac

#endif
