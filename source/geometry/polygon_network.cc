// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/polygon_network.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace porofrac
{
  namespace geometry
  {
    using io::trim;
    namespace
    {
      double
      parse_number(const std::string &s, const std::string &parameter)
      {
        try
          {
            std::size_t  used  = 0;
            const double value = std::stod(s, &used);
            if (used == s.size() && std::isfinite(value))
              return value;
          }
        catch (...)
          {
          }
        throw InputError(parameter, "'" + s + "' is not a number");
      }

      /// Words, numbers and parenthesised tuples of a fracture description.
      std::vector<std::string>
      tokenize(const std::string &s, const std::string &parameter)
      {
        std::vector<std::string> tokens;
        std::size_t              pos = 0;
        while (pos < s.size())
          {
            if (std::isspace(static_cast<unsigned char>(s[pos])))
              ++pos;
            else if (s[pos] == '(')
              {
                const auto close = s.find(')', pos);
                if (close == std::string::npos)
                  throw InputError(parameter, "missing ')' after '" + s.substr(pos, 20) + "'");
                tokens.push_back(s.substr(pos, close - pos + 1));
                pos = close + 1;
              }
            else
              {
                const auto end = s.find_first_of(" \t\r\n(", pos);
                tokens.push_back(s.substr(pos, end - pos));
                pos = end == std::string::npos ? s.size() : end;
              }
          }
        return tokens;
      }

      Point<3>
      parse_point(const std::string &token, const std::string &parameter)
      {
        if (token.size() < 2 || token.front() != '(' || token.back() != ')')
          throw InputError(parameter,
                           "expected a point (x, y, z) at '" + token.substr(0, 20) + "'");
        std::stringstream        inner(token.substr(1, token.size() - 2));
        std::vector<std::string> parts;
        std::string              part;
        while (std::getline(inner, part, ','))
          parts.push_back(trim(part));
        if (parts.size() != 3)
          throw InputError(parameter,
                           "point '" + token + "' must have three coordinates (x, y, z)");
        return Point<3>(parse_number(parts[0], parameter),
                        parse_number(parts[1], parameter),
                        parse_number(parts[2], parameter));
      }

      /// The keyword arguments of a disc or an ellipse: keyword -> its tokens.
      std::map<std::string, std::vector<std::string>>
      keyword_arguments(const std::vector<std::string> &tokens,
                        const std::string              &name,
                        const std::string              &parameter)
      {
        static const std::map<std::string, unsigned int> arity = {{"centre", 1},
                                                                  {"center", 1},
                                                                  {"normal", 1},
                                                                  {"axes", 2},
                                                                  {"radius", 1},
                                                                  {"radii", 2},
                                                                  {"sides", 1}};
        std::map<std::string, std::vector<std::string>>  args;
        for (unsigned int i = 1; i < tokens.size();)
          {
            const auto it = arity.find(tokens[i]);
            if (it == arity.end())
              throw InputError(parameter,
                               name + ": unknown keyword '" + tokens[i] +
                                 "' (expected centre, normal, axes, radius, radii or sides)");
            if (i + it->second >= tokens.size())
              throw InputError(parameter, name + ": '" + tokens[i] + "' needs a value");
            const std::string key = (it->first == "center") ? "centre" : it->first;
            if (args.count(key))
              throw InputError(parameter, name + ": '" + key + "' is given twice");
            args[key] =
              std::vector<std::string>(tokens.begin() + i + 1, tokens.begin() + i + 1 + it->second);
            i += 1 + it->second;
          }
        return args;
      }

      /// A disc or an ellipse as an inscribed polygon.
      PolygonFracture
      parse_ellipse(const unsigned int              id,
                    const std::vector<std::string> &tokens,
                    const std::string              &parameter)
      {
        const std::string shape = tokens[0];
        const std::string name  = "fracture " + std::to_string(id) + " (" + shape + ")";
        const auto        args  = keyword_arguments(tokens, name, parameter);
        auto              need  = [&](const std::string &key) -> const std::vector<std::string>               &{
          const auto it = args.find(key);
          if (it == args.end())
            throw InputError(parameter, name + " needs '" + key + "'");
          return it->second;
        };
        const Point<3> centre = parse_point(need("centre")[0], parameter);
        check_input(!(args.count("normal") && args.count("axes")),
                    parameter,
                    name + ": give either 'normal' or 'axes', not both");
        Tensor<1, 3> normal, t1;
        if (args.count("axes"))
          {
            const Tensor<1, 3> a = parse_point(need("axes")[0], parameter);
            const Tensor<1, 3> b = parse_point(need("axes")[1], parameter);
            check_input(a.norm() > 0 && b.norm() > 0, parameter, name + ": an axis is zero");
            check_input(std::abs(a * b) <= 1e-8 * a.norm() * b.norm(),
                        parameter,
                        name + ": the two axes must be orthogonal");
            t1     = a / a.norm();
            normal = cross_product_3d(a, b);
            normal /= normal.norm();
          }
        else
          {
            check_input(shape == "disc",
                        parameter,
                        name + " needs its two 'axes' (the normal alone leaves them open)");
            normal = parse_point(need("normal")[0], parameter);
            check_input(normal.norm() > 0, parameter, name + ": the normal is zero");
            normal /= normal.norm();
            t1 = default_tangent(normal);
          }
        double a = 0, b = 0;
        if (shape == "disc")
          a = b = parse_number(need("radius")[0], parameter);
        else
          {
            a = parse_number(need("radii")[0], parameter);
            b = parse_number(need("radii")[1], parameter);
          }
        check_input(shape == "disc" || !args.count("radius"),
                    parameter,
                    name + ": an ellipse takes 'radii a b'");
        check_input(shape == "ellipse" || !args.count("radii"),
                    parameter,
                    name + ": a disc takes 'radius r'");
        check_input(a > 0 && b > 0, parameter, name + ": the radius must be positive");
        double sides = 16;
        if (args.count("sides"))
          sides = parse_number(args.at("sides")[0], parameter);
        check_input(sides >= 3 && sides <= 10000 && sides == std::floor(sides),
                    parameter,
                    name + ": 'sides' must be an integer of at least 3");
        return {id,
                shape,
                PlanarPolygon(PolygonNetwork::ellipse_corners(centre, normal, t1, a, b, sides),
                              t1)};
      }
    } // namespace



    std::vector<Point<3>>
    PolygonNetwork::parse_points(const std::string &text, const std::string &parameter)
    {
      std::vector<Point<3>> points;
      for (const auto &token : tokenize(text, parameter))
        points.push_back(parse_point(token, parameter));
      return points;
    }



    std::vector<Point<3>>
    PolygonNetwork::ellipse_corners(const Point<3>     &centre,
                                    const Tensor<1, 3> &normal,
                                    const Tensor<1, 3> &t1,
                                    const double        a,
                                    const double        b,
                                    const unsigned int  sides)
    {
      // Counter-clockwise about the normal, so that the right-hand rule gives it back.
      const Tensor<1, 3>    t2 = cross_product_3d(normal, t1);
      std::vector<Point<3>> corners;
      for (unsigned int k = 0; k < sides; ++k)
        {
          const double theta = 2 * M_PI * k / sides;
          corners.push_back(centre + a * std::cos(theta) * t1 + b * std::sin(theta) * t2);
        }
      return corners;
    }



    std::vector<PolygonFracture>
    PolygonNetwork::parse_fractures(const std::string &input, const std::string &parameter)
    {
      std::vector<PolygonFracture> result;
      std::stringstream            all(input);
      std::string                  item;
      std::set<unsigned int>       ids;
      while (std::getline(all, item, ';'))
        {
          item = trim(item);
          if (item.empty())
            continue;
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            throw InputError(parameter,
                             "fracture '" + item.substr(0, 30) +
                               "' has no id; write 'id: (x, y, z) (x, y, z) (x, y, z) ...'");
          const std::string id_text = trim(item.substr(0, colon));
          if (id_text.empty() || !std::all_of(id_text.begin(), id_text.end(), ::isdigit) ||
              id_text.size() > 6)
            throw InputError(parameter,
                             "fracture id '" + id_text +
                               "' is not a non-negative integer below 1000000");
          const unsigned int id = std::stoul(id_text);
          if (!ids.insert(id).second)
            throw InputError(parameter, "fracture id " + id_text + " is used twice");
          const auto tokens = tokenize(item.substr(colon + 1), parameter);
          if (!tokens.empty() && (tokens[0] == "disc" || tokens[0] == "ellipse"))
            {
              result.push_back(parse_ellipse(id, tokens, parameter));
              continue;
            }
          std::vector<Point<3>> corners;
          for (const auto &token : tokens)
            corners.push_back(parse_point(token, parameter));
          if (corners.size() < 3)
            throw InputError(parameter,
                             "fracture " + id_text +
                               " needs at least three corners (or 'disc ...', 'ellipse ...')");
          const Tensor<1, 3> first_edge = corners[1] - corners[0];
          // validate() reports degenerate polygons.
          result.push_back({id, "polygon", PlanarPolygon(corners, first_edge)});
        }
      return result;
    }



    double
    PolygonNetwork::diameter() const
    {
      return lo.distance(hi);
    }



    double
    PolygonNetwork::tolerance() const
    {
      return 1e-10 * diameter();
    }
  } // namespace geometry
} // namespace porofrac
