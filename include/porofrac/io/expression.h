// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_EXPRESSION_H
#define POROFRAC_IO_EXPRESSION_H

#include <deal.II/base/function_parser.h>

#include <memory>
#include <string>
#include <vector>

namespace porofrac
{
  namespace io
  {
    /**
     * A deck expression (muparser) of the coordinates x, y (, z), and optionally of one more
     * variable @p extra_variable passed as deal.II's "time" (e.g. the distance d to the
     * fracture tips), with the constant pi. One function component per expression.
     *
     * deal.II parses an expression on its first evaluation, not in initialize(): this function
     * evaluates every component once, so that a syntax error or an unknown variable becomes an
     * InputError naming @p parameter here, never an exception in the middle of a solve.
     */
    template <int dim>
    std::unique_ptr<dealii::FunctionParser<dim>>
    parse_expressions(const std::vector<std::string> &expressions,
                      const std::string              &parameter,
                      const std::string              &extra_variable = "");

    /// The variable names of parse_expressions: "x,y" or "x,y,z", plus @p extra_variable.
    template <int dim>
    std::string
    coordinate_variables(const std::string &extra_variable = "");
  } // namespace io
} // namespace porofrac

#endif
