// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_ROCK_TYPE_H
#define POROFRAC_FLOW_ROCK_TYPE_H

#include <porofrac/flow/relative_permeability.h>
#include <porofrac/flow/saturation_law.h>

#include <memory>
#include <string>
#include <vector>

namespace porofrac
{
  namespace flow
  {
    /// Rock types: 0 = matrix, 1 = fracture (also the rock of the interface layer, as in 5.3).
    enum Rock : unsigned int
    {
      matrix_rock   = 0,
      fracture_rock = 1
    };

    /// One rock type: saturation law, relative permeabilities, and the two viscosities (Pa s).
    struct RockType
    {
      std::shared_ptr<const SaturationLaw>        saturation;
      std::shared_ptr<const RelativePermeability> relative_permeability;
      double                                      viscosity[2] = {1e-3, 1e-3};
      /// Added to k_r inside the mobility to keep the phase-pressure system non-singular where a
      /// phase is absent; 0 gives the exact law.
      double mobility_floor = 0.;
      /// The floor of the non-wetting phase (negative: mobility_floor).
      double mobility_floor_nw = -1.;

      /// Mobility eta^alpha = (k_r^alpha(s^nw) + floor) / mu^alpha and d eta/d s^nw.
      double
      mobility(const unsigned int phase, const double s_nw) const
      {
        const double floor =
          phase == 1 && mobility_floor_nw >= 0 ? mobility_floor_nw : mobility_floor;
        return (relative_permeability->value(phase, s_nw) + floor) / viscosity[phase];
      }
      double
      mobility_derivative(const unsigned int phase, const double s_nw) const
      {
        return relative_permeability->derivative(phase, s_nw) / viscosity[phase];
      }

      /// InputErrors naming @p viscosity_section + "/Viscosity w" (or nw) for non-positive
      /// viscosities, @p rock_section + "/Mobility floor" for a negative floor and
      /// @p rock_section + "/Saturation law" (or "/Relative permeability") for a missing law.
      void
      validate(const std::string &viscosity_section, const std::string &rock_section) const;
    };

    /**
     * For the declare functions of registered laws whose default values differ between the
     * rocks: @p matrix_value while FlowParameters::declare_parameters declares the entries of
     * subsection Flow/Matrix, @p fracture_value in Flow/Fracture (@p matrix_value otherwise).
     */
    std::string
    rock_default(const std::string &matrix_value, const std::string &fracture_value);

    /// "Flow/Matrix/Corey R" for @p path = {"Flow", "Matrix"} and @p entry = "Corey R": the
    /// parameter that the InputErrors of registered laws name.
    std::string
    entry_name(const std::vector<std::string> &path, const std::string &entry);
  } // namespace flow
} // namespace porofrac

#endif
