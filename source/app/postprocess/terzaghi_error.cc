// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/coupling/analytical.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /**
       * Coupling/Analytical solution = terzaghi: the relative L2 error (cell-measure weighted)
       * of the matrix wetting pressure at the final time against Terzaghi's consolidation of the
       * column between the lowest and the highest y of the mesh, drained at the top.
       */
      template <int dim>
      class TerzaghiError : public Postprocessor<dim>
      {
      public:
        void
        execute(SceneView<dim> &scene, io::RunContext &context) override
        {
          check_input(scene.poromechanics != nullptr,
                      "Coupling/Analytical solution",
                      "terzaghi needs Physics = poromechanics");
          const auto &grid   = *scene.flow->grid;
          const auto &solver = *scene.flow->solver;
          const auto &mp     = scene.parameters.mechanics;
          const auto &cp     = scene.parameters.coupling;
          double      y_min = 1e300, y_max = -1e300;
          for (const auto &v : scene.mesh.triangulation.get_vertices())
            {
              y_min = std::min(y_min, v[1]);
              y_max = std::max(y_max, v[1]);
            }
          coupling::Terzaghi exact;
          exact.height           = y_max - y_min;
          exact.initial_pressure = scene.parameters.flow.initial_pressure[flow::matrix_rock][0];
          exact.drained_pressure =
            solver.matrix_dirichlet.empty() ? 0. : solver.matrix_dirichlet.begin()->second[0];
          exact.consolidation = coupling::Terzaghi::coefficient(scene.flow->initial_permeability,
                                                                scene.flow->rocks[0].viscosity[0],
                                                                mp.young_modulus,
                                                                mp.poisson_ratio,
                                                                cp.biot_coefficient,
                                                                cp.biot_modulus);
          double e2 = 0, n2 = 0;
          for (unsigned int K = 0; K < grid.n_matrix_cells; ++K)
            {
              const double z  = y_max - grid.nodes[K].centre[1];
              const double pe = exact.pressure(z, scene.time);
              const double w  = grid.nodes[K].measure;
              e2 += w * std::pow(solver.pressure(solver.state, K, 0) - pe, 2);
              n2 += w * std::pow(pe - exact.drained_pressure, 2);
            }
          const double error = std::sqrt(e2 / n2);
          context.report << "Coupling: Terzaghi, c_v t / H^2 = " << std::setprecision(4)
                         << exact.consolidation * scene.time / (exact.height * exact.height)
                         << ", relative L2 error of the excess pressure " << std::scientific
                         << std::setprecision(3) << error << std::defaultfloat << std::endl;
          io::Json e                = io::Json::object();
          e["pressure_rel_l2"]      = error;
          context.summary["errors"] = e;
        }
      };

      template <int dim>
      std::unique_ptr<Postprocessor<dim>>
      make(const PhysicsParameters &p)
      {
        if (p.coupling.analytical_solution != "terzaghi")
          return nullptr;
        return std::make_unique<TerzaghiError<dim>>();
      }

      const std::string description =
        "relative L2 error of the matrix pressure against Terzaghi's consolidation";
    } // namespace

    POROFRAC_REGISTER(PostprocessorRegistry<2>, "terzaghi error", description, make<2>)
    POROFRAC_REGISTER(PostprocessorRegistry<3>, "terzaghi error", description, make<3>)
  } // namespace app
} // namespace porofrac
