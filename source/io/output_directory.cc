// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/io/output_directory.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include <fcntl.h>
#include <unistd.h>

namespace porofrac
{
  namespace io
  {
    namespace
    {
      /// Whether @p file is a sample line porofrac wrote: line_<name>.csv is a name users may
      /// choose too, so its header decides.
      bool
      is_sample_line(const std::filesystem::path &file)
      {
        static const std::regex name("line_.+\\.csv");
        if (!std::regex_match(file.filename().string(), name))
          return false;
        std::string   header;
        std::ifstream in(file);
        std::getline(in, header);
        return header == sample_line_header(2) || header == sample_line_header(3);
      }

      /// The files porofrac writes into an output directory.
      bool
      is_porofrac_output(const std::filesystem::path &file)
      {
        static const std::regex pattern(
          "summary\\.json|history\\.csv|fractures\\.csv|fracture_p2\\.csv|checkpoint\\.bin|"
          "(mesh|mesh_fractures|mesh_fracture_edges|fractures|displacement)\\.(vtu|vtk)|"
          "(mesh|displacement)(_[0-9]+\\.(vtu|vtk)|\\.pvtu)|"
          "(flow|poromechanics)(-[0-9]+(_fractures|_displacement)?\\.(vtu|vtk|pvtu)|\\.pvd)|"
          "(flow|poromechanics)-[0-9]+(_displacement)?_[0-9]+\\.(vtu|vtk)");
        return std::regex_match(file.filename().string(), pattern) || is_sample_line(file);
      }

      /// Whether a process with this id runs (and may be signalled by us).
      bool
      process_runs(const long pid)
      {
        return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
      }

      /// This machine's name ("" if it has none).
      std::string
      host_name()
      {
        char name[256] = {};
        return ::gethostname(name, sizeof(name) - 1) == 0 ? std::string(name) : std::string();
      }

      /// Creates @p file exclusively with our process id and machine; false if it exists.
      bool
      create_lock(const std::string &file)
      {
        const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
        if (fd < 0)
          return false;
        const std::string pid = std::to_string(::getpid()) + " " + host_name() + "\n";
        const bool        ok  = ::write(fd, pid.data(), pid.size()) == ssize_t(pid.size());
        ::close(fd);
        return ok;
      }
    } // namespace



    OutputDirectory::OutputDirectory(const std::string &path,
                                     const std::string &parameter,
                                     const bool         keep_outputs)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      fs::create_directories(path, ec);
      check_input(fs::is_directory(path, ec),
                  parameter,
                  "cannot create the output directory '" + path + "'");
      const std::string file = path + "/.porofrac.lock";
      if (!create_lock(file))
        {
          check_input(fs::exists(file, ec),
                      parameter,
                      "cannot write into the output directory '" + path + "'");
          long          pid = 0;
          std::string   host;
          std::ifstream in(file);
          in >> pid >> host;
          // On a file system shared by several machines, whether the holder still runs can
          // only be told on its own machine.
          check_input(host.empty() || host == host_name(),
                      parameter,
                      "the output directory '" + path + "' is held by porofrac process " +
                        std::to_string(pid) + " on the machine '" + host +
                        "'; choose another directory, or remove '" + file +
                        "' if that run has ended");
          check_input(!process_runs(pid) || pid == ::getpid(),
                      parameter,
                      "the output directory '" + path +
                        "' is in use by another porofrac run "
                        "(process " +
                        std::to_string(pid) + "); choose another directory");
          // A stale lock of a run that was killed.
          fs::remove(file, ec);
          check_input(create_lock(file),
                      parameter,
                      "cannot take the lock file of the output directory '" + path + "'");
        }
      lock_file = file;
      if (keep_outputs)
        return;
      for (const auto &entry : fs::directory_iterator(path, ec))
        if (entry.is_regular_file(ec) && is_porofrac_output(entry.path()))
          if (fs::remove(entry.path(), ec))
            ++removed;
    }



    OutputDirectory::~OutputDirectory()
    {
      std::error_code ec;
      std::filesystem::remove(lock_file, ec);
    }
  } // namespace io
} // namespace porofrac
