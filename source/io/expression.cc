// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/numbers.h>

#include <deal.II/lac/vector.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/quiet_standard_error.h>
#include <porofrac/io/expression.h>
#include <porofrac/io/text.h>

#include <cmath>
#include <new>

namespace porofrac
{
  namespace io
  {
    namespace
    {
      /**
       * A deck expression that refuses to return a non-finite value: sqrt(-1), 1/0 or an
       * overflow becomes an InputError naming the parameter, the expression and the point,
       * instead of a NaN that a solver would report as a failed convergence.
       */
      template <int dim>
      class FiniteFunctionParser : public dealii::FunctionParser<dim>
      {
      public:
        FiniteFunctionParser(const std::vector<std::string> &expressions,
                             const std::string              &parameter,
                             const std::string              &extra_variable)
            : dealii::FunctionParser<dim>(expressions.size())
            , expressions(expressions)
            , parameter(parameter)
            , extra_variable(extra_variable)
        {
        }

        double
        value(const dealii::Point<dim> &p, const unsigned int component = 0) const override
        {
          const double v = dealii::FunctionParser<dim>::value(p, component);
          check(v, p, component);
          return v;
        }

        void
        vector_value(const dealii::Point<dim> &p, dealii::Vector<double> &values) const override
        {
          dealii::FunctionParser<dim>::vector_value(p, values);
          for (unsigned int c = 0; c < values.size(); ++c)
            check(values[c], p, c);
        }

      private:
        void
        check(const double v, const dealii::Point<dim> &p, const unsigned int component) const
        {
          if (!std::isfinite(v))
            throw InputError(parameter,
                             "'" + expressions[component] + "' evaluates to " +
                               (std::isnan(v) ? "NaN" : (v > 0 ? "+infinity" : "-infinity")) +
                               " at " + to_text(p) +
                               (extra_variable.empty() ?
                                  std::string() :
                                  " with " + extra_variable + " = " + to_text(this->get_time())));
        }

        const std::vector<std::string> expressions;
        const std::string              parameter;
        const std::string              extra_variable;
      };
    } // namespace



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
      auto function =
        std::make_unique<FiniteFunctionParser<dim>>(expressions, parameter, extra_variable);
      std::string text;
      for (const std::string &e : expressions)
        text += (text.empty() ? "'" : ", '") + e + "'";
      try
        {
          const QuietStandardError quiet;
          function->initialize(coordinate_variables<dim>(extra_variable),
                               expressions,
                               {{"pi", dealii::numbers::PI}},
                               !extra_variable.empty());
          for (unsigned int c = 0; c < expressions.size(); ++c)
            function->dealii::FunctionParser<dim>::value(dealii::Point<dim>(), c);
        }
      catch (const std::bad_alloc &)
        {
          throw;
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
