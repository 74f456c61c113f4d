// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_OUTPUT_FILE_H
#define POROFRAC_IO_OUTPUT_FILE_H

#include <fstream>
#include <string>

namespace porofrac
{
  namespace io
  {
    /**
     * A file of a run's results (fractures.csv, line_<name>.csv, field files, ...). A file that
     * cannot be opened (a directory in its place, no permission) or written whole (a full disk)
     * is an InputError of Output/Directory naming it, raised by the constructor or by close(): a
     * run never ends as if its results were written when they were not.
     */
    class OutputFile
    {
    public:
      explicit OutputFile(const std::string &filename);

      std::ofstream &
      stream()
      {
        return out;
      }

      /// Writes out what is buffered and checks that everything written arrived.
      void
      close();

    private:
      std::string   filename;
      std::ofstream out;
    };
  } // namespace io
} // namespace porofrac

#endif
