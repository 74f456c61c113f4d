// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_OUTPUT_DIRECTORY_H
#define POROFRAC_IO_OUTPUT_DIRECTORY_H

#include <string>

namespace porofrac
{
  namespace io
  {
    /// The first line of the sample-line files line_<name>.csv (arc length, point, wetting
    /// pressure), by which the clean-up tells them from a user's files of the same name.
    inline std::string
    sample_line_header(const unsigned int dim)
    {
      return dim == 2 ? "s,x,y,p_w" : "s,x,y,z,p_w";
    }

    /**
     * The output directory of one run, held for the run's lifetime. Taking it creates the
     * directory if needed, checks that it can be written, takes the lock file `.porofrac.lock`
     * (refusing a directory that a running porofrac process holds; a lock left by a process that
     * no longer runs on this machine is taken over; a lock of another machine, which may share
     * the file system, is refused with the file to remove if that run has ended) and removes the
     * files a previous run left there under the names porofrac writes (summary.json, history.csv,
     * fractures.csv, fracture_p2.csv, mesh*, fractures.*, displacement.* and its pieces
     * displacement_NNNN.*, flow*, poromechanics*, checkpoint.bin) and the sample lines
     * line_<name>.csv that begin with sample_line_header(), so that the directory never mixes the
     * outputs of two runs. Other files are left alone. The destructor releases the lock.
     */
    class OutputDirectory
    {
    public:
      /// @p parameter names the setting the directory comes from, for error messages. With
      /// @p keep_outputs (a run that resumes in its own directory) nothing is removed.
      OutputDirectory(const std::string &path,
                      const std::string &parameter,
                      const bool         keep_outputs = false);
      ~OutputDirectory();

      OutputDirectory(const OutputDirectory &) = delete;
      OutputDirectory &
      operator=(const OutputDirectory &) = delete;

      /// Number of files of a previous run removed.
      unsigned int
      n_removed() const
      {
        return removed;
      }

    private:
      std::string  lock_file;
      unsigned int removed = 0;
    };
  } // namespace io
} // namespace porofrac

#endif
