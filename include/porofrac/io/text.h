// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_TEXT_H
#define POROFRAC_IO_TEXT_H

#include <deal.II/base/point.h>

#include <sstream>
#include <string>

namespace porofrac
{
  namespace io
  {
    /// @p s without leading and trailing white space.
    inline std::string
    trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t\r\n");
      const auto e = s.find_last_not_of(" \t\r\n");
      return b == std::string::npos ? "" : s.substr(b, e - b + 1);
    }

    /// A number in the shortest default stream format (1.5, 1e-07, 6.31152e+09), for messages.
    inline std::string
    to_text(const double v)
    {
      std::ostringstream s;
      s << v;
      return s.str();
    }

    /// "(x, y)" or "(x, y, z)", for messages.
    template <int dim>
    std::string
    to_text(const dealii::Point<dim> &p)
    {
      std::ostringstream s;
      s << "(";
      for (unsigned int d = 0; d < dim; ++d)
        s << (d ? ", " : "") << p[d];
      s << ")";
      return s.str();
    }
  } // namespace io
} // namespace porofrac

#endif
