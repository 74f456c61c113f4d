// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_PVD_WRITER_H
#define POROFRAC_IO_PVD_WRITER_H

#include <string>
#include <utility>
#include <vector>

namespace porofrac
{
  namespace io
  {
    /**
     * A ParaView collection (.pvd) of the field files of a time-dependent run: each add()
     * records one file at one time and rewrites the collection, so that it always lists every
     * file written so far (also when the run stops early).
     */
    class PvdWriter
    {
    public:
      /// @p filename: the .pvd to write; the files it lists are relative to its directory.
      explicit PvdWriter(const std::string &filename);

      void
      add(const double time, const std::string &file);

      /// The (time, file) entries written so far, and a replacement of them (to resume a run).
      const std::vector<std::pair<double, std::string>> &
      get_entries() const
      {
        return entries;
      }
      void
      set_entries(const std::vector<std::pair<double, std::string>> &restored);

    private:
      std::string                                 filename;
      std::vector<std::pair<double, std::string>> entries;
    };
  } // namespace io
} // namespace porofrac

#endif
