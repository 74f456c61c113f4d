// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_AMG_PRECONDITIONER_H
#define POROFRAC_BASE_AMG_PRECONDITIONER_H

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <string>

namespace porofrac
{
  /// The settings of the smoothed-aggregation AMG (Trilinos ML) of the iterative flow solvers.
  struct AmgSettings
  {
    /// Couplings below this times the geometric mean of their two diagonal entries are dropped
    /// before aggregating (ML's default 1e-4).
    double aggregation_threshold = 1e-4;
    /// "uncoupled": each process aggregates its own rows (ML's "Uncoupled", its default);
    /// "mis": aggregates are maximal independent sets of the whole graph, across process
    /// boundaries (ML's "MIS", a dearer set-up).
    std::string aggregation = "uncoupled";
  };

  /// The aggregation names AmgSettings::aggregation accepts, as a Patterns::Selection string.
  inline constexpr const char *amg_aggregation_names = "uncoupled|mis";

  /// Sets up @p amg for @p matrix: @p data (smoother, null space, ...) with the threshold and
  /// aggregation scheme of @p settings.
  void
  initialize_amg(dealii::TrilinosWrappers::PreconditionAMG                &amg,
                 const dealii::TrilinosWrappers::SparseMatrix             &matrix,
                 dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data,
                 const AmgSettings                                        &settings);
} // namespace porofrac

#endif
