// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_CPR_PRECONDITIONER_H
#define POROFRAC_BASE_CPR_PRECONDITIONER_H

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <porofrac/base/amg_preconditioner.h>

namespace porofrac
{
  /**
   * Two-stage constrained-pressure-residual (CPR) preconditioner of a Jacobian J with
   * @p block_size unknowns per node (node k: unknowns b k, ..., b k + b - 1), for the
   * mass (volume) balances of several phases with one pressure per phase:
   *
   *   stage 1: A_p = R J P, R sums the b equations of a node, P moves its b pressures
   *            together (R = P^T = [1 ... 1] per node): the total-mobility pressure operator
   *            of the fully implicit system (true-IMPES decoupling for volume balances, whose
   *            accumulation terms cancel in the sum); x_1 = P AMG(A_p)^{-1} R r;
   *   stage 2: x = x_1 + ILU(J)^{-1} (r - J x_1) (ILU(0) on each process's rows).
   *
   * The elliptic part (pressure diffusion over the whole domain) goes to the AMG, the local
   * part (saturation, capillary coupling within a node and with its neighbours) to the ILU.
   * Each process's rows must be one contiguous range beginning at a node.
   */
  class CprPreconditioner
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// @p amg_settings: those of the AMG of the pressure stage.
    CprPreconditioner(const unsigned int block_size, const AmgSettings &amg_settings);

    /// Builds A_p, its AMG hierarchy and the ILU of @p jacobian, which must stay alive and
    /// unchanged while vmult() is used. The pattern of A_p is built for the first matrix.
    void
    initialize(const dealii::TrilinosWrappers::SparseMatrix &jacobian);

    /// dst = M^{-1} src.
    void
    vmult(VectorType &dst, const VectorType &src) const;

  private:
    void
    make_pressure_pattern(const dealii::TrilinosWrappers::SparseMatrix &jacobian);

    void
    assemble_pressure(const dealii::TrilinosWrappers::SparseMatrix &jacobian);

    const unsigned int                            block_size;
    const AmgSettings                             amg_settings;
    const dealii::TrilinosWrappers::SparseMatrix *jacobian = nullptr;
    dealii::IndexSet                              owned, owned_nodes;
    dealii::TrilinosWrappers::SparseMatrix        pressure;
    dealii::TrilinosWrappers::PreconditionAMG     amg;
    dealii::TrilinosWrappers::PreconditionILU     ilu;
    mutable VectorType                            pressure_rhs, pressure_x, first, residual;
  };
} // namespace porofrac

#endif
