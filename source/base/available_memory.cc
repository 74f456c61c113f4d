// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/array_view.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/mpi_tools.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <utility>

#include <sys/resource.h>

namespace porofrac
{
  namespace
  {
    /// limit_available_memory(); 0: none.
    double memory_cap_mb = 0;

    /// ReplicatedSerialSolves::copies_per_machine().
    unsigned int replicated_copies = 1;

    /// The first number in the file @p path; 0 where it cannot be read (also "max", cgroup v2's
    /// "no limit").
    double
    number_in_file(const std::string &path)
    {
      std::ifstream file(path);
      double        value = 0;
      return (file >> value) ? value : 0.;
    }

    /// The value of @p key in a file of "key value" lines, 0 where it is absent.
    double
    keyed_value(const std::string &path, const std::string &key)
    {
      std::ifstream file(path);
      std::string   name;
      double        value = 0;
      while (file >> name >> value)
        {
          if (name == key)
            return value;
          file.ignore(256, '\n');
        }
      return 0;
    }

    /// The value in kB of @p key ("VmSize:") in /proc/self/status, 0 where it is absent.
    double
    status_kb(const std::string &key)
    {
      std::ifstream file("/proc/self/status");
      std::string   line;
      while (std::getline(file, line))
        if (line.rfind(key, 0) == 0)
          return std::atof(line.c_str() + key.size());
      return 0;
    }

  } // namespace



  double
  process_memory_headroom_mb()
  {
    double headroom = 0;
    for (const auto &[resource, key] : {std::pair{RLIMIT_AS, "VmSize:"}, {RLIMIT_DATA, "VmData:"}})
      {
        rlimit limit{};
        if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
          continue;
        const double left = std::max(limit.rlim_cur / 1024. - status_kb(key), 1.) / 1024.;
        headroom          = headroom > 0 ? std::min(headroom, left) : left;
      }
    return headroom;
  }



  namespace
  {

    /// The headroom (MB) of the group in directory @p dir, 0 without a limit.
    double
    group_headroom_mb(const std::string &dir, const bool v2)
    {
      const double limit = number_in_file(dir + (v2 ? "/memory.max" : "/memory.limit_in_bytes"));
      // v1 writes "no limit" as a number near 2^63.
      if (limit <= 0 || limit >= 1e18)
        return 0;
      const double usage =
        number_in_file(dir + (v2 ? "/memory.current" : "/memory.usage_in_bytes"));
      const double cache =
        keyed_value(dir + "/memory.stat", v2 ? "inactive_file" : "total_inactive_file");
      return std::max(limit - std::max(usage - cache, 0.), 1.) / (1024. * 1024.);
    }

    /// The group path of the memory controller in /proc/self/cgroup: the "0::" line of cgroup
    /// v2, or the v1 line whose controller list has "memory"; empty if there is none.
    std::string
    memory_group(const bool v2)
    {
      std::ifstream file("/proc/self/cgroup");
      std::string   line;
      while (std::getline(file, line))
        {
          const auto first = line.find(':'), second = line.find(':', first + 1);
          if (first == std::string::npos || second == std::string::npos)
            continue;
          const std::string  controllers = line.substr(first + 1, second - first - 1);
          std::istringstream list(controllers);
          std::string        name;
          bool               memory = v2 && controllers.empty();
          while (!v2 && std::getline(list, name, ','))
            memory = memory || name == "memory";
          if (memory)
            return line.substr(second + 1);
        }
      return "";
    }
  } // namespace



  namespace internal
  {
    double
    cgroup_headroom_mb(const std::string &mount, const std::string &group, const bool v2)
    {
      // Without a cgroup namespace the path names the groups above the container's too, which
      // the mount does not show: start at the longest tail of the path that it shows.
      std::string path = group;
      while (!path.empty() && !std::ifstream(mount + path + "/memory.stat"))
        {
          const auto next = path.find('/', 1);
          path            = next == std::string::npos ? "" : path.substr(next);
        }
      double headroom = 0;
      while (true)
        {
          if (std::ifstream(mount + path + (v2 ? "/memory.max" : "/memory.limit_in_bytes")))
            {
              const double here = group_headroom_mb(mount + path, v2);
              if (here > 0)
                headroom = headroom > 0 ? std::min(headroom, here) : here;
            }
          if (path.empty() || path == "/")
            break;
          path = path.substr(0, path.find_last_of('/'));
        }
      return headroom;
    }
  } // namespace internal



  double
  available_memory_mb()
  {
    const double machine = keyed_value("/proc/meminfo", "MemAvailable:") / 1024.;
    const bool   v2      = static_cast<bool>(std::ifstream("/sys/fs/cgroup/cgroup.controllers"));
    const double group =
      internal::cgroup_headroom_mb(v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory",
                                   memory_group(v2),
                                   v2);
    double available =
      (machine > 0 && group > 0) ? std::min(machine, group) : std::max(machine, group);
    if (memory_cap_mb > 0)
      available = available > 0 ? std::min(available, memory_cap_mb) : memory_cap_mb;
    return available;
  }



