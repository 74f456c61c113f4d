// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/io/output_file.h>
#include <porofrac/io/pvd_writer.h>

#include <fstream>
#include <iomanip>

namespace porofrac
{
  namespace io
  {
    PvdWriter::PvdWriter(const std::string &filename)
        : filename(filename)
    {
    }



    void
    PvdWriter::set_entries(const std::vector<std::pair<double, std::string>> &restored)
    {
      entries = restored;
    }



    void
    PvdWriter::add(const double time, const std::string &file)
    {
      entries.emplace_back(time, file);
      OutputFile    collection(filename);
      std::ostream &pvd = collection.stream();
      pvd << std::setprecision(17);
      pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
             "<Collection>\n";
      for (const auto &e : entries)
        pvd << "<DataSet timestep=\"" << e.first << "\" file=\"" << e.second << "\"/>\n";
      pvd << "</Collection>\n</VTKFile>\n";
      collection.close();
    }
  } // namespace io
} // namespace porofrac
