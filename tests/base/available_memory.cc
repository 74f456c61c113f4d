// SPDX-License-Identifier: LGPL-2.1-or-later
// The memory a process may still take: the headroom of its memory control groups, read from
// fake cgroup trees in a temporary directory. cgroup v2: a group limited to 2048 MB using 1024 MB
// of which 512 MB are inactive page cache has 1536 MB left, and its child without a limit
// ("max") inherits that; v1 with a container's view (the path of /proc/self/cgroup names host
// groups the mount does not show): the job's 3072 MB limit less its 1024 MB; a group whose
// ancestors have lower headroom gets theirs; no limit anywhere gives 0. The machine's own figure
// is positive.
#include <porofrac/base/available_memory.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>

namespace
{
  namespace fs = std::filesystem;

  void
  write(const fs::path &file, const std::string &text)
  {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text << "\n";
  }

  std::string
  megabytes(const double mb)
  {
    return std::to_string(static_cast<long long>(mb * 1024 * 1024));
  }
} // namespace

int
main()
{
  const fs::path root =
    fs::temp_directory_path() / ("porofrac-cgroups-" + std::to_string(::getpid()));

  // cgroup v2: /a limited, /a/b not.
  const fs::path v2 = root / "v2";
  write(v2 / "cgroup.controllers", "memory");
  write(v2 / "memory.stat", "inactive_file 0");
  write(v2 / "a" / "memory.max", megabytes(2048));
  write(v2 / "a" / "memory.current", megabytes(1024));
  write(v2 / "a" / "memory.stat", "active_file 100\ninactive_file " + megabytes(512));
  write(v2 / "a" / "b" / "memory.max", "max");
  write(v2 / "a" / "b" / "memory.current", megabytes(10));
  write(v2 / "a" / "b" / "memory.stat", "inactive_file 0");
  std::cout << "v2, limited group: " << porofrac::internal::cgroup_headroom_mb(v2, "/a", true)
            << " MB" << std::endl;
  std::cout << "v2, its child without a limit: "
            << porofrac::internal::cgroup_headroom_mb(v2, "/a/b", true) << " MB" << std::endl;

  // cgroup v1 seen from a container: /proc/self/cgroup says /host/container/job, the mount shows
  // the container's group as its root (no limit) and job below it.
  const fs::path v1 = root / "v1";
  write(v1 / "memory.limit_in_bytes", "9223372036854771712");
  write(v1 / "memory.usage_in_bytes", megabytes(5000));
  write(v1 / "memory.stat", "total_inactive_file 0");
  write(v1 / "job" / "memory.limit_in_bytes", megabytes(3072));
  write(v1 / "job" / "memory.usage_in_bytes", megabytes(1024));
  write(v1 / "job" / "memory.stat", "cache 0\ntotal_inactive_file 0");
  std::cout << "v1, a job in a container: "
            << porofrac::internal::cgroup_headroom_mb(v1, "/host/container/job", false) << " MB"
            << std::endl;
  // A step below the job with a higher limit than the job has left: the job's headroom.
  write(v1 / "job" / "step" / "memory.limit_in_bytes", megabytes(2500));
  write(v1 / "job" / "step" / "memory.usage_in_bytes", megabytes(100));
  write(v1 / "job" / "step" / "memory.stat", "total_inactive_file 0");
  std::cout << "v1, a step whose job has less left: "
            << porofrac::internal::cgroup_headroom_mb(v1, "/host/container/job/step", false)
            << " MB" << std::endl;
  std::cout << "v1, the container's group (no limit): "
            << porofrac::internal::cgroup_headroom_mb(v1, "/host/container", false) << " MB"
            << std::endl;

  std::cout << "this machine: positive: " << (porofrac::available_memory_mb() > 0 ? "yes" : "no")
            << std::endl;
  fs::remove_all(root);
}
