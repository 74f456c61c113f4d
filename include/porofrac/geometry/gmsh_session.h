// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_GMSH_SESSION_H
#define POROFRAC_GEOMETRY_GMSH_SESSION_H

#include <functional>
#include <string>

namespace porofrac
{
  namespace geometry
  {
    /**
     * gmsh, initialized for the lifetime of the object: quiet, single-threaded, and with errors
     * logged instead of thrown. gmsh 4.8 reports errors by throwing a std::string, also from
     * inside OpenMP regions (surface meshing), where no handler can catch it and the process
     * aborts; logged errors are turned into InputErrors by run().
     */
    class GmshSession
    {
    public:
      GmshSession();
      ~GmshSession();
      GmshSession(const GmshSession &) = delete;
      GmshSession &
      operator=(const GmshSession &) = delete;

      /**
       * Calls @p step; if it throws anything or gmsh logs an error meanwhile, throws
       * InputError(@p parameter, @p what + ": " + gmsh's message).
       */
      void
      run(const std::string &parameter, const std::string &what, const std::function<void()> &step);
    };
  } // namespace geometry
} // namespace porofrac

#endif
