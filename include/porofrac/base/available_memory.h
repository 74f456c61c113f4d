// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_AVAILABLE_MEMORY_H
#define POROFRAC_BASE_AVAILABLE_MEMORY_H

#include <string>
#include <utility>

#include <mpi.h>

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

  /**
   * What this process may still allocate, in MB, under its address-space and data-segment limits
   * (ulimit -v, -d; some batch systems set them): the limit less the address space (data) it has
   * mapped; 0 without a limit. Beyond it an allocation fails instead of having the process
   * killed, and not every library survives that. Unlike available_memory_mb() it is this
   * process's alone.
   */
  double
  process_memory_headroom_mb();

  /**
   * Caps available_memory_mb() at @p megabytes (0: no cap), for this process, e.g. to exercise
   * the memory checks of the solvers in a test without a control group.
   */
  void
  limit_available_memory(double megabytes);

  /**
   * A serial solver that every process of a run holds and factorizes at the same time (the
   * coupled model's replicated contact mechanics) allocates its matrices once per process: its
   * memory check must count them that many times against the machine's memory. While an object
   * of this class lives, copies_per_machine() is the number it was given (the processes of the
   * run on this machine, processes_on_this_machine()); otherwise 1.
   */
  class ReplicatedSerialSolves
  {
  public:
    explicit ReplicatedSerialSolves(unsigned int copies_per_machine);
    ~ReplicatedSerialSolves();
    ReplicatedSerialSolves(const ReplicatedSerialSolves &) = delete;
    ReplicatedSerialSolves &
    operator=(const ReplicatedSerialSolves &) = delete;

    static unsigned int
    copies_per_machine();

  private:
    const unsigned int previous;
  };

  /**
   * Throws InsufficientMemory "<what> would need at least <need>[ for the N processes on this
   * machine that each <each>], more than the <available> available to this run on this machine[;
   * <advice>]" if @p megabytes, counted once per ReplicatedSerialSolves copy, exceed
   * available_memory_mb(), or if @p megabytes (one copy) exceed process_memory_headroom_mb() ("...,
   * more than the <headroom> that this process may still allocate under its address-space
   * limit"); nothing if the available memory cannot be read. Call it before the
   * allocation it guards: on Linux an allocation beyond the memory does not fail but has the
   * process killed.
   */
  void
  require_memory(double             megabytes,
                 const std::string &what,
                 const std::string &each,
                 const std::string &advice);

  /**
   * require_memory() for a need that every process of @p communicator has at once (collective):
   * the needs of the processes on one machine, summed, against the memory available to it
   * (available_memory_mb(), or @p machine_limit_mb where positive), and each process's own need
   * against process_memory_headroom_mb(). Every process throws the same InsufficientMemory, with
   * the largest need and limit over the processes that are short: "<needs>, more than the <limit>
   * available to [the N processes of] this run on this machine; <advice>" or "<needs>, more than
   * the <headroom> that a process may still allocate under its address-space limit (ulimit -v or
   * -d); <advice>", the need written in place of the '%' in @p needs. Where a library maps more
   * address space than it touches, @p address_space_mb (if positive) is the need compared with
   * the headroom.
   */
  void
  require_memory_on_every_process(double             process_mb,
                                  const std::string &needs,
                                  const std::string &advice,
                                  MPI_Comm           communicator,
                                  double             machine_limit_mb = 0,
                                  double             address_space_mb = 0);

  /// @p need and @p available as memory_size_text(), or in whole MB (the need rounded up, the
  /// rest down) where the two would read alike.
  std::pair<std::string, std::string>
  memory_sizes_text(double need, double available);

  /// @p megabytes as "12.3 GB" or, below a GB, "456 MB" (below 10 MB "4.56 MB").
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
