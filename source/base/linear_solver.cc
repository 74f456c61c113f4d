// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/linear_solver.h>
#include <porofrac/base/registry.h>

namespace porofrac
{
  std::unique_ptr<SerialLinearSolver>
  create_serial_linear_solver(const std::string &name, const std::string &parameter)
  {
    return SerialLinearSolverRegistry::instance().create(name, parameter);
  }
} // namespace porofrac
