// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/coupling/parameters.h>
#include <porofrac/io/text.h>

namespace porofrac
{
  namespace coupling
  {
    using namespace dealii;

    void
    CouplingParameters::declare_parameters(ParameterHandler &prm)
    {
      FixedPointParameters::declare_parameters(prm);
      prm.enter_subsection("Coupling");
      prm.declare_entry("Biot coefficient",
                        "1",
                        Patterns::Double(),
                        "b in [0, 1] of eqs. (11b) and (11d) (-).");
      prm.declare_entry("Biot modulus",
                        "1e9",
                        Patterns::Double(),
                        "M > 0 in the porosity law (11d) (Pa).");
      prm.declare_entry("Capillary energy in p_E",
                        "true",
                        Patterns::Bool(),
                        "true: p_E = sum_alpha p^alpha s^alpha - U(p_c) (eq. (11d)); false: the "
                        "modified model of Remark 3.1 without U.");
      prm.declare_entry("Fixed point",
                        "equivalent pressure",
                        Patterns::Selection("equivalent pressure|displacement"),
                        "equivalent pressure: p_E = g_p(p_E) (mechanics, then flow); displacement: "
                        "u = g_u(u) (flow, then mechanics), iterated on the quantities of u the "
                        "flow sees (cell means of div u and face jumps [u]_n).");
      prm.declare_entry("Inner flow residual tolerance",
                        "1e-10",
                        Patterns::Double(0),
                        "Flow Newton relative residual inside coupled iterations.");
      prm.declare_entry("Inner flow update tolerance",
                        "1e-12",
                        Patterns::Double(0),
                        "Flow Newton relative update inside coupled iterations.");
      prm.declare_entry("Kozeny-Carman",
                        "true",
                        Patterns::Bool(),
                        "Matrix permeability K0 phi^3/(1-phi)^2 (1-phi0)^2/phi0^3 of the previous "
                        "step's porosity (explicit in time); false: K = K0.");
      prm.declare_entry("Extrapolate initial guess",
                        "false",
                        Patterns::Bool(),
                        "Start the fixed point of a time step from x_n + (dt_n/dt_{n-1}) (x_n - "
                        "x_{n-1}) (x = p_E or the displacement measures), the linear "
                        "extrapolation of the last two accepted steps; false: from x_n.");
      prm.leave_subsection();
    }



    void
    CouplingParameters::parse_parameters(ParameterHandler &prm)
    {
      fixed_point.parse_parameters(prm);
      prm.enter_subsection("Coupling");
      biot_coefficient = prm.get_double("Biot coefficient");
      biot_modulus     = prm.get_double("Biot modulus");
      capillary_energy = prm.get_bool("Capillary energy in p_E");
      variable         = prm.get("Fixed point") == "displacement" ? CouplingVariable::displacement :
                                                                    CouplingVariable::equivalent_pressure;
      inner_flow_residual_tolerance = prm.get_double("Inner flow residual tolerance");
      inner_flow_update_tolerance   = prm.get_double("Inner flow update tolerance");
      kozeny_carman                 = prm.get_bool("Kozeny-Carman");
      extrapolate_initial_guess     = prm.get_bool("Extrapolate initial guess");
      prm.leave_subsection();
      check_input(biot_coefficient >= 0 && biot_coefficient <= 1,
                  "Coupling/Biot coefficient",
                  "must lie in [0, 1], got " + io::to_text(biot_coefficient));
      check_input(biot_modulus > 0,
                  "Coupling/Biot modulus",
                  "must be positive, got " + io::to_text(biot_modulus));
    }
  } // namespace coupling
} // namespace porofrac
