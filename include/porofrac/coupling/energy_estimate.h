// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_COUPLING_ENERGY_ESTIMATE_H
#define POROFRAC_COUPLING_ENERGY_ESTIMATE_H

#include <porofrac/coupling/poromechanics.h>
#include <porofrac/io/checkpoint.h>

namespace porofrac
{
  namespace coupling
  {
    /**
     * The stored energy of the discrete energy estimate (19) (J; per radian... the weights of
     * the axisymmetric measures apply):
     *   E = sum_K phi_K U_m(p_c,K) |K| + sum_sigma d_f U_f(p_c,sigma) |sigma|
     *       + 1/2 a(u, u) + sum_K (p_E,K)^2 |K| / (2 M).
     */
    struct EnergyTerms
    {
      double capillary_matrix   = 0;
      double capillary_fracture = 0;
      double elastic            = 0;
      double storage            = 0; ///< sum (p_E)^2 |K| / (2M)

      double
      total() const
      {
        return capillary_matrix + capillary_fracture + elastic + storage;
      }
    };

    /**
     * The balance of (19) over one time step t_k -> t_{k+1}: testing (11a) with p^alpha and
     * (11b) with u - u_old and using the convexity of U gives
     *   E_{k+1} - E_k + dissipation + friction_work <= supplied,
     * with the flow dissipation dt sum_alpha sum_c T_c eta^alpha_up (p^alpha_a - p^alpha_b)^2
     * over connections between unknown nodes, the frictional work int_Gamma lambda . [u - u_old]
     * (eq. (17), >= 0), and the work supplied by the mechanical loads, f_ext . (u - u_old), and
     * by the Dirichlet flow boundaries and sources.
     */
    struct StepEnergy
    {
      EnergyTerms energy;            ///< at t_{k+1}
      double      change        = 0; ///< E_{k+1} - E_k
      double      dissipation   = 0;
      double      friction_work = 0;
      double      supplied_work = 0;
      /// max(0, change + dissipation + friction work - supplied) relative to the sum of the
      /// magnitudes of the terms plus the coupling tolerance times |E_{k+1}| (the resolution of
      /// the terms): 0 when the inequality holds.
      double violation = 0;
    };

    /// Records the energy estimate (19) of a coupled run, step by step.
    template <int dim>
    class EnergyEstimate
    {
    public:
      /// Starts the record at the current (initial) state of @p problem.
      explicit EnergyEstimate(const Poromechanics<dim> &problem);

      /// The stored energy E of the problem's current state.
      EnergyTerms
      stored_energy() const;

      /// The balance of the step just solved (to be called before accept_time_step(), while
      /// the accepted state is the start of the step); its energy becomes the reference of
      /// the next step.
      StepEnergy
      record_step();

      /// The reference energy and the largest violation, for checkpoints.
      void
      save(io::CheckpointWriter &checkpoint) const;
      void
      load(io::CheckpointReader &checkpoint);

      /// The stored energy of the last recorded step (of the initial state before the first):
      /// the state a run ends in, also after a failed step was rolled back.
      const EnergyTerms &
      last_stored_energy() const
      {
        return previous;
      }

      /// Largest violation recorded.
      double
      max_violation() const
      {
        return largest_violation;
      }

    private:
      const Poromechanics<dim> &problem;
      EnergyTerms               previous;
      double                    largest_violation = 0;
    };
  } // namespace coupling
} // namespace porofrac

#endif
