// SPDX-License-Identifier: LGPL-2.1-or-later
// io::OutputDirectory: a directory held by a running process (its lock names process 1, which
// always runs) is refused with an InputError; a stale lock (a process id that does not run on
// this machine, with or without the machine's name) is taken over; a lock of another machine is
// refused, naming the lock file to remove; the files of a previous run are removed and other files
// are kept (a line_<name>.csv only when it begins with porofrac's sample-line header); the lock is
// released when the holder ends; a path under a regular file cannot be created.
#include <porofrac/base/exceptions.h>
#include <porofrac/io/output_directory.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>

namespace fs = std::filesystem;

namespace
{
  void
  touch(const fs::path &p, const std::string &text = "x")
  {
    std::ofstream(p) << text;
  }

  /// A process id that does not run (searching down from a large one).
  long
  dead_pid()
  {
    for (long pid = 4000000; pid > 1000; --pid)
      if (::kill(pid, 0) != 0 && errno == ESRCH)
        return pid;
    return -1;
  }

  void
  attempt(const std::string &title, const fs::path &dir)
  {
    try
      {
        porofrac::io::OutputDirectory d(dir.string(), "Output/Directory");
        std::cout << title << ": taken, " << d.n_removed() << " files removed" << std::endl;
      }
    catch (const porofrac::InputError &e)
      {
        std::string what = e.what();
        for (auto p = what.find(dir.string()); p != std::string::npos; p = what.find(dir.string()))
          what.replace(p, dir.string().size(), "DIR");
        std::cout << title << ": " << what << std::endl;
      }
  }
} // namespace

int
main()
{
  const fs::path dir =
    fs::temp_directory_path() / ("porofrac-outdir-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const char *name : {"summary.json",
                           "history.csv",
                           "fractures.csv",
                           "mesh.vtu",
                           "mesh_fractures.vtu",
                           "flow-00003.vtu",
                           "flow-00003_fractures.vtu",
                           "flow.pvd",
                           "poromechanics-00012_displacement.vtk",
                           "mesh_fracture_edges.vtu",
                           "flow-00003.pvtu",
                           "flow-00003_0001.vtu",
                           "poromechanics-00012_displacement_0000.vtu",
                           "poromechanics-00012_displacement.pvtu",
                           "mesh_0001.vtu",
                           "mesh.pvtu",
                           "notes.txt",
                           "my_mesh.vtu",
                           "summary.json.bak"})
    touch(dir / name);
  // A sample line of porofrac's and a user's file under a sample line's name.
  touch(dir / "line_diagonal.csv", porofrac::io::sample_line_header(3) + "\n0,0,0,0,1\n");
  touch(dir / "line_survey.csv", "depth,p\n");

  touch(dir / ".porofrac.lock", "1\n");
  attempt("held by process 1", dir);
  std::cout << "  files kept: " << std::distance(fs::directory_iterator(dir), {}) << std::endl;

  touch(dir / ".porofrac.lock", "1 other-machine.invalid\n");
  attempt("held on another machine", dir);

  char host[256] = {};
  ::gethostname(host, sizeof(host) - 1);
  touch(dir / ".porofrac.lock", std::to_string(dead_pid()) + " " + host + "\n");
  attempt("stale lock of this machine", dir);
  std::cout << "  lock released: " << (fs::exists(dir / ".porofrac.lock") ? "no" : "yes")
            << std::endl;

  touch(dir / "summary.json");
  touch(dir / ".porofrac.lock", std::to_string(dead_pid()) + "\n");
  attempt("stale lock without a machine name", dir);
  std::cout << "  lock released: " << (fs::exists(dir / ".porofrac.lock") ? "no" : "yes")
            << std::endl;
  for (const char *name : {"notes.txt",
                           "my_mesh.vtu",
                           "summary.json.bak",
                           "summary.json",
                           "flow-00003_0001.vtu",
                           "poromechanics-00012_displacement_0000.vtu",
                           "mesh_0001.vtu",
                           "mesh.pvtu",
                           "line_diagonal.csv",
                           "line_survey.csv"})
    std::cout << "  " << name << (fs::exists(dir / name) ? " kept" : " removed") << std::endl;

  attempt("empty directory", dir);
  touch(dir / "plain_file");
  attempt("below a regular file", dir / "plain_file" / "out");
  fs::remove_all(dir);
}
