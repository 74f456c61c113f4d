// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/io/output_file.h>

namespace porofrac
{
  namespace io
  {
    OutputFile::OutputFile(const std::string &filename)
        : filename(filename)
        , out(filename)
    {
      check_input(bool(out), "Output/Directory", "cannot write '" + filename + "'");
    }



    void
    OutputFile::close()
    {
      out.close();
      check_input(!out.fail(), "Output/Directory", "cannot write '" + filename + "'");
    }
  } // namespace io
} // namespace porofrac
