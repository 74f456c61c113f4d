// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/amg_preconditioner.h>
#include <porofrac/base/exceptions.h>

#include <memory>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

namespace porofrac
{
  using namespace dealii;

  void
  initialize_amg(TrilinosWrappers::PreconditionAMG                &amg,
                 const TrilinosWrappers::SparseMatrix             &matrix,
                 TrilinosWrappers::PreconditionAMG::AdditionalData data,
                 const AmgSettings                                &settings)
  {
    AssertThrow(settings.aggregation == "mis" || settings.aggregation == "uncoupled",
                ExcMessage("AMG: unknown aggregation scheme '" + settings.aggregation + "'"));
    data.aggregation_threshold = settings.aggregation_threshold;
    // deal.II's AdditionalData has no aggregation type: it goes into ML's parameter list,
    // which keeps the entries AdditionalData does not set. The null space vectors must live
    // until ML has built the hierarchy.
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> null_space;
    data.set_parameters(parameters, null_space, matrix);
    parameters.set("aggregation: type",
                   std::string(settings.aggregation == "mis" ? "MIS" : "Uncoupled"));
    amg.initialize(matrix, parameters);
  }
} // namespace porofrac
