// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/parameters.h>
#include <porofrac/coupling/scene.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/mechanics/scene.h>

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

      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        Patterns::Anything(),
                        "Directory for all output files (created if needed); the command-line "
                        "option --output-dir overrides it.");
      prm.declare_entry("Format",
                        "vtu",
                        Patterns::Selection("vtu|vtk|none"),
                        "Format of field files: XML VTK (vtu), legacy ASCII VTK (vtk), or none.");
      prm.declare_entry("Verbosity",
                        "normal",
                        Patterns::Selection("quiet|normal|verbose"),
                        "quiet: only the results report (what tests compare); normal: progress; "
                        "verbose: every nonlinear iteration.");
      prm.declare_entry("Timer output",
                        "summary",
                        Patterns::Selection("summary|none"),
                        "Print the TimerOutput table at the end (never in quiet mode).");
      prm.leave_subsection();

      geometry::GeometryParameters::declare_parameters(prm);
      // MECHANICS HOOK (declare)
      mechanics::declare_parameters(prm);
      // FLOW HOOK (declare)
      flow::FlowParameters::declare_parameters(prm);
      coupling::declare_parameters(prm);
    }
  } // namespace app
} // namespace porofrac
