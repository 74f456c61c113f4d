// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_EXCEPTIONS_H
#define POROFRAC_BASE_EXCEPTIONS_H

#include <stdexcept>
#include <string>

namespace porofrac
{
  /**
   * An error in the user's input: a deck parameter with an impossible value, malformed geometry,
   * a missing file. It names the parameter (as "Section/Subsection/Name") and the reason; main()
   * adds the deck name and exits with status 1, so that bad input never ends in a crash.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &parameter, const std::string &reason)
        : std::runtime_error("parameter '" + parameter + "': " + reason)
        , parameter(parameter)
        , reason(reason)
    {
    }

    const std::string parameter;
    const std::string reason;
  };

  /**
   * A nonlinear or linear solve that failed after every remedy (time-step cuts, globalization).
   * main() reports it with the last good state already written.
   */
  class SolverFailure : public std::runtime_error
  {
  public:
    explicit SolverFailure(const std::string &what)
        : std::runtime_error(what)
    {
    }
  };

  /**
   * The run has not enough memory: a solver found, before allocating it, that its factorization
   * or dense matrices would need more than the run has (available_memory_mb()), a library
   * reported that it ran out of memory, or an allocation failed (std::bad_alloc, converted where
   * the run can still stop cleanly: the time loop, app::run_scene). No other direct solver is
   * tried in its place, as it would need at least as much, and a time step is not cut for it, as a
   * shorter step needs the same memory. main() reports it as "out of memory" (exit status 3).
   */
  class InsufficientMemory : public SolverFailure
  {
  public:
    explicit InsufficientMemory(const std::string &what)
        : SolverFailure(what)
    {
    }
  };

  /// The reason an InsufficientMemory converted from std::bad_alloc gives.
  inline constexpr const char *out_of_memory_reason =
    "a memory allocation failed (out of memory); use a coarser mesh, more memory or more "
    "processes";

  /**
   * The run was asked to stop (SIGINT or SIGTERM, see base/interrupt.h). Time-dependent scenes
   * throw it between steps, after writing the last accepted state; main() writes summary.json
   * with status "interrupted".
   */
  class Interrupted : public std::runtime_error
  {
  public:
    explicit Interrupted(const std::string &what)
        : std::runtime_error(what)
    {
    }
  };

/// Throws the InputError @p error unless @p condition holds (the message is built lazily).
#define POROFRAC_CHECK_INPUT(condition, error) \
  do                                           \
    {                                          \
      if (!(condition))                        \
        throw error;                           \
    }                                          \
  while (false)

  /// Throws InputError(parameter, reason) unless @p condition holds.
  inline void
  check_input(const bool condition, const std::string &parameter, const std::string &reason)
  {
    if (!condition)
      throw InputError(parameter, reason);
  }
} // namespace porofrac

#endif
