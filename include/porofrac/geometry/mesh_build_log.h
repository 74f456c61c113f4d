// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_MESH_BUILD_LOG_H
#define POROFRAC_GEOMETRY_MESH_BUILD_LOG_H

#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <porofrac/geometry/random_discs.h>

#include <string>
#include <vector>

namespace porofrac
{
  namespace geometry
  {
    /**
     * How a cut mesh was built: the wall time of each phase and the process's peak memory after
     * it (for benchmarks and summary.json; tests never print them), and what the random disc
     * generator did.
     */
    struct MeshBuildLog
    {
      struct Phase
      {
        std::string name;
        double      seconds;
        double      peak_memory_mb; ///< VmHWM after the phase
        double      memory_mb;      ///< VmRSS after the phase
      };
      std::vector<Phase>   phases;
      RandomDiscStatistics random_discs;

      /// Records phase @p name, timed by @p timer (which is restarted).
      void
      add(const std::string &name, dealii::Timer &timer)
      {
        dealii::Utilities::System::MemoryStats memory;
        dealii::Utilities::System::get_memory_stats(memory);
        phases.push_back({name, timer.wall_time(), memory.VmHWM / 1024., memory.VmRSS / 1024.});
        timer.restart();
      }
    };
  } // namespace geometry
} // namespace porofrac

#endif
