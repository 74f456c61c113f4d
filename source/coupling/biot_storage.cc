// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/coupling/biot_storage.h>
#include <porofrac/coupling/closure.h>

#include <cmath>

namespace porofrac
{
  namespace coupling
  {
    template <int dim>
    BiotStorage<dim>::BiotStorage(const flow::TpfaGrid<dim>                        &grid,
                                  const std::shared_ptr<const flow::SaturationLaw> &law,
                                  const double               inverse_biot_modulus,
                                  const bool                 capillary_energy,
                                  const std::vector<double> &p_E_reference,
                                  const std::vector<double> &displacement_porosity)
        : grid(grid)
        , law(law)
        , inverse_biot_modulus(inverse_biot_modulus)
        , capillary_energy(capillary_energy)
        , p_E_reference(p_E_reference)
    {
      AssertThrow(p_E_reference.size() == grid.n_matrix_cells,
                  dealii::ExcDimensionMismatch(p_E_reference.size(), grid.n_matrix_cells));
      check_input(std::isfinite(inverse_biot_modulus) && inverse_biot_modulus >= 0,
                  "Coupling/Biot modulus",
                  "1/M must be finite and non-negative");
      set_displacement_porosity(displacement_porosity);
    }

    template <int dim>
    void
    BiotStorage<dim>::set_displacement_porosity(const std::vector<double> &phi)
    {
      AssertThrow(phi.size() == grid.n_matrix_cells,
                  dealii::ExcDimensionMismatch(phi.size(), grid.n_matrix_cells));
      phi_u = phi;
    }

    template <int dim>
    double
    BiotStorage<dim>::porosity(const unsigned int K, const double p_w, const double p_c) const
    {
      AssertIndexRange(K, grid.n_matrix_cells);
      if (inverse_biot_modulus == 0)
        return phi_u[K];
      const double p_E = equivalent_pressure(*law, p_w, p_c, capillary_energy);
      return coupling::porosity(phi_u[K], p_E - p_E_reference[K], inverse_biot_modulus);
    }

    template <int dim>
    double
    BiotStorage<dim>::pore_volume(const unsigned int     K,
                                  const double           p_w,
                                  const double           p_c,
                                  std::array<double, 2> &derivative) const
    {
      const double measure = grid.nodes[K].measure;
      derivative           = {{0., 0.}};
      if (inverse_biot_modulus != 0)
        {
          // d PV / d p^alpha = |K| (d p_E / d p^alpha) / M.
          const auto d = equivalent_pressure_derivatives(*law, p_c, capillary_energy);
          derivative   = {
              {measure * inverse_biot_modulus * d[0], measure * inverse_biot_modulus * d[1]}};
        }
      return measure * porosity(K, p_w, p_c);
    }

    template class BiotStorage<2>;
    template class BiotStorage<3>;
  } // namespace coupling
} // namespace porofrac
