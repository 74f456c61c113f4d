// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/parameters.h>
#include <porofrac/coupling/parameters.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/io/output_parameters.h>
#include <porofrac/mechanics/parameters.h>

namespace porofrac
{
  namespace app
  {
    void
    declare_all_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii;
      prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "Space dimension of the scene.");
      prm.declare_entry(
        "Physics",
        "mesh only",
        Patterns::Selection("mesh only|contact mechanics|two-phase flow|poromechanics"),
        "What the scene solves. 'mesh only' builds, checks and writes the cut mesh.");
      prm.declare_entry("Scene name",
                        "",
                        Patterns::Anything(),
                        "Name written to summary.json ('scene'); empty: the deck's file name.");

      io::OutputParameters::declare_parameters(prm);

      geometry::GeometryParameters::declare_parameters(prm);
      mechanics::ContactParameters::declare_parameters(prm);
      flow::FlowParameters::declare_parameters(prm);
      coupling::CouplingParameters::declare_parameters(prm);
    }
  } // namespace app
} // namespace porofrac
