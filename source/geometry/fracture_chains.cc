// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/fracture_chains.h>
#include <porofrac/io/text.h>

#include <map>
#include <set>

namespace porofrac
{
  namespace geometry
  {
    template <int dim>
    void
    chain_fractures(const RawMesh<dim>                         &raw,
                    std::vector<std::array<unsigned int, dim>> &oriented,
                    std::vector<double>                        &s_begin,
                    std::vector<unsigned int>                  &fracture_ids)
    {
      const auto &V = raw.vertices;
      oriented.assign(raw.fracture_faces.size(), std::array<unsigned int, dim>());
      s_begin.assign(raw.fracture_faces.size(), 0.);

      std::map<unsigned int, std::vector<unsigned int>> raw_faces_of_fracture;
      for (unsigned int k = 0; k < raw.fracture_faces.size(); ++k)
        raw_faces_of_fracture[raw.fracture_faces[k].tag].push_back(k);

      for (const auto &[fid, faces] : raw_faces_of_fracture)
        {
          fracture_ids.push_back(fid);
          if constexpr (dim == 2)
            {
              std::map<unsigned int, std::vector<unsigned int>> faces_at;
              for (const unsigned int k : faces)
                for (const unsigned int v : raw.fracture_faces[k].vertices)
                  faces_at[v].push_back(k);
              std::vector<unsigned int> ends;
              for (const auto &[v, fs] : faces_at)
                {
                  POROFRAC_CHECK_INPUT(fs.size() <= 2,
                                       InputError("Geometry/Fractures",
                                                  "fracture " + std::to_string(fid) +
                                                    " branches or crosses itself at " +
                                                    io::to_text(V[v])));
                  if (fs.size() == 1)
                    ends.push_back(v);
                }
              POROFRAC_CHECK_INPUT(ends.size() == 2 || ends.empty(),
                                   InputError("Geometry/Fractures",
                                              "fracture " + std::to_string(fid) +
                                                " is not one connected polyline"));
              unsigned int start = ends.empty() ? faces_at.begin()->first : ends[0];
              const auto   hint  = raw.fracture_start.find(fid);
              if (ends.size() == 2)
                {
                  if (hint != raw.fracture_start.end())
                    {
                      if (V[ends[1]].distance(hint->second) < V[ends[0]].distance(hint->second))
                        start = ends[1];
                    }
                  else if (V[ends[1]][0] < V[ends[0]][0] - 1e-12 ||
                           (std::abs(V[ends[1]][0] - V[ends[0]][0]) <= 1e-12 &&
                            V[ends[1]][1] < V[ends[0]][1]))
                    start = ends[1];
                }
              std::set<unsigned int> visited;
              unsigned int           node = start;
              double                 s    = 0;
              while (visited.size() < faces.size())
                {
                  unsigned int next_face = numbers::invalid_unsigned_int;
                  for (const unsigned int k : faces_at[node])
                    if (!visited.count(k))
                      next_face = k;
                  POROFRAC_CHECK_INPUT(next_face != numbers::invalid_unsigned_int,
                                       InputError("Geometry/Fractures",
                                                  "fracture " + std::to_string(fid) +
                                                    " is not one connected polyline"));
                  visited.insert(next_face);
                  const auto        &fv    = raw.fracture_faces[next_face].vertices;
                  const unsigned int other = (fv[0] == node) ? fv[1] : fv[0];
                  oriented[next_face]      = {{node, other}};
                  s_begin[next_face]       = s;
                  s += V[node].distance(V[other]);
                  node = other;
                }
            }
          else
            for (const unsigned int k : faces)
              oriented[k] = raw.fracture_faces[k].vertices;
        }
    }


    template void
    chain_fractures<2>(const RawMesh<2> &,
                       std::vector<std::array<unsigned int, 2>> &,
                       std::vector<double> &,
                       std::vector<unsigned int> &);
    template void
    chain_fractures<3>(const RawMesh<3> &,
                       std::vector<std::array<unsigned int, 3>> &,
                       std::vector<double> &,
                       std::vector<unsigned int> &);
  } // namespace geometry
} // namespace porofrac
