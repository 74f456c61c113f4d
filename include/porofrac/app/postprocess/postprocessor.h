// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_POSTPROCESS_POSTPROCESSOR_H
#define POROFRAC_APP_POSTPROCESS_POSTPROCESSOR_H

#include <porofrac/base/registry.h>
#include <porofrac/coupling/parameters.h>
#include <porofrac/coupling/poromechanics.h>
#include <porofrac/flow/model.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/run_context.h>
#include <porofrac/mechanics/contact_problem.h>
#include <porofrac/mechanics/parameters.h>

#include <memory>
#include <vector>

namespace porofrac
{
  namespace app
  {
    /// The parsed physics parameters of a scene (those of the physics it does not run keep
    /// their defaults).
    struct PhysicsParameters
    {
      mechanics::ContactParameters mechanics;
      flow::FlowParameters         flow;
      coupling::CouplingParameters coupling;
    };

    /// What a postprocessor may look at: the mesh and the physics the scene runs (null if
    /// absent). The mechanics is mutable for postprocessors that solve again.
    template <int dim>
    struct SceneView
    {
      const geometry::CutMesh<dim>   &mesh;
      const PhysicsParameters        &parameters;
      mechanics::ContactProblem<dim> *mechanics     = nullptr;
      flow::FlowModel<dim>           *flow          = nullptr;
      coupling::Poromechanics<dim>   *poromechanics = nullptr;
      /// Time of the final state (0 for static scenes).
      double time = 0;
    };

    /**
     * A computation on the final state of a scene that reports results (ASPECT's
     * postprocessors): it prints to the results report and writes its own keys into
     * summary.json or files of its own. Implementations register in their own file with
     * PostprocessorRegistry; their factory returns null unless the deck switches them on.
     */
    template <int dim>
    class Postprocessor
    {
    public:
      virtual ~Postprocessor() = default;

      /// Runs at the end of the scene.
      virtual void
      execute(SceneView<dim> &scene, io::RunContext &context) = 0;

      /// Whether execute() changes the physics' state (e.g. solves again); such
      /// postprocessors run after all others.
      virtual bool
      changes_state() const
      {
        return false;
      }

      /// Whether execute() needs the mechanics' assembled system (K, the loads), not only
      /// its state.
      virtual bool
      needs_system_matrices() const
      {
        return false;
      }
    };

    template <int dim>
    using PostprocessorRegistry = Registry<Postprocessor<dim>, const PhysicsParameters &>;

    /// Runs every postprocessor the deck switches on: those that only read the state first
    /// (in name order), then those that change it.
    template <int dim>
    void
    run_postprocessors(SceneView<dim> &scene, io::RunContext &context);

    /// run_postprocessors() on the process that writes files (rank 0) while the others wait; a
    /// failure there is thrown on every process (collectively()). For scenes whose state is
    /// whole on every process.
    template <int dim>
    void
    run_postprocessors_on_writer(SceneView<dim> &scene, io::RunContext &context);

    /// Whether the deck switches any postprocessor on.
    template <int dim>
    bool
    any_postprocessor(const PhysicsParameters &parameters);

    /// Whether a postprocessor the deck switches on needs the mechanics' assembled system.
    template <int dim>
    bool
    postprocessors_need_system_matrices(const PhysicsParameters &parameters);
  } // namespace app
} // namespace porofrac

#endif
