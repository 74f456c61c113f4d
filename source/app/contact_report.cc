// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/app/contact_report.h>
#include <porofrac/io/output_file.h>

#include <fstream>
#include <iomanip>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    template <int dim>
    void
    report_contact_solution(const ContactSolution<dim> &solution, io::RunContext &context)
    {
      const auto &prm  = solution.parameters;
      const auto &mesh = solution.mesh;
      context.report << "Mechanics: solver " << prm.method << ", "
                     << (prm.stick_guess ? "stick" : "open") << " guess, c = " << std::scientific
                     << std::setprecision(1) << prm.c << std::defaultfloat << ": converged in "
                     << solution.statistics.iterations << " iterations" << std::endl;
      if (solution.linear_solver != solution.requested_solver)
        context.report << "Mechanics: Schur complement unavailable (the elasticity block alone "
                          "is singular); the full system was solved"
                       << std::endl;
      if (solution.statistics.direct_fallbacks > 0)
        context.report << "Mechanics: " << solution.statistics.direct_fallbacks
                       << " linear solves fell back from the Krylov solver to the direct solver ("
                       << solution.statistics.fallback_factorizations << " factorizations)"
                       << std::endl;
      if (solution.statistics.direct_workspace_retries > 0)
        context.report << "Mechanics: " << solution.statistics.direct_workspace_retries
                       << " MUMPS factorizations repeated with a larger workspace" << std::endl;
      const auto counts = mechanics::count_states(mesh, solution.faces);
      context.report << "Mechanics: faces open " << counts[0] << ", stick " << counts[1]
                     << ", slip " << counts[2] << std::endl;
      if (mesh.fracture_ids.size() > 1)
        for (const unsigned int id : mesh.fracture_ids)
          {
            const auto c = mechanics::count_states(mesh, solution.faces, id);
            context.report << "Mechanics: fracture " << id << ": open " << c[0] << ", stick "
                           << c[1] << ", slip " << c[2] << std::endl;
          }
      if (mesh.fracture_faces.empty())
        return;
      double jn_min = 1e300, jn_max = -1e300, jt_max = 0, ln_min = 1e300, ln_max = -1e300,
             lt_max = 0;
      for (const auto &v : solution.faces)
        {
          jn_min = std::min(jn_min, v.jump[0]);
          jn_max = std::max(jn_max, v.jump[0]);
          ln_min = std::min(ln_min, v.lambda[0]);
          ln_max = std::max(ln_max, v.lambda[0]);
          jt_max = std::max(jt_max, mechanics::LocalContactLaw<dim>::tangential(v.jump).norm());
          lt_max = std::max(lt_max, mechanics::LocalContactLaw<dim>::tangential(v.lambda).norm());
        }
      context.report << std::scientific << std::setprecision(3) << "Mechanics: jump_n in ["
                     << jn_min << ", " << jn_max << "], max |jump_t| " << jt_max << "\n"
                     << "Mechanics: lambda_n in [" << ln_min << ", " << ln_max
                     << "], max |lambda_t| " << lt_max << std::defaultfloat << std::endl;
    }



    void
    add_iteration_history(const mechanics::ContactStatistics &statistics, io::Json &summary)
    {
      const std::vector<std::string> terms  = {"contact", "mechanical", "stick_slip"};
      const std::vector<std::string> states = {"open", "stick", "slip", "changed"};
      io::Json                       r      = io::Json::object();
      for (unsigned int k = 0; k < terms.size(); ++k)
        {
          std::vector<double> values;
          for (const auto &t : statistics.residual_terms_history)
            values.push_back(t[k]);
          r[terms[k]] = values;
        }
      io::Json f = io::Json::object();
      for (unsigned int k = 0; k < states.size(); ++k)
        {
          std::vector<unsigned int> values;
          for (const auto &c : statistics.face_state_history)
            values.push_back(c[k]);
          f[states[k]] = values;
        }
      summary["residual_terms"] = r;
      summary["face_states"]    = f;
    }



    io::Json
    summarize_contact_iterations(const mechanics::ContactParameters &prm,
                                 const mechanics::ContactStatistics &s)
    {
      io::Json m                           = io::Json::object();
      m["solver"]                          = prm.method;
      m["initial_guess"]                   = std::string(prm.stick_guess ? "stick" : "open");
      m["c"]                               = prm.c;
      m["nonlinear_iterations"]            = s.iterations;
      m["converged"]                       = s.converged;
      m["residuals"]                       = s.residual_history;
      m["residuals_initial_relative"]      = s.initial_relative_history;
      m["steps"]                           = s.step_history;
      m["line_search_backtracks"]          = s.backtracks;
      m["cycles_detected"]                 = s.cycles_detected;
      m["factorizations"]                  = s.factorizations;
      m["reused_factorizations"]           = s.reused_factorizations;
      m["linear_iterations"]               = s.linear_iterations;
      m["linear_direct_fallbacks"]         = s.direct_fallbacks;
      m["linear_direct_workspace_retries"] = s.direct_workspace_retries;
      m["linear_fallback_factorizations"]  = s.fallback_factorizations;
      add_iteration_history(s, m);
      return m;
    }



    template <int dim>
    io::Json
    summarize_contact_solution(const ContactSolution<dim> &solution)
    {
      const mechanics::ContactStatistics &s = solution.statistics;
      const auto counts             = mechanics::count_states(solution.mesh, solution.faces);
      io::Json   m                  = summarize_contact_iterations(solution.parameters, s);
      m["n_open"]                   = counts[0];
      m["n_stick"]                  = counts[1];
      m["n_slip"]                   = counts[2];
      io::Json timing               = io::Json::object();
      timing["contact_rows_s"]      = s.time_contact_rows;
      timing["factorization_s"]     = s.time_factorization;
      timing["triangular_solves_s"] = s.time_solves;
      timing["residuals_s"]         = s.time_residuals;
      timing["cholesky_s"]          = s.time_cholesky;
      timing["form_W_s"]            = s.time_form_W;
      m["timing"]                   = timing;
      m["linear_solver"]            = solution.linear_solver == solution.requested_solver ?
                                        solution.requested_solver :
                                        std::string("full system (schur complement unavailable)");
      return m;
    }



    template <int dim>
    void
    write_fracture_outputs(const ContactSolution<dim> &solution, io::RunContext &context)
    {
      io::OutputFile csv(context.path("fractures.csv"));
      mechanics::write_fracture_table_header(csv.stream(), dim, false);
      mechanics::write_fracture_table_rows(csv.stream(), solution.mesh, solution.faces);
      csv.close();
      if (context.output_format == "none" || solution.mesh.fracture_faces.empty())
        return;
      geometry::FractureFields fields;
      mechanics::append_contact_fields(solution.faces, fields);
      geometry::write_fracture_cells(solution.mesh,
                                     context.path("fractures." + context.output_format),
                                     context.output_format,
                                     fields);
    }

#define POROFRAC_INSTANTIATE(dim)                                                            \
  template void     report_contact_solution(const ContactSolution<dim> &, io::RunContext &); \
  template io::Json summarize_contact_solution(const ContactSolution<dim> &);                \
  template void     write_fracture_outputs(const ContactSolution<dim> &, io::RunContext &);
    POROFRAC_INSTANTIATE(2)
    POROFRAC_INSTANTIATE(3)
#undef POROFRAC_INSTANTIATE
  } // namespace app
} // namespace porofrac
