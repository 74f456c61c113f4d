// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/io/text.h>
#include <porofrac/mechanics/contact_linear_solver.h>
#include <porofrac/mechanics/contact_method.h>
#include <porofrac/mechanics/distributed_contact_linear_solver.h>
#include <porofrac/mechanics/parameters.h>

#include <cmath>
#include <sstream>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    namespace
    {
      std::string
      trim(const std::string &s)
      {
        return dealii::Utilities::trim(s);
      }

      unsigned int
      parse_id(const std::string &s, const std::string &parameter)
      {
        try
          {
            const int v = dealii::Utilities::string_to_int(trim(s));
            if (v < 0)
              throw 1;
            return v;
          }
        catch (...)
          {
            throw InputError(parameter, "'" + trim(s) + "' is not a non-negative integer id");
          }
      }

      /// "x=expr, y=expr" -> component -> expression.
      std::map<unsigned int, std::string>
      parse_components(const std::string &text,
                       const unsigned int dim,
                       const std::string &parameter)
      {
        std::map<unsigned int, std::string> m;
        for (const std::string &item : dealii::Utilities::split_string_list(text, ','))
          {
            const auto eq = item.find('=');
            if (eq == std::string::npos)
              throw InputError(parameter, "expected 'x=value' in '" + item + "'");
            const std::string name = trim(item.substr(0, eq));
            const std::string expr = trim(item.substr(eq + 1));
            unsigned int      c;
            if (name == "x")
              c = 0;
            else if (name == "y")
              c = 1;
            else if (name == "z" && dim == 3)
              c = 2;
            else
              throw InputError(parameter, "unknown component '" + name + "'");
            if (expr.empty())
              throw InputError(parameter, "empty value for component '" + name + "'");
            m[c] = expr;
          }
        return m;
      }
    } // namespace

    void
    ContactParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mechanics");
      prm.declare_entry("Young modulus", "25e9", Patterns::Double(), "E (Pa).");
      prm.declare_entry("Poisson ratio",
                        "0.25",
                        Patterns::Double(),
                        "nu, in (-1, 0.5). 2D is plane strain.");
      prm.declare_entry("Solver",
                        "active set",
                        Patterns::Selection(ContactMethodRegistry<2>::instance().selection()),
                        "Contact method: " + ContactMethodRegistry<2>::instance().documentation());
      prm.declare_entry("Complementarity parameter c",
                        "1e9",
                        Patterns::Double(),
                        "c > 0 in the complementarity functions (25)-(26) (Pa/m).");
      prm.declare_entry("Initial guess",
                        "stick",
                        Patterns::Selection("open|stick"),
                        "open: lambda = 0, u = 0; stick: lambda_n = Initial normal multiplier, "
                        "lambda_tau = 0, u = 0.");
      prm.declare_entry("Initial normal multiplier",
                        "100",
                        Patterns::Double(),
                        "lambda_n of the stick initial guess (Pa).");
      prm.declare_entry("Max iterations",
                        "50",
                        Patterns::Integer(1),
                        "Contact iterations before the solve fails.");
      prm.declare_entry("Tolerance",
                        "1e-6",
                        Patterns::Double(),
                        "Relative residual of the contact iterations.");
      prm.declare_entry("Line search",
                        "false",
                        Patterns::Bool(),
                        "Globalization: backtracking (Armijo) line search on the merit "
                        "max(scaled residual of (25)-(26) / |lambda|, mechanical residual / |f|).");
      prm.declare_entry("Line search halvings",
                        "6",
                        Patterns::Integer(0),
                        "At most this many step halvings per iteration; without sufficient "
                        "decrease the best step tried is taken.");
      prm.declare_entry("Line search memory",
                        "1",
                        Patterns::Integer(1),
                        "Sufficient decrease is measured against the largest merit of the last "
                        "M iterates (non-monotone line search); 1 is the monotone Armijo rule.");
      prm.declare_entry("Line search trigger",
                        "always",
                        Patterns::Selection("always|stagnation"),
                        "always: from the first iteration; stagnation: full steps until the "
                        "relative residual of an iterate is not below that of the previous one, "
                        "the line search from then on.");
      prm.declare_entry("Cycle damping",
                        "0",
                        Patterns::Double(),
                        "Globalization: when the face states (open/stick/slip) of an iterate "
                        "repeat those of an earlier, non-consecutive iterate, the step is "
                        "multiplied by this factor in (0, 1); 0 switches the safeguard off.");
      prm.declare_entry("Continuation c start",
                        "0",
                        Patterns::Double(),
                        "Globalization: continuation in c; the iterations start with this c and "
                        "move it towards `Complementarity parameter c` by `Continuation factor` "
                        "whenever the face states of an iterate equal those of the previous one "
                        "(0: off).");
      prm.declare_entry(
        "Multiplier stabilization",
        "0",
        Patterns::Double(),
        "alpha >= 0 of the multiplier stabilization (doc/algorithms.md §2.2): the contact "
        "conditions read the jump of a face minus sum over its neighbours in the same fracture "
        "of alpha h / E' (lambda_face - lambda_neighbour), h the mean face size, E' = E / (1 - "
        "nu^2): the compliance of a face bubble, which makes the face-wise constant multipliers "
        "stable against P2 on tetrahedra. It leaves multipliers constant on a fracture "
        "unchanged. 0: off (the paper's method). Contact-mechanics runs only; on one process "
        "with Linear solver = schur complement, or distributed (any Distributed linear "
        "solver).");
      prm.declare_entry("Continuation factor",
                        "100",
                        Patterns::Double(),
                        "Factor (> 1) by which c moves at each continuation step.");
      prm.declare_entry("Reuse factorization iterations",
                        "0",
                        Patterns::Integer(0),
                        "Linear solves of the contact iterations: first try GMRES preconditioned "
                        "by the LU factors of the last factorized matrix (only face rows change), "
                        "at most this many GMRES steps (relative residual 1e-12), then "
                        "refactorize; 0 factorizes every iteration.");
      prm.declare_entry("Linear solver",
                        "full system",
                        Patterns::Selection(ContactLinearSolverRegistry<2>::instance().selection()),
                        "Linear solves of the contact iterations. " +
                          ContactLinearSolverRegistry<2>::instance().documentation());
      prm.declare_entry(
        "Distributed linear solver",
        "direct",
        Patterns::Selection(DistributedContactLinearSolverRegistry<2>::instance().selection()),
        "Linear solves of the contact iterations in distributed runs (more than one MPI "
        "process, doc/parallel.md). " +
          DistributedContactLinearSolverRegistry<2>::instance().documentation());
      prm.declare_entry("Linear solver tolerance",
                        "1e-2",
                        Patterns::Double(),
                        "Iterative linear solvers: the relative residual of each Newton step is "
                        "min(this, Linear solver forcing x the relative residual of the last "
                        "contact iterate) (inexact steps).");
      prm.declare_entry("Linear solver forcing",
                        "0.1",
                        Patterns::Double(),
                        "Iterative linear solvers: see Linear solver tolerance.");
      prm.declare_entry("Max linear iterations",
                        "200",
                        Patterns::Integer(1),
                        "Iterative linear solvers: Krylov iterations per solve before the step "
                        "is solved by the direct solver instead (counted in summary.json, "
                        "mechanics/linear_direct_fallbacks).");
      prm.declare_entry(
        "AMG prolongator",
        "smoothed",
        Patterns::Selection("smoothed|unsmoothed"),
        "Iterative linear solver: the prolongator of the AMG hierarchy of the elasticity block. "
        "'smoothed': smoothed aggregation (fewer Krylov iterations); 'unsmoothed': the "
        "tentative prolongator of plain aggregation, about half the memory of the whole run "
        "for 3D P2 (the smoothed prolongator's Galerkin products dominate it) for about 1.4 "
        "times the iterations (doc/benchmarks/penny.md).");
      prm.declare_entry(
        "Schur complement scaling",
        "1",
        Patterns::Double(),
        "Iterative linear solver: the factor gamma of the multiplier block of its "
        "preconditioner, S~ = D - gamma W B_0 diag(K)^-1 B_0^T. diag(K)^-1 underestimates the "
        "compliance K^-1 the exact Schur complement holds; gamma = 3 to 5 saved 20 to 40 % of "
        "the GMRES iterations on the penny and 3D network decks, but can change the path of "
        "inexact contact iterations (doc/benchmarks/penny.md). Must be positive.");
      prm.declare_entry(
        "Report linear solve time",
        "false",
        Patterns::Bool(),
        "Also time one linear elasticity solve (every fracture open) on the "
        "same mesh: serial runs by UMFPACK (factorization + solve), distributed "
        "runs by the counterpart of Distributed linear solver (iterative: CG "
        "with the same AMG to Linear solver tolerance; direct: MUMPS); written "
        "to summary.json (mechanics/linear_solve_time_s and, in contact mechanics "
        "scenes, contact_linear_ratio); a reference that cannot be run (short of memory, or "
        "K singular without the contact rows) is reported there instead "
        "(mechanics/linear_solve_failure) and the run's results stand.");
      prm.declare_entry("Write P2 reconstruction",
                        "false",
                        Patterns::Bool(),
                        "2D: also write fracture_p2.csv, the paper's P2 reconstructions of the "
                        "jump and the multiplier (as in the 5.2.1 errors) at 3 Gauss points per "
                        "fracture face, in the face's local frame (n+, tangent), with the face's "
                        "abscissa interval: enough to evaluate the P2 fields anywhere on the "
                        "fracture (self-convergence studies, contrib/mechanics-convergence).");
      prm.declare_entry("Iteration table",
                        "false",
                        Patterns::Bool(),
                        "After the solve with the settings above (whose results are reported and "
                        "written), solve again for every contact method (active set, semismooth "
                        "newton) x c in {1e6, 1e9, 1e11} x initial guess (stick, open), each "
                        "from a cold start (initial guess, no state of the previous solve; the "
                        "other Mechanics settings, e.g. the globalization, as above), sharing the "
                        "assembled elasticity block and, with `Linear solver = schur complement`, "
                        "its Cholesky factors and W. Iteration counts, convergence and residual "
                        "histories (paper Tables 1-4) go to summary.json "
                        "(mechanics/iteration_table) and to the results report.");
      prm.declare_entry("Dirichlet",
                        "",
                        Patterns::Anything(),
                        "Prescribed displacement components per outer boundary id, "
                        "'id: x=expr, y=expr; id: ...' (muparser in x, y, z).");
      prm.declare_entry("Traction",
                        "",
                        Patterns::Anything(),
                        "Traction vector per boundary id, 'id: x=expr, y=expr; ...' (Pa).");
      prm.declare_entry("Normal pressure",
                        "",
                        Patterns::Anything(),
                        "Pressure p per boundary id (traction -p n), 'id: expr; id: expr'.");
      prm.declare_entry("Fracture pressure",
                        "",
                        Patterns::Anything(),
                        "Fluid pressure p in the fractures (Pa), acting on both sides as -p n "
                        "(the face value at its centre): 'id: expr; id: expr' per fracture id, or "
                        "one expression for every fracture; expressions of x, y (, z).");
      prm.declare_entry(
        "Point constraints",
        "",
        Patterns::Anything(),
        "Components fixed at mesh vertices, '(px, py): x=value; (px, py): y=value'. "
        "Every point must be a vertex of the mesh.");
      prm.declare_entry("Friction coefficient",
                        "0",
                        Patterns::Anything(),
                        "F >= 0 per fracture, 'id: expr; id: expr', or one expression for all; "
                        "muparser in x, y (, z) and d, the distance to the fracture's tips.");
      prm.declare_entry("Friction law",
                        "coulomb",
                        Patterns::Selection(FrictionLawRegistry::instance().selection()),
                        "How F depends on the state of a face: " +
                          FrictionLawRegistry::instance().documentation());
      FrictionLawRegistry::instance().declare_parameters(prm);
      prm.declare_entry("Body force",
                        "",
                        Patterns::Anything(),
                        "Comma-separated components (muparser in x, y, z), empty for zero.");
      prm.declare_entry("Pre-stress",
                        "",
                        Patterns::Anything(),
                        "Constant pre-stress sigma0, dim*dim comma-separated components row by "
                        "row (Pa, tension positive: the stress is C eps(u) + sigma0 - b p_E I), "
                        "empty for zero.");
      prm.declare_entry("Axisymmetric",
                        "false",
                        Patterns::Bool(),
                        "2D only: the mesh is the radial section of a body of revolution, with "
                        "x (first coordinate) along the axis and r = y >= 0; hoop strain u_r/r, "
                        "integrals weighted by 2 pi r (multipliers stay tractions in Pa).");
      prm.declare_entry("Pre-stress hoop",
                        "0",
                        Patterns::Double(),
                        "Axisymmetric only: the sigma0_theta theta component of the pre-stress "
                        "(Pa; tension positive, like Pre-stress).");
      prm.declare_entry("Report stress range",
                        "false",
                        Patterns::Bool(),
                        "Print the range of each stress component at the cell centroids (patch "
                        "tests).");
      prm.declare_entry("Analytical solution",
                        "none",
                        Patterns::Selection("none|single fracture|penny crack"),
                        "Errors against an analytical solution: single fracture (Section "
                        "5.2.1, 2D) or penny crack (3D: one planar disc of radius Fracture half "
                        "length in an infinite medium under the remote compression Remote stress "
                        "along x and the Fracture pressure at the disc centre; closed and "
                        "slipping, sticking or frictionless, or open; doc/algorithms.md).");
      prm.declare_entry("Remote stress",
                        "1e8",
                        Patterns::Double(),
                        "Analytical solutions: remote compression sigma along x (Pa).");
      prm.declare_entry("Fracture angle",
                        "20",
                        Patterns::Double(),
                        "5.2.1: angle psi of the fracture to the x axis (degrees); penny crack: "
                        "taken from the mesh.");
      prm.declare_entry("Fracture half length",
                        "1",
                        Patterns::Double(),
                        "Analytical solutions: 5.2.1: half length l; penny crack: radius a (m).");
      prm.leave_subsection();
    }



    void
    ContactParameters::parse_parameters(const ParameterHandler &prm, const unsigned int dim)
    {
      const std::vector<std::string> p = {"Mechanics"};
      young_modulus                    = prm.get_double(p, "Young modulus");
      poisson_ratio                    = prm.get_double(p, "Poisson ratio");
      method                           = prm.get(p, "Solver");
      c                                = prm.get_double(p, "Complementarity parameter c");
      stick_guess                      = prm.get(p, "Initial guess") == "stick";
      initial_lambda_n                 = prm.get_double(p, "Initial normal multiplier");
      max_iterations                   = prm.get_integer(p, "Max iterations");
      tolerance                        = prm.get_double(p, "Tolerance");
      line_search                      = prm.get_bool(p, "Line search");
      line_search_halvings             = prm.get_integer(p, "Line search halvings");
      line_search_memory               = prm.get_integer(p, "Line search memory");
      line_search_on_stagnation        = prm.get(p, "Line search trigger") == "stagnation";
      cycle_damping                    = prm.get_double(p, "Cycle damping");
      c_start                          = prm.get_double(p, "Continuation c start");
      continuation_factor              = prm.get_double(p, "Continuation factor");
      multiplier_stabilization         = prm.get_double(p, "Multiplier stabilization");
      linear_solver                    = prm.get(p, "Linear solver");
      reuse_iterations                 = prm.get_integer(p, "Reuse factorization iterations");
      distributed_linear_solver        = prm.get(p, "Distributed linear solver");
      linear_tolerance                 = prm.get_double(p, "Linear solver tolerance");
      linear_forcing                   = prm.get_double(p, "Linear solver forcing");
      max_linear_iterations            = prm.get_integer(p, "Max linear iterations");
      amg_smoothed_prolongator         = prm.get(p, "AMG prolongator") == "smoothed";
      schur_scaling                    = prm.get_double(p, "Schur complement scaling");

      dirichlet = parse_component_map(prm.get(p, "Dirichlet"), dim, "Mechanics/Dirichlet");
      traction  = parse_component_map(prm.get(p, "Traction"), dim, "Mechanics/Traction");
      pressure.clear();
      for (const auto &[id, e] :
           parse_scalar_map(prm.get(p, "Normal pressure"), "Mechanics/Normal pressure"))
        {
          check_input(id != numbers::invalid_unsigned_int,
                      "Mechanics/Normal pressure",
                      "expected 'id: expression'");
          pressure[id] = e;
        }
      fracture_pressure =
        parse_scalar_map(prm.get(p, "Fracture pressure"), "Mechanics/Fracture pressure");
      point_constraints = parse_point_constraints(prm.get(p, "Point constraints"),
                                                  dim,
                                                  "Mechanics/Point constraints");
      friction.clear();
      for (const auto &[id, e] :
           parse_scalar_map(prm.get(p, "Friction coefficient"), "Mechanics/Friction coefficient"))
        if (id == numbers::invalid_unsigned_int)
          friction_all = e;
        else
          friction[id] = e;
      friction_law_name = prm.get(p, "Friction law");
      auto law =
        FrictionLawRegistry::instance().create(friction_law_name, "Mechanics/Friction law");
      law->parse_parameters(prm);
      friction_law = std::move(law);

      body_force.clear();
      const std::string bf = prm.get(p, "Body force");
      if (!Utilities::trim(bf).empty())
        body_force = Utilities::split_string_list(bf, ',');
      pre_stress.clear();
      const std::string ps = prm.get(p, "Pre-stress");
      if (!Utilities::trim(ps).empty())
        for (const auto &s : Utilities::split_string_list(ps, ','))
          try
            {
              pre_stress.push_back(Utilities::string_to_double(s));
            }
          catch (...)
            {
              throw InputError("Mechanics/Pre-stress", "'" + s + "' is not a number");
            }
      axisymmetric    = prm.get_bool(p, "Axisymmetric");
      pre_stress_hoop = prm.get_double(p, "Pre-stress hoop");

      reports.linear_solve_time    = prm.get_bool(p, "Report linear solve time");
      reports.p2_reconstruction    = prm.get_bool(p, "Write P2 reconstruction");
      reports.iteration_table      = prm.get_bool(p, "Iteration table");
      reports.stress_range         = prm.get_bool(p, "Report stress range");
      reports.analytical_solution  = prm.get(p, "Analytical solution");
      reports.remote_stress        = prm.get_double(p, "Remote stress");
      reports.fracture_angle       = prm.get_double(p, "Fracture angle");
      reports.fracture_half_length = prm.get_double(p, "Fracture half length");
      validate(dim);
    }



    void
    ContactParameters::validate(const unsigned int dim) const
    {
      check_input(young_modulus > 0 && std::isfinite(young_modulus),
                  "Mechanics/Young modulus",
                  "must be positive");
      check_input(poisson_ratio < 0.5 && poisson_ratio > -1,
                  "Mechanics/Poisson ratio",
                  "must be below 0.5 and above -1");
      check_input(ContactMethodRegistry<2>::instance().has(method),
                  "Mechanics/Solver",
                  "'" + method + "' is not one of " +
                    ContactMethodRegistry<2>::instance().selection());
      check_input(c > 0 && std::isfinite(c),
                  "Mechanics/Complementarity parameter c",
                  "must be positive");
      check_input(tolerance > 0, "Mechanics/Tolerance", "must be positive");
      check_input(max_iterations > 0, "Mechanics/Max iterations", "must be positive");
      check_input(cycle_damping >= 0 && cycle_damping < 1,
                  "Mechanics/Cycle damping",
                  "must be in [0, 1)");
      check_input(c_start >= 0, "Mechanics/Continuation c start", "must be >= 0");
      check_input(continuation_factor > 1, "Mechanics/Continuation factor", "must be > 1");
      check_input(ContactLinearSolverRegistry<2>::instance().has(linear_solver),
                  "Mechanics/Linear solver",
                  "'" + linear_solver + "' is not one of " +
                    ContactLinearSolverRegistry<2>::instance().selection());
      check_input(multiplier_stabilization >= 0 && std::isfinite(multiplier_stabilization),
                  "Mechanics/Multiplier stabilization",
                  "must be >= 0");
      check_input(DistributedContactLinearSolverRegistry<2>::instance().has(
                    distributed_linear_solver),
                  "Mechanics/Distributed linear solver",
                  "'" + distributed_linear_solver + "' is not one of " +
                    DistributedContactLinearSolverRegistry<2>::instance().selection());
      check_input(linear_tolerance > 0 && linear_tolerance < 1,
                  "Mechanics/Linear solver tolerance",
                  "must be in (0, 1)");
      check_input(linear_forcing > 0 && linear_forcing < 1,
                  "Mechanics/Linear solver forcing",
                  "must be in (0, 1)");
      check_input(schur_scaling > 0 && std::isfinite(schur_scaling),
                  "Mechanics/Schur complement scaling",
                  "must be positive");
      check_input(FrictionLawRegistry::instance().has(friction_law_name),
                  "Mechanics/Friction law",
                  "'" + friction_law_name + "' is not one of " +
                    FrictionLawRegistry::instance().selection());
      check_input(body_force.empty() || body_force.size() == dim,
                  "Mechanics/Body force",
                  "needs " + std::to_string(dim) + " components");
      check_input(pre_stress.empty() || pre_stress.size() == dim * dim,
                  "Mechanics/Pre-stress",
                  "needs " + std::to_string(dim * dim) + " components");
      check_input(!axisymmetric || dim == 2,
                  "Mechanics/Axisymmetric",
                  "the axisymmetric mode needs Dimension = 2");
      check_input(reports.analytical_solution != "penny crack" || dim == 3,
                  "Mechanics/Analytical solution",
                  "the penny crack needs Dimension = 3");
      check_input(reports.fracture_half_length > 0,
                  "Mechanics/Fracture half length",
                  "must be positive");
      check_input(axisymmetric || pre_stress_hoop == 0,
                  "Mechanics/Pre-stress hoop",
                  "a hoop pre-stress needs Axisymmetric = true");
    }



    std::map<types::boundary_id, std::map<unsigned int, std::string>>
    parse_component_map(const std::string &text,
                        const unsigned int dim,
                        const std::string &parameter)
    {
      std::map<types::boundary_id, std::map<unsigned int, std::string>> result;
      for (const std::string &entry : dealii::Utilities::split_string_list(text, ';'))
        {
          if (trim(entry).empty())
            continue;
          const auto colon = entry.find(':');
          if (colon == std::string::npos)
            throw InputError(parameter, "expected 'id: x=value, ...' in '" + entry + "'");
          const unsigned int id = parse_id(entry.substr(0, colon), parameter);
          result[id]            = parse_components(entry.substr(colon + 1), dim, parameter);
        }
      return result;
    }

    std::map<unsigned int, std::string>
    parse_scalar_map(const std::string &text, const std::string &parameter)
    {
      std::map<unsigned int, std::string> result;
      if (text.find(':') == std::string::npos)
        {
          if (!trim(text).empty())
            result[numbers::invalid_unsigned_int] = trim(text);
          return result;
        }
      for (const std::string &entry : dealii::Utilities::split_string_list(text, ';'))
        {
          if (trim(entry).empty())
            continue;
          const auto colon = entry.find(':');
          if (colon == std::string::npos)
            throw InputError(parameter, "expected 'id: expression' in '" + entry + "'");
          result[parse_id(entry.substr(0, colon), parameter)] = trim(entry.substr(colon + 1));
        }
      return result;
    }

    std::vector<PointConstraint>
    parse_point_constraints(const std::string &text,
                            const unsigned int dim,
                            const std::string &parameter)
    {
      std::vector<PointConstraint> result;
      for (const std::string &entry : dealii::Utilities::split_string_list(text, ';'))
        {
          if (trim(entry).empty())
            continue;
          const auto open = entry.find('('), close = entry.find(')');
          const auto colon = entry.find(':', close == std::string::npos ? 0 : close);
          if (open == std::string::npos || close == std::string::npos || colon == std::string::npos)
            throw InputError(parameter, "expected '(px, py): x=value' in '" + entry + "'");
          PointConstraint pc;
          for (const std::string &c :
               dealii::Utilities::split_string_list(entry.substr(open + 1, close - open - 1), ','))
            try
              {
                pc.point.push_back(dealii::Utilities::string_to_double(c));
              }
            catch (...)
              {
                throw InputError(parameter, "bad coordinate '" + c + "'");
              }
          if (pc.point.size() != dim)
            throw InputError(parameter,
                             "the point in '" + entry + "' needs " + std::to_string(dim) +
                               " coordinates");
          pc.values = parse_components(entry.substr(colon + 1), dim, parameter);
          result.push_back(pc);
        }
      return result;
    }
  } // namespace mechanics
} // namespace porofrac
