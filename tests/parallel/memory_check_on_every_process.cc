// SPDX-License-Identifier: LGPL-2.1-or-later
// require_memory_on_every_process() on two processes of one machine: the needs of the processes
// count together against the machine's memory (100 MB each passes alone under a 150 MB limit, is
// refused together, passes under 250 MB); a need that only one process has stops both with the
// same message; a need above one process's address-space headroom (ulimit -v, set on rank 1
// only) stops both, naming the address-space limit, where the need in address space (not the
// resident one) is above it. On MPI_COMM_SELF each process counts alone.
// mpi: 2
#include <deal.II/base/mpi.h>

#include <porofrac/base/available_memory.h>
#include <porofrac/base/exceptions.h>

#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "../address_space.h"
#include <sys/resource.h>

namespace
{
  namespace mpi_utils = dealii::Utilities::MPI;


  /// Runs the check on @p comm and prints, on rank 0, each process's outcome (the messages of
  /// the two processes must be the same).
  void
  check(const std::string &title,
        const double       process_mb,
        const double       machine_limit_mb,
        const MPI_Comm     comm = MPI_COMM_WORLD)
  {
    std::string outcome = "passes";
    try
      {
        porofrac::require_memory_on_every_process(process_mb,
                                                  "a test allocation would need at least %",
                                                  "use less",
                                                  comm,
                                                  machine_limit_mb);
      }
    catch (const porofrac::InsufficientMemory &e)
      {
        outcome = std::string("refused: ") + e.what();
      }
    const std::vector<std::string> outcomes = mpi_utils::gather(MPI_COMM_WORLD, outcome);
    if (mpi_utils::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::cout << title << std::endl;
        for (unsigned int rank = 0; rank < outcomes.size(); ++rank)
          std::cout << "  rank " << rank << ": " << outcomes[rank] << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank = mpi_utils::this_mpi_process(MPI_COMM_WORLD);

  check("100 MB on each process, 150 MB on the machine", 100, 150);
  check("100 MB on each process, 250 MB on the machine", 100, 250);
  check("100 MB on rank 1 only, 50 MB on the machine", rank == 1 ? 100 : 0, 50);
  check("each process alone: 100 MB, 150 MB on the machine", 100, 150, MPI_COMM_SELF);

  rlimit original{};
  getrlimit(RLIMIT_AS, &original);
  const bool unlimited =
    mpi_utils::min(original.rlim_cur == RLIM_INFINITY ? 1 : 0, MPI_COMM_WORLD) == 1;
  if (!unlimited)
    {
      if (rank == 0)
        std::cout << "the test runs under an address-space limit already" << std::endl;
      return 1;
    }
  if (rank == 1)
    {
      rlimit limited   = original;
      limited.rlim_cur = static_cast<rlim_t>((porofrac_tests::mapped_kb() + 200 * 1024.) * 1024.);
      setrlimit(RLIMIT_AS, &limited);
    }
  // The headroom of rank 1 (150-200 MB) varies from run to run: only whether its limit is named.
  std::string outcome = "passes";
  try
    {
      // The resident need is small; the address space it maps is what the limit refuses.
      porofrac::require_memory_on_every_process(
        1, "a test allocation would need at least %", "", MPI_COMM_WORLD, 1e9, rank == 1 ? 400 : 1);
    }
  catch (const porofrac::InsufficientMemory &e)
    {
      const std::string message = e.what();
      outcome                   = "refused, need 400 MB and the address-space limit named: " +
                std::string(message.find("a test allocation would need at least 400 MB, "
                                         "more than the ") == 0 ?
                              "yes" :
                              "no") +
                ", " +
                (message.find("that a process may still allocate under its address-space "
                              "limit (ulimit -v or -d)") != std::string::npos ?
                   "yes" :
                   "no");
    }
  // A resident need above the headroom passes where the address space it maps is small.
  std::string resident = "passes";
  try
    {
      porofrac::require_memory_on_every_process(
        rank == 1 ? 400 : 1, "%", "", MPI_COMM_WORLD, 1e9, 1);
    }
  catch (const porofrac::InsufficientMemory &)
    {
      resident = "refused";
    }
  if (rank == 1)
    setrlimit(RLIMIT_AS, &original);
  const std::vector<std::string> outcomes = mpi_utils::gather(MPI_COMM_WORLD, outcome);
  if (rank == 0)
    {
      std::cout << "400 MB of address space on rank 1, 200 MB above its address space "
                   "(ulimit -v on rank 1)"
                << std::endl;
      for (unsigned int r = 0; r < outcomes.size(); ++r)
        std::cout << "  rank " << r << ": " << outcomes[r] << std::endl;
    }
  const std::vector<std::string> residents = mpi_utils::gather(MPI_COMM_WORLD, resident);
  if (rank == 0)
    std::cout << "400 MB resident and 1 MB of address space on rank 1, under the same limit: "
              << residents[0] << ", " << residents[1] << std::endl;
  check("limit lifted: 100 MB on each process, 250 MB on the machine", 100, 250);
}
