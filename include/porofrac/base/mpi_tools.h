// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_MPI_TOOLS_H
#define POROFRAC_BASE_MPI_TOOLS_H

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <porofrac/base/exceptions.h>

#include <array>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>
#include <tuple>

namespace porofrac
{
  /// What a process failed with (for collectively()).
  enum class FailureKind : int
  {
    none        = 0,
    input       = 1, ///< InputError
    solver      = 2, ///< SolverFailure
    interrupted = 3, ///< Interrupted
    internal    = 4, ///< any other std::exception
    memory      = 5  ///< InsufficientMemory (a SolverFailure that no time-step cut helps)
  };

  /**
   * Runs @p work on every process of @p communicator. If it throws on any of them (an
   * InputError, InsufficientMemory or std::bad_alloc (thrown as InsufficientMemory),
   * SolverFailure, Interrupted or another std::exception),
   * every process throws the same exception, with the message of the lowest failing rank,
   * after the vote. Work
   * whose outcome may differ between processes (a point constraint seen by one process only,
   * a file only rank 0 writes, a postprocessor that runs on rank 0) goes through here, so that
   * no process is left waiting in a collective call while another one has left with an error.
   */
  template <typename Work>
  void
  collectively(const MPI_Comm communicator, const Work &work)
  {
    namespace MPI = dealii::Utilities::MPI;
    std::tuple<int, std::string, std::string> failure{int(FailureKind::none), "", ""};
    try
      {
        work();
      }
    catch (const InputError &e)
      {
        failure = {int(FailureKind::input), e.parameter, e.reason};
      }
    catch (const InsufficientMemory &e)
      {
        failure = {int(FailureKind::memory), "", e.what()};
      }
    catch (const SolverFailure &e)
      {
        failure = {int(FailureKind::solver), "", e.what()};
      }
    catch (const Interrupted &e)
      {
        failure = {int(FailureKind::interrupted), "", e.what()};
      }
    catch (const std::bad_alloc &)
      {
        failure = {int(FailureKind::memory), "", out_of_memory_reason};
      }
    catch (const std::exception &e)
      {
        failure = {int(FailureKind::internal), "", e.what()};
      }
    // MPI_COMM_SELF needs no vote (and no MPI_Init: serial programs call this too).
    const unsigned int n = communicator == MPI_COMM_SELF ? 1 : MPI::n_mpi_processes(communicator);
    if (n > 1)
      {
        const bool         failed = std::get<0>(failure) != int(FailureKind::none);
        const unsigned int first =
          MPI::min(failed ? MPI::this_mpi_process(communicator) : n, communicator);
        if (first == n)
          return;
        failure = MPI::broadcast(communicator, failure, first);
      }
    const auto &[kind, parameter, message] = failure;
    switch (FailureKind(kind))
      {
        case FailureKind::none:
          return;
        case FailureKind::input:
          throw InputError(parameter, message);
        case FailureKind::solver:
          throw SolverFailure(message);
        case FailureKind::memory:
          throw InsufficientMemory(message);
        case FailureKind::interrupted:
          throw Interrupted(message);
        default:
          throw std::runtime_error(message);
      }
  }

  /// The sums of @p values over the processes of @p communicator on this machine, which share
  /// its memory (collective; one split of the communicator and one reduction).
  template <std::size_t n>
  std::array<double, n>
  sum_on_this_machine(const std::array<double, n> &values, const MPI_Comm communicator)
  {
    if (communicator == MPI_COMM_SELF)
      return values;
    MPI_Comm machine;
    MPI_Comm_split_type(communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &machine);
    std::array<double, n> sums;
    dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(values.data(), n),
                                machine,
                                dealii::ArrayView<double>(sums.data(), n));
    MPI_Comm_free(&machine);
    return sums;
  }

  /// The sum of @p value over the processes of @p communicator on this machine (collective).
  inline double
  sum_on_this_machine(const double value, const MPI_Comm communicator)
  {
    return sum_on_this_machine<1>({{value}}, communicator)[0];
  }

  /// The number of processes of @p communicator on this machine (collective).
  inline unsigned int
  processes_on_this_machine(const MPI_Comm communicator)
  {
    return static_cast<unsigned int>(std::lround(sum_on_this_machine(1., communicator)));
  }
} // namespace porofrac

#endif
