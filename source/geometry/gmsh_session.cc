// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/gmsh_session.h>

#include <exception>
#include <new>
#include <vector>

#include <gmsh.h>

namespace porofrac
{
  namespace geometry
  {
    GmshSession::GmshSession()
    {
      gmsh::initialize(0, nullptr, false);
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::option::setNumber("General.Verbosity", 1); // errors only, into the logger
      gmsh::option::setNumber("General.AbortOnError", 0);
      gmsh::option::setNumber("General.NumThreads", 1);
      for (const char *name :
           {"Mesh.MaxNumThreads1D", "Mesh.MaxNumThreads2D", "Mesh.MaxNumThreads3D"})
        gmsh::option::setNumber(name, 1);
      gmsh::logger::start();
    }



    GmshSession::~GmshSession()
    {
      try
        {
          gmsh::logger::stop();
          gmsh::finalize();
        }
      catch (...)
        {
        }
    }



    void
    GmshSession::run(const std::string           &parameter,
                     const std::string           &what,
                     const std::function<void()> &step)
    {
      std::string message;
      try
        {
          step();
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const std::bad_alloc &)
        {
          throw;
        }
      catch (const std::string &s)
        {
          message = s;
        }
      catch (const std::exception &e)
        {
          message = e.what();
        }
      catch (...)
        {
          message = "unknown error";
        }
      std::vector<std::string> log;
      try
        {
          gmsh::logger::get(log);
          gmsh::logger::stop();
          gmsh::logger::start();
        }
      catch (...)
        {
        }
      for (const auto &line : log)
        if (message.empty() && line.rfind("Error", 0) == 0)
          message = line.substr(line.find(':') == std::string::npos ? 0 : line.find(':') + 2);
      // gmsh reports an allocation that failed inside it as an error like any other: it is no
      // fault of the input.
      if (message.find("bad_alloc") != std::string::npos)
        throw std::bad_alloc();
      if (!message.empty())
        throw InputError(parameter, what + ": " + message);
    }
  } // namespace geometry
} // namespace porofrac
