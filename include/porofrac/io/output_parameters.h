// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_OUTPUT_PARAMETERS_H
#define POROFRAC_IO_OUTPUT_PARAMETERS_H

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace porofrac
{
  namespace io
  {
    /// Deck subsection "Output": where and what a run writes and prints.
    struct OutputParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(const dealii::ParameterHandler &prm);

      /// Output directory (the command line's --output-dir overrides it).
      std::string directory = "output";
      /// Field files: "vtu" (XML VTK), "vtk" (legacy ASCII) or "none".
      std::string format = "vtu";
      /// "quiet" (only the results report), "normal" (progress) or "verbose".
      std::string verbosity = "normal";
      /// Print the TimerOutput table at the end (never in quiet mode).
      bool timer_summary = true;
    };
  } // namespace io
} // namespace porofrac

#endif
