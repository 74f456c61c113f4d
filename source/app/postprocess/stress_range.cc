// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/postprocess/postprocessor.h>

#include <algorithm>
#include <iomanip>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /// Range of every stress component at the cell centroids (patch tests; deck entry
      /// Mechanics/Report stress range).
      template <int dim>
      class StressRange : public Postprocessor<dim>
      {
      public:
        void
        execute(SceneView<dim> &scene, io::RunContext &context) override
        {
          const auto &problem = *scene.mechanics;
          Point<dim>  centroid;
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
      };

      template <int dim>
      std::unique_ptr<Postprocessor<dim>>
      make(const PhysicsParameters &p)
      {
        if (!p.mechanics.reports.stress_range)
          return nullptr;
        return std::make_unique<StressRange<dim>>();
      }

      const std::string description = "the range of each stress component at the cell centroids";
    } // namespace

    POROFRAC_REGISTER(PostprocessorRegistry<2>, "stress range", description, make<2>)
    POROFRAC_REGISTER(PostprocessorRegistry<3>, "stress range", description, make<3>)
  } // namespace app
} // namespace porofrac
