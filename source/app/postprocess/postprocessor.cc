// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/base/mpi_tools.h>

#include <algorithm>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    template <int dim>
    void
    run_postprocessors(SceneView<dim> &scene, io::RunContext &context)
    {
      auto entries = PostprocessorRegistry<dim>::instance().entries();
      std::sort(entries.begin(), entries.end(), [](const auto &a, const auto &b) {
        return a.name < b.name;
      });
      std::vector<std::unique_ptr<Postprocessor<dim>>> active;
      for (const auto &e : entries)
        if (auto p = e.create(scene.parameters))
          active.push_back(std::move(p));
      std::stable_partition(active.begin(), active.end(), [](const auto &p) {
        return !p->changes_state();
      });
      for (const auto &p : active)
        p->execute(scene, context);
    }

    template <int dim>
    void
    run_postprocessors_on_writer(SceneView<dim> &scene, io::RunContext &context)
    {
      collectively(context.communicator, [&]() {
        if (context.writes_files())
          run_postprocessors(scene, context);
      });
    }

    template <int dim>
    bool
    any_postprocessor(const PhysicsParameters &parameters)
    {
      for (const auto &e : PostprocessorRegistry<dim>::instance().entries())
        if (e.create(parameters))
          return true;
      return false;
    }

    template <int dim>
    bool
    postprocessors_need_system_matrices(const PhysicsParameters &parameters)
    {
      for (const auto &e : PostprocessorRegistry<dim>::instance().entries())
        if (const auto p = e.create(parameters); p && p->needs_system_matrices())
          return true;
      return false;
    }

    template bool
    postprocessors_need_system_matrices<2>(const PhysicsParameters &);
    template bool
    postprocessors_need_system_matrices<3>(const PhysicsParameters &);
    template bool
    any_postprocessor<2>(const PhysicsParameters &);
    template bool
    any_postprocessor<3>(const PhysicsParameters &);
    template void
    run_postprocessors(SceneView<2> &, io::RunContext &);
    template void
    run_postprocessors(SceneView<3> &, io::RunContext &);
    template void
    run_postprocessors_on_writer(SceneView<2> &, io::RunContext &);
    template void
    run_postprocessors_on_writer(SceneView<3> &, io::RunContext &);
  } // namespace app
} // namespace porofrac
