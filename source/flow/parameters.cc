// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <porofrac/base/distributed_linear_solver.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/linear_solver.h>
#include <porofrac/base/registry.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/geometry/boundary_entries.h>
#include <porofrac/io/text.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace porofrac
{
  namespace flow
  {
    using namespace dealii;

    namespace
    {
      const char *rock_names[2] = {"Matrix", "Fracture"};

      /// The rock whose entries declare_parameters() is declaring (see rock_default()).
      Rock rock_being_declared = matrix_rock;

      /// Laws, initial pressures and mobility floors of rock subsection Flow/<rock>.
      void
      declare_rock(ParameterHandler &prm, const Rock rock)
      {
        const bool matrix   = rock == matrix_rock;
        rock_being_declared = rock;
        prm.enter_subsection(rock_names[rock]);
        const auto &saturation_laws = SaturationLawRegistry::instance();
        prm.declare_entry("Saturation law",
                          "corey",
                          Patterns::Selection(saturation_laws.selection()),
                          "S^nw(p_c) of this rock (paper eq. (1)); " +
                            saturation_laws.documentation());
        saturation_laws.declare_parameters(prm);
        const auto &permeabilities = RelativePermeabilityRegistry::instance();
        prm.declare_entry("Relative permeability",
                          matrix ? "van genuchten-mualem" : "linear",
                          Patterns::Selection(permeabilities.selection()),
                          "k_r^alpha(s^nw) of this rock; " + permeabilities.documentation());
        permeabilities.declare_parameters(prm);
        prm.declare_entry("Mobility floor",
                          "0",
                          Patterns::Double(),
                          "Added to k_r in the mobilities so that an absent phase keeps a "
                          "well-posed pressure (-); 0 = exact laws.");
        prm.declare_entry("Mobility floor nw",
                          "-1",
                          Patterns::Double(),
                          "Floor of the non-wetting phase alone (-); negative: Mobility floor. "
                          "With Capillary pressure bound the non-wetting floor should be 0.");
        const std::string p0 = matrix ? "4e6" : "1e5";
        prm.declare_entry("Initial pressure w",
                          p0,
                          Patterns::Double(),
                          "Initial wetting pressure (Pa).");
        prm.declare_entry("Initial pressure nw",
                          p0,
                          Patterns::Double(),
                          "Initial non-wetting pressure (Pa).");
        prm.leave_subsection();
        rock_being_declared = matrix_rock;
      }

      void
      declare_matrix_data(ParameterHandler &prm)
      {
        prm.enter_subsection("Matrix");
        prm.declare_entry("Porosity", "0.15", Patterns::Double(), "Initial porosity phi_0 (-).");
        prm.declare_entry("Permeability",
                          "5e-20",
                          Patterns::Double(),
                          "K_0 of the Kozeny-Carman law, K at phi_0 (m^2).");
        prm.declare_entry("Permeability expression",
                          "",
                          Patterns::Anything(),
                          "Heterogeneous matrix permeability (m^2): a muparser expression of x, "
                          "y (, z) evaluated at the centroid of every matrix cell, e.g. "
                          "'1e-12 + 9e-12*(z < 10)'; empty: Permeability everywhere. Two-phase "
                          "flow scenes only (the Kozeny-Carman law of poromechanics starts from "
                          "the uniform K_0).");
        prm.declare_entry("Source w",
                          "0",
                          Patterns::Anything(),
                          "Wetting-phase source h^w of scheme (11a): volume of phase per bulk "
                          "volume and second (1/s), muparser in x, y (, z); negative = sink.");
        prm.declare_entry("Source nw",
                          "0",
                          Patterns::Anything(),
                          "Non-wetting-phase source h^nw (1/s), as Source w.");
        prm.leave_subsection();
      }

      void
      declare_fracture_data(ParameterHandler &prm)
      {
        prm.enter_subsection("Fracture");
        prm.declare_entry("Aperture", "1e-3", Patterns::Double(), "Initial aperture d_f (m).");
        prm.declare_entry("Normal transmissibility",
                          "1e-9",
                          Patterns::Double(),
                          "Lambda_f of eq. (3) (m).");
        prm.declare_entry(
          "Damaged layer thickness",
          "0",
          Patterns::Double(),
          "d_a: thickness of the damaged layer on each side of a fracture, the pore "
          "space of the matrix-fracture interface unknowns (m; 0: massless "
          "interfaces). The layer uses the fracture's laws.");
        prm.declare_entry("Damaged layer porosity",
                          "0",
                          Patterns::Double(),
                          "phi_a: porosity of the damaged layer (-).");
        prm.leave_subsection();
      }

      void
      declare_boundary_conditions(ParameterHandler &prm)
      {
        prm.enter_subsection("Boundary conditions");
        prm.declare_entry("Matrix",
                          "",
                          Patterns::Anything(),
                          "Dirichlet conditions on matrix boundary faces: 'id: p_w = v, p_nw = v; "
                          "id: s_nw = v, p_nw = v' (two of p_w, p_nw, s_nw, s_w per id; Pa, -). "
                          "Other boundaries: no flux.");
        prm.declare_entry("Fracture",
                          "",
                          Patterns::Anything(),
                          "Dirichlet conditions on fracture nodes on the outer boundary, same "
                          "syntax (matrix boundary ids).");
        prm.declare_entry("Matrix flux",
                          "",
                          Patterns::Anything(),
                          "Prescribed fluxes into the matrix through boundary faces: 'id: q_w = "
                          "v, q_nw = v; ...', volume of phase per face area and second (m/s), "
                          "or 'id: Q_w = v, Q_nw = v', the total rate through the id (m^3/s; in 2D "
                          "plane runs m^2/s, per metre out of the plane) "
                          "spread over its faces in proportion to their area (exact totals where "
                          "the faces only approximate a region); positive into the domain, a "
                          "missing phase 0. An id may not also carry a Dirichlet condition.");
        prm.leave_subsection();
      }

      void
      declare_time_stepping(ParameterHandler &prm)
      {
        prm.declare_entry("Final time", "1", Patterns::Double(), "End of the simulation (s).");
        prm.declare_entry("Initial time step", "0.01", Patterns::Double(), "First time step (s).");
        prm.declare_entry("Maximum time step",
                          "1e100",
                          Patterns::Double(),
                          "Delta t_max in dt_{k+1/2} = min(rho dt_{k-1/2}, Delta t_max) (s).");
        prm.declare_entry("Time step growth", "1.1", Patterns::Double(), "rho (-).");
        prm.declare_entry("Maximum time steps",
                          "100000",
                          Patterns::Integer(1),
                          "A deck whose time-step rule (initial step, growth, maximum step) "
                          "needs more steps than this to reach the final time is refused before "
                          "any solve; raise it when so many steps are meant.");
        prm.declare_entry("Maximum time step cuts",
                          "20",
                          Patterns::Integer(0),
                          "Halvings of one step allowed before giving up.");
        prm.declare_entry("Output every",
                          "1",
                          Patterns::Integer(0),
                          "Write fields every n accepted steps (0: only the last).");
      }

      void
      declare_newton(ParameterHandler &prm)
      {
        prm.declare_entry("Maximum Newton iterations",
                          "50",
                          Patterns::Integer(1),
                          "Newton iterations before the step is halved.");
        prm.declare_entry("Residual tolerance",
                          "1e-5",
                          Patterns::Double(),
                          "Stop Newton when |R|/|R_0| is below this ...");
        prm.declare_entry("Update tolerance",
                          "1e-4",
                          Patterns::Double(),
                          "... or when max |dp| / max |p| is below this ...");
        prm.declare_entry("Mass balance tolerance",
                          "1e-11",
                          Patterns::Double(),
                          "... and each phase's relative mass defect is below this.");
        prm.declare_entry("Capillary chop",
                          "1",
                          Patterns::Double(0),
                          "Newton: largest change of a node's capillary pressure per iteration, in "
                          "units of the pressure scale of its rock's saturation law (Corey R, van "
                          "Genuchten P_r, Brooks-Corey entry pressure; 0: no limit).");
        prm.declare_entry(
          "Entry slope iterations",
          "1000",
          Patterns::Integer(0),
          "Newton: number of iterations per time step that use the entry slope "
          "(see Entry slope in Jacobian); later iterations use the exact Jacobian.");
        prm.declare_entry("Stagnation iterations",
                          "10",
                          Patterns::Integer(0),
                          "Newton: give up (and cut the time step) after this many iterations in "
                          "which neither the residual nor the mass defect halved and the "
                          "capillary chop limited no update (0: never).");
        prm.declare_entry("Saturation chop",
                          "0",
                          Patterns::Double(0),
                          "Newton: largest change of a node's non-wetting saturation per "
                          "iteration (Appleyard chop; 0: no limit). Interface nodes are limited "
                          "under both the matrix and the fracture law.");
        prm.declare_entry("Line search",
                          "false",
                          Patterns::Bool(),
                          "Newton: halve the update (up to 4 times) while it increases the "
                          "residual norm (breaks the two-cycles of van Genuchten-Mualem k_r^w, "
                          "whose slope is unbounded at S^nw = 0).");
        prm.declare_entry(
          "Capillary pressure bound",
          "false",
          Patterns::Bool(),
          "Newton: keep p_c >= p_e at every node, p_e the entry pressure of its "
          "saturation law (0 for corey and van genuchten): the non-wetting "
          "pressure of a saturated node is projected onto p^w + p_e, and the "
          "Jacobian uses the entry slope there. S = 0 for p_c <= p_e, so this removes a "
          "pressure that no equation fixes; use it with Mobility floor nw = 0.");
        prm.declare_entry(
          "Entry slope in Jacobian",
          "true",
          Patterns::Bool(),
          "Newton: use the entry slope instead of 0 in the Jacobian where p_c <= p_e, "
          "the entry pressure of the saturation law (false: exact Jacobian). The "
          "entry slope is the larger of S'(p_e+) and the secant S(p_e + s)/s over "
          "the law's pressure scale s (van Genuchten: S'(0+) = 0).");
        const auto &solvers = SerialLinearSolverRegistry::instance();
        prm.declare_entry("Linear solver",
                          "umfpack",
                          Patterns::Selection(solvers.selection()),
                          "Solver of the linear system of each Newton iteration; " +
                            solvers.documentation());
        const auto &distributed = DistributedLinearSolverRegistry::instance();
        prm.declare_entry("Distributed linear solver",
                          "mumps",
                          Patterns::Selection(distributed.selection()),
                          "Solver of the Newton systems when the flow runs distributed "
                          "(General/Distributed; Linear solver is the serial code's); " +
                            distributed.documentation());
        prm.declare_entry("Linear solver tolerance",
                          "1e-4",
                          Patterns::Double(),
                          "Iterative linear solvers: the relative residual of each Newton step is "
                          "min(this, Linear solver forcing x |R|/|R_0|), at least 1e-12 "
                          "(inexact Newton steps; direct solvers ignore it).");
        prm.declare_entry("Linear solver forcing",
                          "1",
                          Patterns::Double(),
                          "Iterative linear solvers: see Linear solver tolerance.");
        prm.declare_entry("Max linear iterations",
                          "200",
                          Patterns::Integer(1),
                          "Iterative linear solvers: Krylov iterations per Newton step before "
                          "the step is solved by MUMPS instead (counted in summary.json, "
                          "flow_linear_solver/direct_fallbacks).");
        prm.declare_entry("AMG aggregation threshold",
                          "1e-4",
                          Patterns::Double(0., 1.),
                          "cpr-gmres and amg-gmres: couplings of the AMG's matrix weaker than "
                          "this times the geometric mean of their two diagonal entries are "
                          "dropped before aggregating (Trilinos ML). 1e-4 is ML's default; "
                          "0.02 lets the AMG follow highly conductive fracture networks (the "
                          "Berre et al. cases: doc/benchmarks/berre2021.md).");
        prm.declare_entry("AMG aggregation",
                          "uncoupled",
                          Patterns::Selection(amg_aggregation_names),
                          "cpr-gmres and amg-gmres: how the AMG (Trilinos ML) forms its "
                          "aggregates. uncoupled: each process aggregates its own rows (ML's "
                          "default, the cheapest set-up); mis: maximal independent sets of the "
                          "whole matrix graph, across process boundaries (ML's MIS), which on "
                          "several processes lets the aggregates follow a fracture network "
                          "that crosses a process boundary (Berre et al. case 2: "
                          "doc/benchmarks/berre2021.md), at a dearer set-up.");
      }

      std::array<double, 2>
      get_pressures(const ParameterHandler &prm, const std::vector<std::string> &path)
      {
        return {{prm.get_double(path, "Initial pressure w"),
                 prm.get_double(path, "Initial pressure nw")}};
      }
    } // namespace

    std::string
    rock_default(const std::string &matrix_value, const std::string &fracture_value)
    {
      return rock_being_declared == matrix_rock ? matrix_value : fracture_value;
    }

    void
    FlowParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Flow");
      prm.declare_entry("Axisymmetric",
                        "false",
                        Patterns::Bool(),
                        "Weight volumes and face measures by 2 pi r, r = second coordinate (the "
                        "radial section of the paper's Section 5.3).");
      prm.declare_entry("Viscosity w",
                        "1e-3",
                        Patterns::Double(),
                        "Wetting viscosity mu_w (Pa s).");
      prm.declare_entry("Viscosity nw",
                        "1.851e-5",
                        Patterns::Double(),
                        "Non-wetting viscosity mu_nw (Pa s).");
      declare_time_stepping(prm);
      declare_newton(prm);
      prm.declare_entry("Reference pressure",
                        "0",
                        Patterns::Double(),
                        "Pressures are stored relative to this value (Pa); the results do not "
                        "depend on it. Set it to the pressure of the best-conducting region (the "
                        "fractures' boundary pressure): one ulp of a stored 1e5 Pa there can "
                        "exceed the mass balance tolerance (doc/benchmarks/flow.md).");
      declare_rock(prm, matrix_rock);
      declare_matrix_data(prm);
      declare_rock(prm, fracture_rock);
      declare_fracture_data(prm);
      declare_boundary_conditions(prm);
      prm.declare_entry("Cell centres",
                        "auto",
                        Patterns::Selection("auto|circumcentre|centroid"),
                        "Where the pressure of a matrix cell (and, in 3D, of a fracture "
                        "triangle) lives. circumcentre: the paper's TPFA, exact two-point fluxes "
                        "on Delaunay meshes. centroid: half transmissibilities |e| K (n . d) / "
                        "|d|^2, d from the centroid to the face centre (always positive; "
                        "consistent only on near-orthogonal meshes). auto: circumcentres in 2D "
                        "(Delaunay flips make the mesh Delaunay), centroids in 3D, whose "
                        "tetrahedral meshes are not Delaunay (doc/flow.md).");
      prm.declare_entry("Sample lines",
                        "",
                        Patterns::Anything(),
                        "Segments along which the matrix pressure of the final state is written "
                        "to line_<name>.csv (columns s, x, y[, z], p_w; s = arc length from the "
                        "start; the value of the cell containing each point): 'name: (x, y, z) "
                        "(x, y, z) [number of points, default 1000]; ...'.");
      prm.leave_subsection();
    }

    void
    FlowParameters::parse_parameters(const ParameterHandler &prm)
    {
      const std::vector<std::string> flow = {"Flow"};
      axisymmetric                        = prm.get_bool(flow, "Axisymmetric");
      for (const Rock r : {matrix_rock, fracture_rock})
        {
          const std::vector<std::string> path   = {"Flow", rock_names[r]};
          const std::string              prefix = std::string("Flow/") + rock_names[r];
          RockType                      &rock   = rocks[r];
          rock.saturation                       = SaturationLawRegistry::instance().create(
            prm.get(path, "Saturation law"), prefix + "/Saturation law", prm, path);
          rock.relative_permeability = RelativePermeabilityRegistry::instance().create(
            prm.get(path, "Relative permeability"), prefix + "/Relative permeability", prm, path);
          rock.viscosity[0]      = prm.get_double(flow, "Viscosity w");
          rock.viscosity[1]      = prm.get_double(flow, "Viscosity nw");
          rock.mobility_floor    = prm.get_double(path, "Mobility floor");
          rock.mobility_floor_nw = prm.get_double(path, "Mobility floor nw");
          initial_pressure[r]    = get_pressures(prm, path);
        }

      const std::vector<std::string> matrix = {"Flow", "Matrix"}, fracture = {"Flow", "Fracture"};
      porosity                = prm.get_double(matrix, "Porosity");
      permeability            = prm.get_double(matrix, "Permeability");
      permeability_expression = Utilities::trim(prm.get(matrix, "Permeability expression"));
      source                  = {{prm.get(matrix, "Source w"), prm.get(matrix, "Source nw")}};
      aperture                = prm.get_double(fracture, "Aperture");
      normal_transmissibility = prm.get_double(fracture, "Normal transmissibility");
      damaged_layer_thickness = prm.get_double(fracture, "Damaged layer thickness");
      damaged_layer_porosity  = prm.get_double(fracture, "Damaged layer porosity");
      reference_pressure      = prm.get_double(flow, "Reference pressure");
      sample_lines            = prm.get(flow, "Sample lines");
      cell_centres            = prm.get(flow, "Cell centres");

      stepping.final_time    = prm.get_double(flow, "Final time");
      stepping.initial_step  = prm.get_double(flow, "Initial time step");
      stepping.maximum_step  = prm.get_double(flow, "Maximum time step");
      stepping.growth        = prm.get_double(flow, "Time step growth");
      stepping.maximum_cuts  = prm.get_integer(flow, "Maximum time step cuts");
      stepping.output_every  = prm.get_integer(flow, "Output every");
      stepping.maximum_steps = prm.get_integer(flow, "Maximum time steps");

      newton.max_iterations            = prm.get_integer(flow, "Maximum Newton iterations");
      newton.residual_tolerance        = prm.get_double(flow, "Residual tolerance");
      newton.update_tolerance          = prm.get_double(flow, "Update tolerance");
      newton.mass_tolerance            = prm.get_double(flow, "Mass balance tolerance");
      newton.capillary_chop            = prm.get_double(flow, "Capillary chop");
      newton.saturation_chop           = prm.get_double(flow, "Saturation chop");
      newton.stagnation_iterations     = prm.get_integer(flow, "Stagnation iterations");
      newton.entry_slope_iterations    = prm.get_integer(flow, "Entry slope iterations");
      newton.entry_slope               = prm.get_bool(flow, "Entry slope in Jacobian");
      newton.capillary_bound           = prm.get_bool(flow, "Capillary pressure bound");
      newton.line_search               = prm.get_bool(flow, "Line search");
      newton.linear_solver             = prm.get(flow, "Linear solver");
      newton.distributed_linear_solver = prm.get(flow, "Distributed linear solver");
      newton.linear_tolerance          = prm.get_double(flow, "Linear solver tolerance");
      newton.linear_forcing            = prm.get_double(flow, "Linear solver forcing");
      newton.max_linear_iterations     = prm.get_integer(flow, "Max linear iterations");
      newton.amg.aggregation_threshold = prm.get_double(flow, "AMG aggregation threshold");
      newton.amg.aggregation           = prm.get(flow, "AMG aggregation");

      const std::vector<std::string> bc = {"Flow", "Boundary conditions"};
      matrix_dirichlet                  = parse_dirichlet(prm.get(bc, "Matrix"),
                                         rocks[matrix_rock],
                                         "Flow/Boundary conditions/Matrix");
      fracture_dirichlet                = parse_dirichlet(prm.get(bc, "Fracture"),
                                           rocks[fracture_rock],
                                           "Flow/Boundary conditions/Fracture");
      matrix_flux = parse_flux(prm.get(bc, "Matrix flux"), "Flow/Boundary conditions/Matrix flux");
      validate();
    }

    void
    FlowParameters::validate() const
    {
      for (const Rock r : {matrix_rock, fracture_rock})
        rocks[r].validate("Flow", std::string("Flow/") + rock_names[r]);

      check_input(stepping.final_time > 0, "Flow/Final time", "must be positive");
      check_input(stepping.initial_step > 0, "Flow/Initial time step", "must be positive");
      check_input(stepping.maximum_step > 0, "Flow/Maximum time step", "must be positive");
      check_input(stepping.growth >= 1, "Flow/Time step growth", "must be >= 1");
      // A configuration that cannot reach the final time in a sane number of steps is bad input.
      double t = 0, dt = std::min(stepping.initial_step, stepping.maximum_step);
      for (unsigned int k = 0; k < stepping.maximum_steps && t < stepping.final_time; ++k)
        {
          t += dt;
          dt = std::min(stepping.growth * dt, stepping.maximum_step);
        }
      check_input(t >= stepping.final_time,
                  "Flow/Maximum time step",
                  "the final time " + io::to_text(stepping.final_time) + " s is not reached in " +
                    std::to_string(stepping.maximum_steps) +
                    " steps (Flow/Maximum time steps) with this initial step, growth and "
                    "maximum step; raise Flow/Maximum time steps if so many steps are meant");

      check_input(newton.saturation_chop < 1, "Flow/Saturation chop", "must be below 1");
      check_input(SerialLinearSolverRegistry::instance().has(newton.linear_solver),
                  "Flow/Linear solver",
                  "'" + newton.linear_solver + "' is not one of " +
                    SerialLinearSolverRegistry::instance().selection());

      check_input(DistributedLinearSolverRegistry::instance().has(newton.distributed_linear_solver),
                  "Flow/Distributed linear solver",
                  "'" + newton.distributed_linear_solver + "' is not one of " +
                    DistributedLinearSolverRegistry::instance().selection());
      check_input(newton.linear_tolerance > 0 && newton.linear_tolerance < 1,
                  "Flow/Linear solver tolerance",
                  "must lie in (0, 1)");
      check_input(newton.linear_forcing > 0, "Flow/Linear solver forcing", "must be positive");

      check_input(porosity > 0 && porosity < 1, "Flow/Matrix/Porosity", "must lie in (0, 1)");
      check_input(permeability > 0, "Flow/Matrix/Permeability", "must be positive");
      check_input(aperture > 0, "Flow/Fracture/Aperture", "must be positive");
      check_input(damaged_layer_thickness >= 0,
                  "Flow/Fracture/Damaged layer thickness",
                  "must be non-negative");
      check_input(damaged_layer_porosity >= 0 && damaged_layer_porosity < 1,
                  "Flow/Fracture/Damaged layer porosity",
                  "must lie in [0, 1)");
      check_input(damaged_layer_thickness == 0 || damaged_layer_porosity > 0,
                  "Flow/Fracture/Damaged layer porosity",
                  "must be positive when the damaged layer thickness is");
      check_input(normal_transmissibility > 0,
                  "Flow/Fracture/Normal transmissibility",
                  "must be positive");
      for (const auto &q : matrix_flux)
        check_input(matrix_dirichlet.count(q.first) == 0,
                    "Flow/Boundary conditions/Matrix flux",
                    "boundary id " + std::to_string(q.first) +
                      " also has a Dirichlet condition (Flow/Boundary conditions/Matrix)");
    }

    namespace
    {
      /// "id: name = value, name = value; ..." with names from @p allowed, as id -> name -> value.
      std::map<types::boundary_id, std::map<std::string, double>>
      parse_boundary_entries(const std::string           &text,
                             const std::set<std::string> &allowed,
                             const std::string           &parameter)
      {
        std::map<types::boundary_id, std::map<std::string, double>> result;
        std::string                                                 names;
        for (const auto &a : allowed)
          names += (names.empty() ? "" : ", ") + a;
        for (const auto &[id, rest] :
             geometry::split_boundary_entries(text, parameter, "id: name = value, name = value"))
          {
            auto &values = result[id];
            for (const std::string &item : Utilities::split_string_list(rest, ','))
              {
                const auto eq = item.find('=');
                check_input(eq != std::string::npos,
                            parameter,
                            "expected 'name = value' in '" + rest + "'");
                const std::string key = Utilities::trim(item.substr(0, eq));
                check_input(allowed.count(key) > 0,
                            parameter,
                            "unknown quantity '" + key + "' (" + names + ")");
                try
                  {
                    values[key] = Utilities::string_to_double(Utilities::trim(item.substr(eq + 1)));
                  }
                catch (...)
                  {
                    throw InputError(parameter, "bad number in '" + item + "'");
                  }
                check_input(std::isfinite(values[key]),
                            parameter,
                            "the value in '" + item + "' is not finite");
              }
          }
        return result;
      }
    } // namespace

    DirichletData
    parse_dirichlet(const std::string &text, const RockType &rock, const std::string &parameter)
    {
      DirichletData result;
      for (auto &[id, values] :
           parse_boundary_entries(text, {"p_w", "p_nw", "s_nw", "s_w"}, parameter))
        {
          check_input(values.size() == 2,
                      parameter,
                      "give exactly two of p_w, p_nw, s_nw, s_w for boundary id " +
                        std::to_string(id));
          if (values.count("s_w"))
            {
              check_input(values["s_w"] >= 0 && values["s_w"] <= 1,
                          parameter,
                          "saturation s_w outside [0, 1] for boundary id " + std::to_string(id));
              values["s_nw"] = 1. - values["s_w"];
            }
          if (values.count("s_nw"))
            check_input(values["s_nw"] >= 0 && values["s_nw"] <= 1,
                        parameter,
                        "saturation s_nw outside [0, 1] for boundary id " + std::to_string(id));
          std::array<double, 2> p;
          if (values.count("p_w") && values.count("p_nw"))
            p = {{values["p_w"], values["p_nw"]}};
          else
            {
              check_input(values.count("s_nw"),
                          parameter,
                          "give a saturation and one pressure, or both pressures, for id " +
                            std::to_string(id));
              const double pc = rock.saturation->inverse(values["s_nw"], parameter);
              if (values.count("p_w"))
                p = {{values["p_w"], values["p_w"] + pc}};
              else
                p = {{values["p_nw"] - pc, values["p_nw"]}};
            }
          result[id] = p;
        }
      return result;
    }

    FluxData
    parse_flux(const std::string &text, const std::string &parameter)
    {
      FluxData result;
      for (auto &[id, values] :
           parse_boundary_entries(text, {"q_w", "q_nw", "Q_w", "Q_nw"}, parameter))
        {
          BoundaryFlux &flux = result[id];
          flux.total         = values.count("Q_w") || values.count("Q_nw");
          check_input(!flux.total || !(values.count("q_w") || values.count("q_nw")),
                      parameter,
                      "boundary id " + std::to_string(id) +
                        " mixes fluxes per area (q) and total rates (Q)");
          const std::string w = flux.total ? "Q_w" : "q_w", nw = flux.total ? "Q_nw" : "q_nw";
          flux.rate = {{values.count(w) ? values[w] : 0., values.count(nw) ? values[nw] : 0.}};
        }
      return result;
    }

    namespace
    {
      /// The law @p name of @p registry, parsed from a ParameterHandler with the Flow subsection
      /// declared and @p values set in Flow/<rock>; errors name @p selection.
      template <typename RegistryType>
      auto
      make_law(const RegistryType                       &registry,
               const std::string                        &selection,
               const std::string                        &name,
               const std::map<std::string, std::string> &values,
               const Rock                                rock)
      {
        ParameterHandler prm;
        FlowParameters::declare_parameters(prm);
        prm.enter_subsection("Flow");
        prm.enter_subsection(rock_names[rock]);
        for (const auto &[entry, value] : values)
          prm.set(entry, value);
        prm.leave_subsection();
        prm.leave_subsection();
        return registry.create(name,
                               std::string("Flow/") + rock_names[rock] + "/" + selection,
                               prm,
                               {"Flow", rock_names[rock]});
      }
    } // namespace

    std::shared_ptr<const SaturationLaw>
    make_saturation_law(const std::string                        &name,
                        const std::map<std::string, std::string> &values,
                        const Rock                                rock)
    {
      return make_law(SaturationLawRegistry::instance(), "Saturation law", name, values, rock);
    }

    std::shared_ptr<const RelativePermeability>
    make_relative_permeability(const std::string                        &name,
                               const std::map<std::string, std::string> &values,
                               const Rock                                rock)
    {
      return make_law(
        RelativePermeabilityRegistry::instance(), "Relative permeability", name, values, rock);
    }
  } // namespace flow
} // namespace porofrac
