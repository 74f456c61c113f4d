// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/coupling/parameters.h>
#include <porofrac/io/text.h>

#include <algorithm>

namespace porofrac
{
  namespace coupling
  {
    using namespace dealii;

    void
    CouplingParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Coupling");
      prm.declare_entry("Method",
                        "newton-krylov",
                        Patterns::Selection("newton-krylov|anderson|fixed point"),
                        "How each time step's fixed point is solved: Jacobian-free Newton-Krylov "
                        "acceleration (paper, Section 5), Anderson acceleration (one map "
                        "evaluation per iteration), or plain fixed-point iterations.");
      prm.declare_entry("Anderson depth",
                        "5",
                        Patterns::Integer(1),
                        "Anderson: number of previous residual differences in the least-squares "
                        "mixing.");
      prm.declare_entry("Tolerance",
                        "1e-6",
                        Patterns::Double(0),
                        "Stop at this relative increment or relative residual (paper: 1e-6).");
      prm.declare_entry("Max iterations",
                        "30",
                        Patterns::Integer(1),
                        "Newton (or fixed-point) iterations before the time step is cut.");
      prm.declare_entry("GMRES restart",
                        "30",
                        Patterns::Integer(1),
                        "Krylov space size of GMRES in each Newton step.");
      prm.declare_entry(
        "Max GMRES iterations",
        "30",
        Patterns::Integer(1),
        "GMRES iterations per Newton step (each costs one coupled map evaluation).");
      prm.declare_entry("Forcing term max",
                        "0.1",
                        Patterns::Double(0, 1),
                        "Upper bound of the Eisenstat-Walker relative GMRES tolerance.");
      prm.declare_entry("Fracture output times",
                        "",
                        Patterns::Anything(),
                        "Comma-separated times (s) at which fractures.csv rows and the fields are "
                        "written: the time steps are shortened to land on them; t = 0 and the "
                        "final time always are.");
      prm.declare_entry("Analytical solution",
                        "none",
                        Patterns::Selection("none|terzaghi"),
                        "terzaghi: at the final time, the relative L2 error of the matrix wetting "
                        "pressure against Terzaghi's consolidation of a laterally confined column, "
                        "drained at the top (largest y) through a Dirichlet condition and loaded "
                        "by a constant pressure (coupling/analytical.h).");

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
      prm.declare_entry(
        "Distributed contact mechanics",
        "false",
        Patterns::Bool(),
        "Distributed runs (more than one MPI process, or Distributed = always): true solves the "
        "contact problem with the distributed code (partitioned matrices, Mechanics/Distributed "
        "linear solver: MUMPS or AMG-preconditioned GMRES; doc/parallel.md) and copies its "
        "solution to every process after each solve; false: every process solves the serial "
        "contact problem (Mechanics/Linear solver). Serial runs ignore it.");
      prm.leave_subsection();
    }



    void
    CouplingParameters::parse_parameters(const ParameterHandler &prm)
    {
      const std::vector<std::string> c  = {"Coupling"};
      FixedPointParameters          &fp = fixed_point;
      fp.method                         = prm.get(c, "Method");
      fp.tolerance                      = prm.get_double(c, "Tolerance");
      fp.max_iterations                 = prm.get_integer(c, "Max iterations");
      fp.gmres_restart                  = prm.get_integer(c, "GMRES restart");
      fp.max_gmres_iterations           = prm.get_integer(c, "Max GMRES iterations");
      fp.eta_max                        = prm.get_double(c, "Forcing term max");
      fp.anderson_depth                 = prm.get_integer(c, "Anderson depth");
      biot_coefficient                  = prm.get_double(c, "Biot coefficient");
      biot_modulus                      = prm.get_double(c, "Biot modulus");
      capillary_energy                  = prm.get_bool(c, "Capillary energy in p_E");
      variable                          = prm.get(c, "Fixed point") == "displacement" ?
                                            CouplingVariable::displacement :
                                            CouplingVariable::equivalent_pressure;
      inner_flow_residual_tolerance     = prm.get_double(c, "Inner flow residual tolerance");
      inner_flow_update_tolerance       = prm.get_double(c, "Inner flow update tolerance");
      kozeny_carman                     = prm.get_bool(c, "Kozeny-Carman");
      extrapolate_initial_guess         = prm.get_bool(c, "Extrapolate initial guess");
      distributed_contact               = prm.get_bool(c, "Distributed contact mechanics");
      output_times.clear();
      for (const std::string &s :
           Utilities::split_string_list(prm.get(c, "Fracture output times"), ','))
        try
          {
            output_times.push_back(Utilities::string_to_double(s));
          }
        catch (...)
          {
            throw InputError("Coupling/Fracture output times", "'" + s + "' is not a number");
          }
      std::sort(output_times.begin(), output_times.end());
      analytical_solution = prm.get(c, "Analytical solution");
      validate();
    }



    void
    CouplingParameters::validate() const
    {
      check_input(fixed_point.tolerance > 0, "Coupling/Tolerance", "must be positive");
      check_input(biot_coefficient >= 0 && biot_coefficient <= 1,
                  "Coupling/Biot coefficient",
                  "must lie in [0, 1], got " + io::to_text(biot_coefficient));
      check_input(biot_modulus > 0,
                  "Coupling/Biot modulus",
                  "must be positive, got " + io::to_text(biot_modulus));
    }
  } // namespace coupling
} // namespace porofrac
