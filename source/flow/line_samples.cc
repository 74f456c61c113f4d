// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/rtree.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/flow/line_samples.h>
#include <porofrac/geometry/simplex_tools.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <memory>
#include <regex>
#include <set>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      /// Whether @p p lies in the simplex @p cell (barycentric coordinates >= -1e-10).
      template <int dim, typename Cell>
      bool
      contains(const Cell &cell, const Point<dim> &p)
      {
        std::array<Point<dim>, dim + 1> vertices;
        for (unsigned int i = 0; i <= dim; ++i)
          vertices[i] = cell->vertex(i);
        return geometry::contains<dim>(vertices, p, 1e-10);
      }
    } // namespace



    template <int dim>
    std::vector<SampleLine<dim>>
    parse_sample_lines(const std::string &text, const std::string &parameter)
    {
      const std::string number = R"(\s*([-+0-9.eE]+)\s*)";
      std::string       point  = R"(\()" + number;
      for (unsigned int d = 1; d < dim; ++d)
        point += "," + number;
      point += R"(\))";
      const std::regex pattern(R"(\s*([A-Za-z0-9_-]+)\s*:\s*)" + point + R"(\s*)" + point +
                               R"(\s*([0-9]*)\s*)");
      std::vector<SampleLine<dim>> lines;
      std::set<std::string>        names;
      for (const std::string &entry : Utilities::split_string_list(text, ';'))
        {
          if (entry.empty())
            continue;
          std::smatch m;
          check_input(std::regex_match(entry, m, pattern),
                      parameter,
                      "expected 'name: " +
                        std::string(dim == 2 ? "(x, y) (x, y)" : "(x, y, z) (x, y, z)") +
                        " [number of points]', got '" + entry + "'");
          SampleLine<dim> line;
          line.name = m[1];
          try
            {
              for (unsigned int d = 0; d < dim; ++d)
                {
                  line.start[d] = std::stod(m[2 + d]);
                  line.end[d]   = std::stod(m[2 + dim + d]);
                }
              if (m[2 + 2 * dim].length() > 0)
                line.n_points = std::stoul(m[2 + 2 * dim]);
            }
          catch (...)
            {
              throw InputError(parameter, "bad number in '" + entry + "'");
            }
          check_input(line.n_points >= 2 && line.n_points <= 1000000,
                      parameter,
                      "line '" + line.name + "' needs 2 to 10^6 points");
          check_input(line.start.distance(line.end) > 0,
                      parameter,
                      "line '" + line.name + "' has zero length");
          check_input(names.insert(line.name).second,
                      parameter,
                      "line name '" + line.name + "' is used twice");
          lines.push_back(line);
        }
      return lines;
    }



    template <int dim>
    std::vector<unsigned int>
    cells_along_line(const geometry::CutMesh<dim> &mesh, const SampleLine<dim> &line)
    {
      using Box                      = std::pair<BoundingBox<dim>, unsigned int>;
      const auto               &tria = mesh.triangulation;
      std::vector<unsigned int> cells(line.n_points, numbers::invalid_unsigned_int);
      auto                      hint = tria.end();
      // The first active cell that contains p, as a scan over all cells would find it, among
      // the cells whose bounding box (widened beyond the containment tolerance) holds p. The
      // tree is built when the walk from the last cell first fails.
      std::vector<typename Triangulation<dim>::active_cell_iterator> by_index;
      std::unique_ptr<RTree<Box>>                                    tree;
      const auto first_cell_containing = [&](const Point<dim> &p) ->
        typename Triangulation<dim>::cell_iterator {
          if (!tree)
            {
              std::vector<Box> boxes;
              for (const auto &cell : tria.active_cell_iterators())
                {
                  BoundingBox<dim> box  = cell->bounding_box();
                  double           size = 0;
                  for (unsigned int d = 0; d < dim; ++d)
                    size = std::max(size, box.side_length(d));
                  box.extend(1e-8 * size);
                  boxes.emplace_back(box, cell->active_cell_index());
                  by_index.push_back(cell);
                }
              tree = std::make_unique<RTree<Box>>(pack_rtree(boxes));
            }
          std::vector<Box> hits;
          tree->query(boost::geometry::index::intersects(p), std::back_inserter(hits));
          std::sort(hits.begin(), hits.end(), [](const Box &a, const Box &b) {
            return a.second < b.second;
          });
          for (const auto &hit : hits)
            if (contains<dim>(by_index[hit.second], p))
              return by_index[hit.second];
          return tria.end();
        };
      for (unsigned int k = 0; k < line.n_points; ++k)
        {
          const double     t     = double(k) / (line.n_points - 1);
          const Point<dim> p     = line.start + t * (line.end - line.start);
          auto             found = tria.end();
          if (hint != tria.end())
            {
              if (contains<dim>(hint, p))
                found = hint;
              else
                for (const unsigned int f : hint->face_indices())
                  if (!hint->at_boundary(f) && contains<dim>(hint->neighbor(f), p))
                    {
                      found = hint->neighbor(f);
                      break;
                    }
            }
          if (found == tria.end())
            found = first_cell_containing(p);
          if (found != tria.end())
            {
              cells[k] = found->active_cell_index();
              hint     = found;
            }
        }
      return cells;
    }

    template std::vector<SampleLine<2>>
    parse_sample_lines(const std::string &, const std::string &);
    template std::vector<SampleLine<3>>
    parse_sample_lines(const std::string &, const std::string &);
    template std::vector<unsigned int>
    cells_along_line(const geometry::CutMesh<2> &, const SampleLine<2> &);
    template std::vector<unsigned int>
    cells_along_line(const geometry::CutMesh<3> &, const SampleLine<3> &);
  } // namespace flow
} // namespace porofrac
