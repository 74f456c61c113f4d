// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/flow/flow_output.h>

namespace porofrac
{
  namespace flow
  {
    template <int dim>
    geometry::CellFields
    matrix_fields(const TwoPhaseSolver<dim> &solver, const TpfaGrid<dim> &grid)
    {
      const unsigned int n = grid.n_matrix_cells;
      Vector<double>     pw(n), pnw(n), pc(n), snw(n);
      for (unsigned int K = 0; K < n; ++K)
        {
          pw[K]  = solver.pressure(solver.state, K, 0);
          pnw[K] = solver.pressure(solver.state, K, 1);
          pc[K]  = solver.state[K][1] - solver.state[K][0];
          snw[K] = solver.saturation(solver.state, K, matrix_rock);
        }
      return {{"p_w", pw}, {"p_nw", pnw}, {"p_c", pc}, {"s_nw", snw}};
    }



    template <int dim>
    geometry::FractureFields
    fracture_fields(const TwoPhaseSolver<dim> &solver, const TpfaGrid<dim> &grid)
    {
      geometry::FractureFields fields = {
        {"p_w", {}}, {"p_nw", {}}, {"p_c", {}}, {"s_nw", {}}, {"aperture", {}}};
      for (unsigned int f = 0; f < grid.n_fracture_cells; ++f)
        {
          const unsigned int i = grid.n_matrix_cells + f;
          fields[0].second.push_back(solver.pressure(solver.state, i, 0));
          fields[1].second.push_back(solver.pressure(solver.state, i, 1));
          fields[2].second.push_back(solver.state[i][1] - solver.state[i][0]);
          fields[3].second.push_back(solver.saturation(solver.state, i, fracture_rock));
          fields[4].second.push_back(grid.aperture[f]);
        }
      return fields;
    }



    template <int dim>
    double
    mean_aperture(const geometry::CutMesh<dim> &mesh, const TpfaGrid<dim> &grid)
    {
      double num = 0, den = 0;
      for (unsigned int f = 0; f < grid.n_fracture_cells; ++f)
        {
          num += mesh.fracture_faces[f].measure * grid.aperture[f];
          den += mesh.fracture_faces[f].measure;
        }
      return den > 0 ? num / den : 0.;
    }

    io::Json
    linear_solver_summary(const std::string &name, const LinearSolverStatistics &statistics)
    {
      io::Json s      = io::Json::object();
      s["name"]       = name;
      s["solves"]     = statistics.solves;
      s["iterations"] = statistics.iterations;
      s["iterations_per_solve"] =
        statistics.solves > 0 ? double(statistics.iterations) / statistics.solves : 0.;
      s["direct_fallbacks"]         = statistics.direct_fallbacks;
      s["reused_setups"]            = statistics.reused_setups;
      s["direct_workspace_retries"] = statistics.direct_workspace_retries;
      return s;
    }

    void
    save_linear_statistics(io::CheckpointWriter &w, const LinearSolverStatistics &statistics)
    {
      w.put("flow linear solves", static_cast<unsigned int>(statistics.solves));
      w.put("flow linear iterations", static_cast<unsigned int>(statistics.iterations));
      w.put("flow linear direct fallbacks", static_cast<unsigned int>(statistics.direct_fallbacks));
      w.put("flow linear reused set-ups", static_cast<unsigned int>(statistics.reused_setups));
      w.put("flow linear direct workspace retries",
            static_cast<unsigned int>(statistics.direct_workspace_retries));
    }

    LinearSolverStatistics
    load_linear_statistics(io::CheckpointReader &r)
    {
      unsigned int solves = 0, iterations = 0, fallbacks = 0, reused = 0, retries = 0;
      r.get("flow linear solves", solves);
      r.get("flow linear iterations", iterations);
      r.get("flow linear direct fallbacks", fallbacks);
      r.get("flow linear reused set-ups", reused);
      r.get("flow linear direct workspace retries", retries);
      LinearSolverStatistics statistics;
      statistics.solves                   = solves;
      statistics.iterations               = iterations;
      statistics.direct_fallbacks         = fallbacks;
      statistics.reused_setups            = reused;
      statistics.direct_workspace_retries = retries;
      return statistics;
    }

    void
    report_linear_solver(const std::string            &name,
                         const LinearSolverStatistics &statistics,
                         std::ostream                 &report)
    {
      if (statistics.direct_workspace_retries > 0)
        report << "Flow: MUMPS factorizations repeated with a larger workspace: "
               << statistics.direct_workspace_retries << std::endl;
      if (statistics.iterations == 0)
        return;
      const double per_solve = double(statistics.iterations) / statistics.solves;
      report << "Flow: linear solver " << name
             << ", direct fallbacks: " << statistics.direct_fallbacks << std::endl
             << "Flow: linear solver " << name
             << ", below 30 Krylov iterations per solve: " << (per_solve < 30 ? "yes" : "NO")
             << std::endl;
    }

#define POROFRAC_INSTANTIATE(dim)                                                                  \
  template geometry::CellFields matrix_fields(const TwoPhaseSolver<dim> &, const TpfaGrid<dim> &); \
  template geometry::FractureFields fracture_fields(const TwoPhaseSolver<dim> &,                   \
                                                    const TpfaGrid<dim> &);                        \
  template double mean_aperture(const geometry::CutMesh<dim> &, const TpfaGrid<dim> &);
    POROFRAC_INSTANTIATE(2)
    POROFRAC_INSTANTIATE(3)
#undef POROFRAC_INSTANTIATE
  } // namespace flow
} // namespace porofrac
