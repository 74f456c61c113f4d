// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/numbers.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/io/expression.h>

namespace porofrac
{
  namespace io
  {
    template <int dim>
    std::string
    coordinate_variables(const std::string &extra_variable)
    {
      const std::string xyz = (dim == 2 ? "x,y" : "x,y,z");
      return extra_variable.empty() ? xyz : xyz + "," + extra_variable;
    }



    template <int dim>
    std::unique_ptr<dealii::FunctionParser<dim>>
    parse_expressions(const std::vector<std::string> &expressions,
                      const std::string              &parameter,
                      const std::string              &extra_variable)
    {
      auto        function = std::make_unique<dealii::FunctionParser<dim>>(expressions.size());
      std::string text;
      for (const std::string &e : expressions)
        text += (text.empty() ? "'" : ", '") + e + "'";
      try
        {
          function->initialize(coordinate_variables<dim>(extra_variable),
                               expressions,
                               {{"pi", dealii::numbers::PI}},
                               !extra_variable.empty());
          for (unsigned int c = 0; c < expressions.size(); ++c)
            function->value(dealii::Point<dim>(), c);
        }
      catch (...)
        {
          throw InputError(parameter,
                           "cannot parse " + text + " as a muparser expression of " +
                             coordinate_variables<dim>(extra_variable));
        }
      return function;
    }

    template std::string
    coordinate_variables<2>(const std::string &);
    template std::string
    coordinate_variables<3>(const std::string &);
    template std::unique_ptr<dealii::FunctionParser<2>>
    parse_expressions(const std::vector<std::string> &, const std::string &, const std::string &);
    template std::unique_ptr<dealii::FunctionParser<3>>
    parse_expressions(const std::vector<std::string> &, const std::string &, const std::string &);
  } // namespace io
} // namespace porofrac
