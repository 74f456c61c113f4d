// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_COUPLING_BIOT_STORAGE_H
#define POROFRAC_COUPLING_BIOT_STORAGE_H

#include <porofrac/flow/saturation_law.h>
#include <porofrac/flow/storage_model.h>
#include <porofrac/flow/tpfa_grid.h>

#include <array>
#include <memory>
#include <vector>

namespace porofrac
{
  namespace coupling
  {
    /**
     * The linearised Biot storage of eq. (11d) as the flow's pore-volume law: the porosity of
     * matrix cell K is
     *   phi_K = phi_u,K + (p_E,K - p_E0,K) / M,   phi_u = phi_0 + b div(u - u_0),
     * with p_E of the cell's phase pressures (coupling::equivalent_pressure, with or without U).
     * phi_u is frozen during a flow solve (set by the mechanics between solves); the p_E term is
     * implicit in the unknowns, so the flow Jacobian contains its derivatives.
     */
    template <int dim>
    class BiotStorage : public flow::StorageModel
    {
    public:
      /**
       * @p law: the matrix saturation law; @p p_E_reference: p_E0 per matrix cell;
       * @p displacement_porosity: the initial phi_u per matrix cell. InputError naming
       * "Coupling/Biot modulus" for a negative or non-finite 1/M.
       */
      BiotStorage(const flow::TpfaGrid<dim>                        &grid,
                  const std::shared_ptr<const flow::SaturationLaw> &law,
                  const double                                      inverse_biot_modulus,
                  const bool                                        capillary_energy,
                  const std::vector<double>                        &p_E_reference,
                  const std::vector<double>                        &displacement_porosity);

      /// Sets phi_u = phi_0 + b div(u - u_0) per matrix cell (coupling::displacement_porosity).
      void
      set_displacement_porosity(const std::vector<double> &phi_u);
      const std::vector<double> &
      displacement_porosity() const
      {
        return phi_u;
      }

      /// phi_K at the absolute wetting pressure @p p_w and capillary pressure @p p_c.
      double
      porosity(const unsigned int K, const double p_w, const double p_c) const;

      double
      pore_volume(const unsigned int     K,
                  const double           p_w,
                  const double           p_c,
                  std::array<double, 2> &derivative) const override;

    private:
      const flow::TpfaGrid<dim>                       &grid;
      const std::shared_ptr<const flow::SaturationLaw> law;
      const double                                     inverse_biot_modulus;
      const bool                                       capillary_energy;
      const std::vector<double>                        p_E_reference;
      std::vector<double>                              phi_u;
    };
  } // namespace coupling
} // namespace porofrac

#endif
