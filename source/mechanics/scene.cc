// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/geometry/mesh_output.h>
#include <porofrac/mechanics/contact_problem.h>
#include <porofrac/mechanics/fracture_reconstruction.h>
#include <porofrac/mechanics/fracture_table.h>
#include <porofrac/mechanics/scene.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mechanics");
      prm.declare_entry("Young modulus", "25e9", Patterns::Double(), "E (Pa).");
      prm.declare_entry("Poisson ratio",
                        "0.25",
                        Patterns::Double(),
                        "nu, in (-1, 0.5). 2D is plane strain.");
      prm.declare_entry("Solver",
                        "active set",
                        Patterns::Selection("active set|semismooth newton"),
                        "Contact solver: the active-set method of Section 5.1, or the "
                        "regularized semi-smooth Newton method (specs.md 3a).");
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
      prm.declare_entry("Max iterations", "50", Patterns::Integer(1), "Contact iterations.");
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
                        Patterns::Selection("full system|schur complement"),
                        "Linear solves of the contact iterations. full system: UMFPACK LU of the "
                        "whole (u, lambda) Jacobian at every iteration whose face rows changed. "
                        "schur complement: one Cholesky factorization of the elasticity block K "
                        "(it never changes), W = J K^{-1} B^T formed once (dim x fracture faces "
                        "square, dense), then per iteration a dense LU of A_l - A_j W and two "
                        "sparse triangular solve pairs (needs K positive definite, i.e. enough "
                        "Dirichlet conditions without the contact rows).");
      prm.declare_entry("Report linear solve time",
                        "false",
                        Patterns::Bool(),
                        "Also time one linear elasticity solve (every fracture open, UMFPACK "
                        "factorization + solve) on the same mesh; written to summary.json "
                        "(mechanics/linear_solve_time_s).");
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
                        Patterns::Selection("none|single fracture"),
                        "Errors against the analytical solution of Section 5.2.1.");
      prm.declare_entry("Remote stress",
                        "1e8",
                        Patterns::Double(),
                        "5.2.1: remote compression sigma (Pa).");
      prm.declare_entry("Fracture angle",
                        "20",
                        Patterns::Double(),
                        "5.2.1: angle psi of the fracture to the x axis (degrees).");
      prm.declare_entry("Fracture half length", "1", Patterns::Double(), "5.2.1: l (m).");
      prm.leave_subsection();
    }

    ContactParameters
    parse_parameters(const ParameterHandler &prm, const unsigned int dim)
    {
      const std::vector<std::string> p          = {"Mechanics"};
      auto                           get_double = [&](const std::string &n) {
        return Utilities::string_to_double(prm.get(p, n));
      };
      ContactParameters r;
      r.young_modulus = get_double("Young modulus");
      r.poisson_ratio = get_double("Poisson ratio");
      check_input(r.young_modulus > 0, "Mechanics/Young modulus", "must be positive");
      check_input(r.poisson_ratio < 0.5 && r.poisson_ratio > -1,
                  "Mechanics/Poisson ratio",
                  "must be below 0.5 and above -1");
      r.method = prm.get(p, "Solver") == "active set" ? ContactMethod::active_set :
                                                        ContactMethod::semismooth_newton;
      r.c      = get_double("Complementarity parameter c");
      check_input(r.c > 0, "Mechanics/Complementarity parameter c", "must be positive");
      r.stick_guess      = prm.get(p, "Initial guess") == "stick";
      r.initial_lambda_n = get_double("Initial normal multiplier");
      r.max_iterations   = Utilities::string_to_int(prm.get(p, "Max iterations"));
      r.tolerance        = get_double("Tolerance");
      check_input(r.tolerance > 0, "Mechanics/Tolerance", "must be positive");
      r.line_search               = prm.get(p, "Line search") == "true";
      r.line_search_halvings      = Utilities::string_to_int(prm.get(p, "Line search halvings"));
      r.line_search_memory        = Utilities::string_to_int(prm.get(p, "Line search memory"));
      r.line_search_on_stagnation = prm.get(p, "Line search trigger") == "stagnation";
      r.cycle_damping             = get_double("Cycle damping");
      check_input(r.cycle_damping >= 0 && r.cycle_damping < 1,
                  "Mechanics/Cycle damping",
                  "must be in [0, 1)");
      r.c_start = get_double("Continuation c start");
      check_input(r.c_start >= 0, "Mechanics/Continuation c start", "must be >= 0");
      r.continuation_factor = get_double("Continuation factor");
      check_input(r.continuation_factor > 1, "Mechanics/Continuation factor", "must be > 1");
      r.time_linear_solve = prm.get(p, "Report linear solve time") == "true";
      r.schur_complement  = prm.get(p, "Linear solver") == "schur complement";
      r.reuse_iterations  = Utilities::string_to_int(prm.get(p, "Reuse factorization iterations"));
      r.dirichlet = parse_component_map(prm.get(p, "Dirichlet"), dim, "Mechanics/Dirichlet");
      r.traction  = parse_component_map(prm.get(p, "Traction"), dim, "Mechanics/Traction");
      for (const auto &[id, e] :
           parse_scalar_map(prm.get(p, "Normal pressure"), "Mechanics/Normal pressure"))
        {
          check_input(id != numbers::invalid_unsigned_int,
                      "Mechanics/Normal pressure",
                      "expected 'id: expression'");
          r.pressure[id] = e;
        }
      r.point_constraints = parse_point_constraints(prm.get(p, "Point constraints"),
                                                    dim,
                                                    "Mechanics/Point constraints");
      for (const auto &[id, e] :
           parse_scalar_map(prm.get(p, "Friction coefficient"), "Mechanics/Friction coefficient"))
        if (id == numbers::invalid_unsigned_int)
          r.friction_all = e;
        else
          r.friction[id] = e;
      const std::string bf = prm.get(p, "Body force");
      if (!Utilities::trim(bf).empty())
        {
          r.body_force = Utilities::split_string_list(bf, ',');
          check_input(r.body_force.size() == dim,
                      "Mechanics/Body force",
                      "needs " + std::to_string(dim) + " components");
        }
      const std::string ps = prm.get(p, "Pre-stress");
      if (!Utilities::trim(ps).empty())
        {
          for (const auto &s : Utilities::split_string_list(ps, ','))
            r.pre_stress.push_back(Utilities::string_to_double(s));
          check_input(r.pre_stress.size() == dim * dim,
                      "Mechanics/Pre-stress",
                      "needs " + std::to_string(dim * dim) + " components");
        }
      r.axisymmetric    = prm.get(p, "Axisymmetric") == "true";
      r.pre_stress_hoop = get_double("Pre-stress hoop");
      check_input(!r.axisymmetric || dim == 2,
                  "Mechanics/Axisymmetric",
                  "the axisymmetric mode needs Dimension = 2");
      check_input(r.axisymmetric || r.pre_stress_hoop == 0,
                  "Mechanics/Pre-stress hoop",
                  "a hoop pre-stress needs Axisymmetric = true");
      return r;
    }


    namespace
    {
      /**
       * The paper's iteration tables (Tables 1-4) on the mesh of @p problem: every contact
       * method x c x initial guess, each a cold solve (ContactProblem::set_contact_solver()),
       * sharing the mesh-only data of the problem. Leaves the last cell's solution in @p problem.
       */
      template <int dim>
      io::Json
      run_iteration_table(ContactProblem<dim> &problem, io::RunContext &context)
      {
        io::Json table = io::Json::array();
        for (const ContactMethod method :
             {ContactMethod::active_set, ContactMethod::semismooth_newton})
          for (const bool stick : {true, false})
            for (const double c : {1e6, 1e9, 1e11})
              {
                const std::string name =
                  method == ContactMethod::active_set ? "active set" : "semismooth newton";
                problem.set_contact_solver(method, c, stick);
                Timer       clock;
                std::string failure;
                try
                  {
                    problem.solve();
                  }
                catch (const SolverFailure &e)
                  {
                    failure = e.what();
                  }
                io::Json r                = io::Json::object();
                r["solver"]               = name;
                r["initial_guess"]        = std::string(stick ? "stick" : "open");
                r["c"]                    = c;
                r["converged"]            = problem.converged;
                r["nonlinear_iterations"] = problem.iterations;
                r["last_residual"] =
                  problem.residual_history.empty() ? 0. : problem.residual_history.back();
                r["residuals"]              = problem.residual_history;
                r["steps"]                  = problem.step_history;
                r["line_search_backtracks"] = problem.backtracks;
                r["cycles_detected"]        = problem.cycles_detected;
                r["factorizations"]         = problem.factorizations;
                r["wall_time_s"]            = clock.wall_time();
                if (!failure.empty())
                  r["failure"] = failure;
                table.push_back(r);
                std::ostringstream line;
                line << "Mechanics: iteration table: " << name << ", " << (stick ? "stick" : "open")
                     << " guess, c = " << std::scientific << std::setprecision(0) << c << ": ";
                if (problem.converged)
                  line << "converged in " << problem.iterations << " iterations";
                else
                  line << "not converged in " << problem.iterations << " iterations";
                context.report << line.str() << std::endl;
                context.progress << "    " << line.str() << " (" << std::defaultfloat
                                 << std::setprecision(3) << clock.wall_time() << " s)" << std::endl;
              }
        return table;
      }
    } // namespace

    template <int dim>
    void
    run_scene(const ParameterHandler       &prm,
              const geometry::CutMesh<dim> &mesh,
              io::RunContext               &context)
    {
      const ContactParameters cp = parse_parameters(prm, dim);
      context.progress << "*** Contact mechanics" << std::endl;
      ContactProblem<dim> problem(mesh, cp, context.progress, context.timer);
      problem.setup();
      context.report << "Mechanics: " << problem.n_dofs() << " dofs ("
                     << problem.n_displacement_dofs() << " displacement, "
                     << problem.n_dofs() - problem.n_displacement_dofs() << " multiplier)"
                     << std::endl;
      context.summary["n_dofs_mechanics"] = problem.n_dofs();
      double linear_time = 0, linear_time_cholesky = 0;
      if (cp.time_linear_solve)
        {
          linear_time = problem.time_linear_solve();
          context.progress << "    one linear elasticity solve (UMFPACK): " << linear_time << " s"
                           << std::endl;
          try
            {
              linear_time_cholesky = problem.time_linear_solve_cholesky();
              context.progress << "    one linear elasticity solve (Cholesky): "
                               << linear_time_cholesky << " s" << std::endl;
            }
          catch (const SolverFailure &)
            {
            }
        }
      double contact_time = 0;
      {
        Timer clock;
        problem.solve();
        contact_time                            = clock.wall_time();
        context.summary["contact_solve_time_s"] = contact_time;
      }

      unsigned int counts[3] = {0, 0, 0};
      for (unsigned int f = 0; f < mesh.fracture_faces.size(); ++f)
        ++counts[static_cast<unsigned int>(problem.state(f))];
      const std::string solver = prm.get({"Mechanics"}, "Solver");
      context.report << "Mechanics: solver " << solver << ", "
                     << prm.get({"Mechanics"}, "Initial guess") << " guess, c = " << std::scientific
                     << std::setprecision(1) << cp.c << std::defaultfloat << ": converged in "
                     << problem.iterations << " iterations" << std::endl;
      if (problem.schur_complement_unavailable())
        context.report << "Mechanics: Schur complement unavailable (the elasticity block alone is "
                          "singular); the full system was solved"
                       << std::endl;
      context.report << "Mechanics: faces open " << counts[0] << ", stick " << counts[1]
                     << ", slip " << counts[2] << std::endl;

      if (mesh.fracture_ids.size() > 1)
        for (const unsigned int fid : mesh.fracture_ids)
          {
            unsigned int c[3] = {0, 0, 0};
            for (const unsigned int f : mesh.faces_of_fracture.at(fid))
              ++c[static_cast<unsigned int>(problem.state(f))];
            context.report << "Mechanics: fracture " << fid << ": open " << c[0] << ", stick "
                           << c[1] << ", slip " << c[2] << std::endl;
          }
      // Ranges of the face values (local frame), for tests and logs.
      double jn_min = 1e300, jn_max = -1e300, jt_max = 0, ln_min = 1e300, ln_max = -1e300,
             lt_max = 0;
      for (const auto &face : mesh.fracture_faces)
        {
          const Tensor<2, dim> R = problem.frame(face.index);
          const Tensor<1, dim> j = R * problem.jump(face.index);
          const Tensor<1, dim> l = R * problem.multiplier(face.index);
          jn_min                 = std::min(jn_min, j[0]);
          jn_max                 = std::max(jn_max, j[0]);
          ln_min                 = std::min(ln_min, l[0]);
          ln_max                 = std::max(ln_max, l[0]);
          jt_max                 = std::max(jt_max, LocalContactLaw<dim>::tangential(j).norm());
          lt_max                 = std::max(lt_max, LocalContactLaw<dim>::tangential(l).norm());
        }
      if (!mesh.fracture_faces.empty())
        context.report << std::scientific << std::setprecision(3) << "Mechanics: jump_n in ["
                       << jn_min << ", " << jn_max << "], max |jump_t| " << jt_max << "\n"
                       << "Mechanics: lambda_n in [" << ln_min << ", " << ln_max
                       << "], max |lambda_t| " << lt_max << std::defaultfloat << std::endl;

      if (prm.get({"Mechanics"}, "Report stress range") == "true")
        {
          Point<dim> centroid;
          for (unsigned int d = 0; d < dim; ++d)
            centroid[d] = 1. / (dim + 1);
          SymmetricTensor<2, dim> smin, smax;
          bool                    first = true;
          for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
            {
              const SymmetricTensor<2, dim> st = problem.stress(cell, centroid);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int k = i; k < dim; ++k)
                  {
                    smin[i][k] = first ? st[i][k] : std::min(smin[i][k], st[i][k]);
                    smax[i][k] = first ? st[i][k] : std::max(smax[i][k], st[i][k]);
                  }
              first = false;
            }
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int k = i; k < dim; ++k)
              context.report << "Mechanics: stress_"
                             << "xyz"[i] << "xyz"[k] << " in [" << std::scientific
                             << std::setprecision(4) << smin[i][k] << ", " << smax[i][k] << "]"
                             << std::defaultfloat << std::endl;
        }

      io::Json m                      = io::Json::object();
      m["solver"]                     = solver;
      m["initial_guess"]              = prm.get({"Mechanics"}, "Initial guess");
      m["c"]                          = cp.c;
      m["nonlinear_iterations"]       = problem.iterations;
      m["converged"]                  = problem.converged;
      m["n_open"]                     = counts[0];
      m["n_stick"]                    = counts[1];
      m["n_slip"]                     = counts[2];
      m["residuals"]                  = problem.residual_history;
      m["residuals_initial_relative"] = problem.initial_relative_history;
      m["steps"]                      = problem.step_history;
      m["line_search_backtracks"]     = problem.backtracks;
      m["cycles_detected"]            = problem.cycles_detected;
      m["factorizations"]             = problem.factorizations;
      m["reused_factorizations"]      = problem.reused_factorizations;
      io::Json timing                 = io::Json::object();
      timing["contact_rows_s"]        = problem.time_contact_rows;
      timing["factorization_s"]       = problem.time_factorization;
      timing["triangular_solves_s"]   = problem.time_solves;
      timing["residuals_s"]           = problem.time_residuals;
      timing["cholesky_s"]            = problem.time_cholesky;
      timing["form_W_s"]              = problem.time_form_W;
      m["timing"]                     = timing;
      m["linear_solver"]              = problem.schur_complement_unavailable() ?
                                          std::string("full system (schur complement unavailable)") :
                                          prm.get({"Mechanics"}, "Linear solver");
      if (cp.time_linear_solve)
        {
          // One linear elasticity solve on the same mesh, in the same run (issue 3, item 8):
          // with UMFPACK on the full system (the `full system` path), and with the Cholesky
          // factorization of K (the `schur complement` path).
          m["linear_solve_time_s"]  = linear_time;
          m["contact_linear_ratio"] = contact_time / linear_time;
          if (linear_time_cholesky > 0)
            {
              m["linear_solve_time_cholesky_s"]  = linear_time_cholesky;
              m["contact_linear_ratio_cholesky"] = contact_time / linear_time_cholesky;
            }
        }
      context.summary["mechanics"] = m;

      // fractures.csv
      {
        TimerOutput::Scope t(context.timer, "Output: mechanics");
        std::ofstream      csv(context.path("fractures.csv"));
        write_fracture_table_header(csv, dim, false);
        write_fracture_table_rows(csv, problem);
        if (context.output_format != "none" && !mesh.fracture_faces.empty())
          {
            // Fracture fields per fracture face (local frame n+, tau): face-mean jump of eq. (10),
            // multiplier, state (0 open, 1 stick, 2 slip) and friction coefficient.
            geometry::FractureFields fields = {{"jump_n", {}},
                                               {"jump_t", {}},
                                               {"lambda_n", {}},
                                               {"lambda_t", {}},
                                               {"state", {}},
                                               {"friction", {}}};
            for (const auto &face : mesh.fracture_faces)
              {
                const Tensor<2, dim> R = problem.frame(face.index);
                const Tensor<1, dim> j = R * problem.jump(face.index);
                const Tensor<1, dim> l = R * problem.multiplier(face.index);
                // 2D: signed tangential component; 3D: its magnitude.
                const auto tangential = [](const Tensor<1, dim> &v) {
                  return dim == 2 ? v[1] : LocalContactLaw<dim>::tangential(v).norm();
                };
                fields[0].second.push_back(j[0]);
                fields[1].second.push_back(tangential(j));
                fields[2].second.push_back(l[0]);
                fields[3].second.push_back(tangential(l));
                fields[4].second.push_back(static_cast<double>(problem.state(face.index)));
                fields[5].second.push_back(problem.friction(face.index));
              }
            geometry::write_fracture_cells(mesh,
                                           context.path("fractures." + context.output_format),
                                           context.output_format,
                                           fields);
          }
        if (context.output_format != "none")
          {
            DataOut<dim> data_out;
            data_out.attach_dof_handler(problem.get_dof_handler());
            std::vector<DataComponentInterpretation::DataComponentInterpretation> interp(
              dim, DataComponentInterpretation::component_is_part_of_vector);
            data_out.add_data_vector(problem.displacement(),
                                     std::vector<std::string>(dim, "displacement"),
                                     DataOut<dim>::type_dof_data,
                                     interp);
            data_out.build_patches(mesh.mapping(), 2);
            geometry::write_data_out(data_out,
                                     context.path("displacement." + context.output_format),
                                     context.output_format);
          }
      }

      if (dim == 2 && prm.get({"Mechanics"}, "Write P2 reconstruction") == "true")
        {
          std::ofstream csv(context.path("fracture_p2.csv"));
          csv << "fracture_id,face_id,s_begin,s_end,s,JxW,jump_n,jump_t,lambda_n,lambda_t\n"
              << std::setprecision(12);
          for (const auto &v : reconstruct_fracture_fields(problem, 3))
            {
              const auto          &face = mesh.fracture_faces[v.face];
              const Tensor<2, dim> R    = problem.frame(v.face);
              const Tensor<1, dim> j = R * v.jump, l = R * v.lambda;
              csv << face.fracture_id << ',' << v.face << ',' << face.abscissa_begin << ','
                  << face.abscissa_end << ',' << v.abscissa << ',' << v.JxW << ',' << j[0] << ','
                  << j[dim - 1] << ',' << l[0] << ',' << l[dim - 1] << '\n';
            }
        }

      // Section 5.2.1: analytical solution, central 90 % of the fracture.
      if (prm.get({"Mechanics"}, "Analytical solution") == "single fracture")
        {
          const std::vector<std::string> p = {"Mechanics"};
          const double sigma = Utilities::string_to_double(prm.get(p, "Remote stress"));
          const double psi =
            Utilities::string_to_double(prm.get(p, "Fracture angle")) * numbers::PI / 180.;
          const double ell = Utilities::string_to_double(prm.get(p, "Fracture half length"));
          const double E = cp.young_modulus, nu = cp.poisson_ratio;
          const double lambda_n = sigma * std::sin(psi) * std::sin(psi);
          // Analytical slip at abscissa tau with friction F; specs.md Corrections 1: plane-strain
          // prefactor 4(1 - nu^2)/E.
          const auto analytical_slip = [&](const double F, const double tau) {
            return 4 * (1 - nu * nu) / E * sigma * std::sin(psi) *
                   (std::cos(psi) - F * std::sin(psi)) *
                   std::sqrt(std::max(0., ell * ell - (ell - tau) * (ell - tau)));
          };
          double e_t = 0, n_t = 0, e_n = 0, n_n = 0, max_jn = 0;
          for (const auto &face : mesh.fracture_faces)
            {
              const double tau = face.abscissa; // from the first point of the fracture
              if (tau < 0.1 * ell || tau > 1.9 * ell)
                continue;
              const double         slip = analytical_slip(problem.friction(face.index), tau);
              const Tensor<2, dim> R    = problem.frame(face.index);
              const Tensor<1, dim> j    = R * problem.jump(face.index);
              const Tensor<1, dim> l    = R * problem.multiplier(face.index);
              e_t += face.measure * std::pow(std::abs(j[1]) - slip, 2);
              n_t += face.measure * slip * slip;
              e_n += face.measure * std::pow(l[0] - lambda_n, 2);
              n_n += face.measure * lambda_n * lambda_n;
              max_jn = std::max(max_jn, std::abs(j[0]));
            }
          const double jt_err = std::sqrt(e_t / n_t), ln_err = std::sqrt(e_n / n_n);
          context.report << "Mechanics: 5.2.1 errors (central 90 %, face means): jump_t rel L2 "
                         << std::scientific << std::setprecision(3) << jt_err
                         << ", lambda_n rel L2 " << ln_err << std::defaultfloat << std::endl;

          // The same norms with the paper's P2 reconstructions (Section 5: natural P2 jump,
          // node-based P2 multiplier from the weak-form tractions; fracture_reconstruction.h),
          // 4-point Gauss rule per face, the points whose abscissa lies in the central 90 %.
          double p_et = 0, p_nt = 0, p_en = 0, p_nn = 0, p_jn = 0;
          for (const auto &v : reconstruct_fracture_fields(problem, 4))
            {
              const double tau = v.abscissa;
              if (tau < 0.1 * ell || tau > 1.9 * ell)
                continue;
              const double         slip = analytical_slip(problem.friction(v.face), tau);
              const Tensor<2, dim> R    = problem.frame(v.face);
              const Tensor<1, dim> j = R * v.jump, l = R * v.lambda;
              p_et += v.JxW * std::pow(LocalContactLaw<dim>::tangential(j).norm() - slip, 2);
              p_nt += v.JxW * slip * slip;
              p_en += v.JxW * std::pow(l[0] - lambda_n, 2);
              p_nn += v.JxW * lambda_n * lambda_n;
              p_jn += v.JxW * j[0] * j[0];
            }
          const double p_jt = std::sqrt(p_et / p_nt), p_ln = std::sqrt(p_en / p_nn);
          context.report << "Mechanics: 5.2.1 errors (central 90 %, P2 reconstructions): jump_t "
                         << "rel L2 " << std::scientific << std::setprecision(3) << p_jt
                         << ", lambda_n rel L2 " << p_ln << std::defaultfloat << std::endl;
          io::Json e                     = io::Json::object();
          e["jump_t_rel_l2"]             = p_jt;
          e["lambda_n_rel_l2"]           = p_ln;
          e["jump_n_abs_l2"]             = std::sqrt(p_jn);
          e["jump_t_rel_l2_face_mean"]   = jt_err;
          e["lambda_n_rel_l2_face_mean"] = ln_err;
          e["max_abs_jump_n"]            = max_jn;
          context.summary["errors"]      = e;
        }

      // Paper Tables 1-4: every method x c x initial guess on this mesh, in this process.
      if (prm.get({"Mechanics"}, "Iteration table") == "true")
        {
          context.progress << "*** Iteration table (12 cold solves)" << std::endl;
          context.summary["mechanics"]["iteration_table"] = run_iteration_table(problem, context);
        }
    }

    template void
    run_scene<2>(const ParameterHandler &, const geometry::CutMesh<2> &, io::RunContext &);
    template void
    run_scene<3>(const ParameterHandler &, const geometry::CutMesh<3> &, io::RunContext &);
  } // namespace mechanics
} // namespace porofrac
