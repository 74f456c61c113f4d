// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_COUPLING_PARAMETERS_H
#define POROFRAC_COUPLING_PARAMETERS_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/coupling/newton_krylov.h>

#include <string>
#include <vector>

namespace porofrac
{
  namespace coupling
  {
    /// Which fixed point a coupled time step solves (paper, Section 5 opening).
    enum class CouplingVariable
    {
      /// p_E = g_p(p_E): contact mechanics with p_E, then two-phase flow with u.
      equivalent_pressure,
      /// u = g_u(u): two-phase flow with u, then contact mechanics with p_E.
      displacement
    };

    /// Deck subsection "Coupling": Biot data of eq. (11d), the per-step fixed point and the
    /// outputs of coupled scenes.
    struct CouplingParameters
    {
      double biot_coefficient = 1.;  ///< b in [0, 1]
      double biot_modulus     = 1e9; ///< M > 0 (Pa)
      /// p_E with the capillary energy U of (11d); false = the modified model of Remark 3.1.
      bool             capillary_energy = true;
      CouplingVariable variable         = CouplingVariable::equivalent_pressure;
      /// Flow Newton tolerances inside coupled iterations (tight: Newton-Krylov differences
      /// the coupled map, so inner noise must stay far below the finite-difference step).
      double inner_flow_residual_tolerance = 1e-10;
      double inner_flow_update_tolerance   = 1e-12;
      /// Kozeny-Carman permeability of the previous step's porosity (explicit in time).
      bool kozeny_carman = true;
      /// Start each step's fixed point from the linear extrapolation in time of the last two
      /// accepted states instead of the last one.
      bool extrapolate_initial_guess = false;
      /// Distributed runs: solve the contact problem with the distributed code
      /// (mechanics::DistributedContactProblem) instead of the serial code on every process.
      bool                 distributed_contact = false;
      FixedPointParameters fixed_point;
      /// Times (s, sorted) at which fractures.csv rows and fields are written; the time steps
      /// land on them.
      std::vector<double> output_times;
      /// "none" or "terzaghi": errors against Terzaghi's consolidation at the final time.
      std::string analytical_solution = "none";

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(const dealii::ParameterHandler &prm);
      void
      validate() const;
    };
  } // namespace coupling
} // namespace porofrac

#endif
