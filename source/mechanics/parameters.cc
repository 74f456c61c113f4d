// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/parameters.h>

#include <sstream>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      std::string
      trim(const std::string &s)
      {
        return dealii::Utilities::trim(s);
      }

      unsigned int
      parse_id(const std::string &s, const std::string &parameter)
      {
        try
          {
            const int v = dealii::Utilities::string_to_int(trim(s));
            if (v < 0)
              throw 1;
            return v;
          }
        catch (...)
          {
            throw InputError(parameter, "'" + trim(s) + "' is not a non-negative integer id");
          }
      }

      /// "x=expr, y=expr" -> component -> expression.
      std::map<unsigned int, std::string>
      parse_components(const std::string &text,
                       const unsigned int dim,
                       const std::string &parameter)
      {
        std::map<unsigned int, std::string> m;
        for (const std::string &item : dealii::Utilities::split_string_list(text, ','))
          {
            const auto eq = item.find('=');
            if (eq == std::string::npos)
              throw InputError(parameter, "expected 'x=value' in '" + item + "'");
            const std::string name = trim(item.substr(0, eq));
            const std::string expr = trim(item.substr(eq + 1));
            unsigned int      c;
            if (name == "x")
              c = 0;
            else if (name == "y")
              c = 1;
            else if (name == "z" && dim == 3)
              c = 2;
            else
              throw InputError(parameter, "unknown component '" + name + "'");
            if (expr.empty())
              throw InputError(parameter, "empty value for component '" + name + "'");
            m[c] = expr;
          }
        return m;
      }
    } // namespace

    std::map<types::boundary_id, std::map<unsigned int, std::string>>
    parse_component_map(const std::string &text,
                        const unsigned int dim,
                        const std::string &parameter)
    {
      std::map<types::boundary_id, std::map<unsigned int, std::string>> result;
      for (const std::string &entry : dealii::Utilities::split_string_list(text, ';'))
        {
          if (trim(entry).empty())
            continue;
          const auto colon = entry.find(':');
          if (colon == std::string::npos)
            throw InputError(parameter, "expected 'id: x=value, ...' in '" + entry + "'");
          const unsigned int id = parse_id(entry.substr(0, colon), parameter);
          result[id]            = parse_components(entry.substr(colon + 1), dim, parameter);
        }
      return result;
    }

    std::map<unsigned int, std::string>
    parse_scalar_map(const std::string &text, const std::string &parameter)
    {
      std::map<unsigned int, std::string> result;
      if (text.find(':') == std::string::npos)
        {
          if (!trim(text).empty())
            result[numbers::invalid_unsigned_int] = trim(text);
          return result;
        }
      for (const std::string &entry : dealii::Utilities::split_string_list(text, ';'))
        {
          if (trim(entry).empty())
            continue;
          const auto colon = entry.find(':');
          if (colon == std::string::npos)
            throw InputError(parameter, "expected 'id: expression' in '" + entry + "'");
          result[parse_id(entry.substr(0, colon), parameter)] = trim(entry.substr(colon + 1));
        }
      return result;
    }

    std::vector<PointConstraint>
    parse_point_constraints(const std::string &text,
                            const unsigned int dim,
                            const std::string &parameter)
    {
      std::vector<PointConstraint> result;
      for (const std::string &entry : dealii::Utilities::split_string_list(text, ';'))
        {
          if (trim(entry).empty())
            continue;
          const auto open = entry.find('('), close = entry.find(')');
          const auto colon = entry.find(':', close == std::string::npos ? 0 : close);
          if (open == std::string::npos || close == std::string::npos || colon == std::string::npos)
            throw InputError(parameter, "expected '(px, py): x=value' in '" + entry + "'");
          PointConstraint pc;
          for (const std::string &c :
               dealii::Utilities::split_string_list(entry.substr(open + 1, close - open - 1), ','))
            try
              {
                pc.point.push_back(dealii::Utilities::string_to_double(c));
              }
            catch (...)
              {
                throw InputError(parameter, "bad coordinate '" + c + "'");
              }
          if (pc.point.size() != dim)
            throw InputError(parameter,
                             "the point in '" + entry + "' needs " + std::to_string(dim) +
                               " coordinates");
          pc.values = parse_components(entry.substr(colon + 1), dim, parameter);
          result.push_back(pc);
        }
      return result;
    }
  } // namespace mechanics
} // namespace porofrac
