// SPDX-License-Identifier: LGPL-2.1-or-later
// The time loop stops a run that runs out of memory in a time step, after writing the last
// accepted state: an InsufficientMemory (a solver's memory check) or a failed allocation
// (std::bad_alloc, on one process) thrown by the third step's attempt ends the loop with an
// InsufficientMemory that names the scene and the time, without cutting the step (a shorter step
// needs the same memory); the accepted state is restored and written once, and the totals are
// recorded; the third attempt is the last. A step that fails without an exception is cut and
// retried, for comparison.
#include <deal.II/base/mpi.h>

#include <porofrac/app/time_loop.h>
#include <porofrac/base/exceptions.h>

#include <iostream>
#include <new>
#include <string>

namespace
{
  using porofrac::app::StepOutcome;

  /// Runs 5 steps of 1 s; the attempt at t = 2 s ends as @p how says.
  void
  run(const std::string &how)
  {
    std::cout << how << ":" << std::endl;
    porofrac::AdaptiveTimeStepper stepper(5, 1, 1, 1, 3);
    dealii::ConditionalOStream    progress(std::cout, true);
    unsigned int                  attempts = 0;
    const auto                    attempt  = [&](const double dt) -> StepOutcome {
      ++attempts;
      if (stepper.time() == 2)
        {
          if (how == "a memory check refuses")
            throw porofrac::InsufficientMemory("the factorization would need 9 GB, more than the 1 "
                                                                   "GB available");
          if (how == "an allocation fails")
            throw std::bad_alloc();
          if (dt == 1)
            return {false, "no convergence"};
        }
      return {true, ""};
    };
    const auto write_state = [&](const bool restore_first) {
      std::cout << "  last accepted state written at t = " << stepper.time()
                << (restore_first ? ", restored first" : "") << std::endl;
    };
    try
      {
        porofrac::app::run_time_loop(
          stepper,
          "Test scene",
          [] {},
          attempt,
          [&] { std::cout << "  accepted t = " << stepper.time() << std::endl; },
          write_state,
          progress,
          MPI_COMM_SELF,
          [] { std::cout << "  totals recorded" << std::endl; });
        std::cout << "  finished" << std::endl;
      }
    catch (const porofrac::InsufficientMemory &e)
      {
        std::cout << "  InsufficientMemory: " << e.what() << std::endl;
      }
    std::cout << "  attempts " << attempts << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run("a memory check refuses");
  run("an allocation fails");
  run("a step does not converge");
}
