// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_PARAMETERS_H
#define POROFRAC_APP_PARAMETERS_H

#include <deal.II/base/parameter_handler.h>

namespace porofrac
{
  namespace app
  {
    /// Declares every parameter of every module: top level, Geometry, Output and the physics.
    void
    declare_all_parameters(dealii::ParameterHandler &prm);
  } // namespace app
} // namespace porofrac

#endif