  void
  limit_available_memory(const double megabytes)
  {
    memory_cap_mb = megabytes;
  }



  ReplicatedSerialSolves::ReplicatedSerialSolves(const unsigned int copies_per_machine)
      : previous(replicated_copies)
  {
    replicated_copies = std::max(copies_per_machine, 1u);
  }



  ReplicatedSerialSolves::~ReplicatedSerialSolves()
  {
    replicated_copies = previous;
  }



  unsigned int
  ReplicatedSerialSolves::copies_per_machine()
  {
    return replicated_copies;
  }



  void
  require_memory(const double       megabytes,
                 const std::string &what,
                 const std::string &each,
                 const std::string &advice)
  {
    const unsigned int copies    = ReplicatedSerialSolves::copies_per_machine();
    const double       need      = copies * megabytes;
    const double       available = available_memory_mb();
    if (available > 0 && need > available)
      {
        const std::string copies_text =
          copies > 1 ?
            " for the " + std::to_string(copies) + " processes on this machine that each " + each :
            "";
        const auto [need_text, available_text] = memory_sizes_text(need, available);
        throw InsufficientMemory(what + " would need at least " + need_text + copies_text +
                                 ", more than the " + available_text +
                                 " available to this run on this machine" +
                                 (advice.empty() ? "" : "; " + advice));
      }
    // Each process allocates its own copy under its own limits.
    const double headroom = process_memory_headroom_mb();
    if (headroom > 0 && megabytes > headroom)
      {
        const auto [need_text, headroom_text] = memory_sizes_text(megabytes, headroom);
        throw InsufficientMemory(what + " would need at least " + need_text + ", more than the " +
                                 headroom_text +
                                 " that this process may still allocate under its address-space "
                                 "limit (ulimit -v or -d)" +
                                 (advice.empty() ? "" : "; " + advice));
      }
  }



  void
  require_memory_on_every_process(const double       process_mb,
                                  const std::string &needs,
                                  const std::string &advice,
                                  const MPI_Comm     communicator,
                                  const double       machine_limit_mb,
                                  const double       address_space_mb)
  {
    const double mapped_mb     = address_space_mb > 0 ? address_space_mb : process_mb;
    const auto [need, sharing] = sum_on_this_machine<2>({{process_mb, 1.}}, communicator);
    const double limit         = machine_limit_mb > 0 ? machine_limit_mb : available_memory_mb();
    const double headroom      = process_memory_headroom_mb();
    // The processes that share a machine share its memory; each has its own address space.
    // The largest shortfalls over the processes, in one reduction.
    const bool                  machine_short = limit > 0 && need > limit;
    const bool                  process_short = headroom > 0 && mapped_mb > headroom;
    const std::array<double, 5> own{{machine_short ? need : 0.,
                                     machine_short ? limit : 0.,
                                     machine_short ? sharing : 0.,
                                     process_short ? mapped_mb : 0.,
                                     process_short ? headroom : 0.}};
    std::array<double, 5>       worst = own;
    if (communicator != MPI_COMM_SELF)
      dealii::Utilities::MPI::max(dealii::ArrayView<const double>(own.data(), own.size()),
                                  communicator,
                                  dealii::ArrayView<double>(worst.data(), worst.size()));
    const auto [worst_need, worst_limit, worst_sharing, worst_process, worst_room] = worst;
    const auto message = [&](const double n, const double l, const std::string &where) {
      const auto [need_text, limit_text] = memory_sizes_text(n, l);
      std::string text                   = needs;
      const auto  mark                   = text.find('%');
      if (mark != std::string::npos)
        text.replace(mark, 1, need_text);
      return text + ", more than the " + limit_text + where + (advice.empty() ? "" : "; " + advice);
    };
    if (worst_need > 0)
      throw InsufficientMemory(message(worst_need,
                                       worst_limit,
                                       worst_sharing > 1 ?
                                         " available to the " +
                                           std::to_string(std::lround(worst_sharing)) +
                                           " processes of this run on this machine" :
                                         " available to this run on this machine"));
    if (worst_process > 0)
      throw InsufficientMemory(message(worst_process,
                                       worst_room,
                                       " that a process may still allocate under its "
                                       "address-space limit (ulimit -v or -d)"));
  }



  std::pair<std::string, std::string>
  memory_sizes_text(const double need, const double available)
  {
    std::string need_text = memory_size_text(need), available_text = memory_size_text(available);
    if (need_text == available_text) // rounded alike: whole MB, the need up, the rest down
      {
        need_text      = std::to_string(static_cast<long>(std::ceil(need))) + " MB";
        available_text = std::to_string(static_cast<long>(std::floor(available))) + " MB";
      }
    return {need_text, available_text};
  }



  std::string
  memory_size_text(const double megabytes)
  {
    std::ostringstream text;
    if (megabytes >= 1024)
      text << std::fixed << std::setprecision(1) << megabytes / 1024. << " GB";
    else
      text << std::fixed
           << std::setprecision(megabytes < 1  ? 3 :
                                megabytes < 10 ? 2 :
                                                 0)
           << megabytes << " MB";
    return text.str();
  }
} // namespace porofrac
