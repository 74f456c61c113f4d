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
