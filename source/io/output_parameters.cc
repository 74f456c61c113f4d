// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/io/output_parameters.h>

namespace porofrac
{
  namespace io
  {
    using namespace dealii;

    void
    OutputParameters::declare_parameters(ParameterHandler &prm)
    {
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
    }



    void
    OutputParameters::parse_parameters(const ParameterHandler &prm)
    {
      directory     = prm.get({"Output"}, "Directory");
      format        = prm.get({"Output"}, "Format");
      verbosity     = prm.get({"Output"}, "Verbosity");
      timer_summary = prm.get({"Output"}, "Timer output") == "summary";
    }
  } // namespace io
} // namespace porofrac
