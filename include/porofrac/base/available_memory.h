// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_AVAILABLE_MEMORY_H
#define POROFRAC_BASE_AVAILABLE_MEMORY_H

#include <string>

namespace porofrac
{
  /**
   * The memory this process may still take, in MB: MemAvailable of /proc/meminfo, or less where
   * the process's memory control group (a container's limit, a batch job's allocation under
   * Slurm) or one of its ancestors allows less. A group's headroom is its limit less the memory
   * it uses but could not reclaim (its usage less its inactive page cache), as container runtimes
   * count it. cgroup v2 and v1 are read; 0 if neither /proc/meminfo nor a limit can be read.
   */
  double
  available_memory_mb();

  /// @p megabytes as "12.3 GB" or, below a GB, "456 MB".
  std::string
  memory_size_text(double megabytes);

  namespace internal
  {
    /**
     * The smallest headroom (MB) of the memory control groups from @p group (a path as in
     * /proc/self/cgroup) up to the root of the hierarchy mounted at @p mount, with the
     * interface files of cgroup v2 (@p v2) or v1; 0 if no group on the way has a limit.
     * Without a cgroup namespace @p group also names the groups above a container's, which
     * its mount does not show: the walk starts at the longest tail of @p group that the mount
     * has.
     */
    double
    cgroup_headroom_mb(const std::string &mount, const std::string &group, bool v2);
  } // namespace internal
} // namespace porofrac

#endif
