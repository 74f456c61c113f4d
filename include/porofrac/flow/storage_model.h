// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_STORAGE_MODEL_H
#define POROFRAC_FLOW_STORAGE_MODEL_H

#include <porofrac/flow/tpfa_grid.h>

#include <array>

namespace porofrac
{
  namespace flow
  {
    /**
     * Pore volume of the matrix cells as a function of their phase pressures: the PV of the
     * accumulation PV S^alpha in scheme (11a). The two-phase solver differentiates through it,
     * so that a porosity depending on the unknowns (the Biot storage of eq. (11d), implemented by
     * the coupling module) enters the Newton Jacobian.
     */
    class StorageModel
    {
    public:
      virtual ~StorageModel() = default;

      /**
       * Pore volume of matrix cell @p K (active cell index) at the absolute wetting pressure
       * @p p_w and the capillary pressure @p p_c = p^nw - p^w (Pa), with its derivatives with
       * respect to (p^w, p^nw) in @p derivative.
       */
      virtual double
      pore_volume(const unsigned int     K,
                  const double           p_w,
                  const double           p_c,
                  std::array<double, 2> &derivative) const = 0;
    };

    /// Pore volumes that do not depend on the pressures: |K| phi_K with phi_K = grid.porosity[K]
    /// at the time of the call (another module may change it between time steps).
    template <int dim>
    class GridPorosity : public StorageModel
    {
    public:
      explicit GridPorosity(const TpfaGrid<dim> &grid)
          : grid(grid)
      {
      }

      double
      pore_volume(const unsigned int K,
                  const double /*p_w*/,
                  const double /*p_c*/,
                  std::array<double, 2> &derivative) const override
      {
        derivative = {{0., 0.}};
        return grid.pore_volume(K);
      }

    private:
      const TpfaGrid<dim> &grid;
    };
  } // namespace flow
} // namespace porofrac

#endif
