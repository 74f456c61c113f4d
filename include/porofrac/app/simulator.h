// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_APP_SIMULATOR_H
#define POROFRAC_APP_SIMULATOR_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/io/run_context.h>

#include <ostream>
#include <string>

namespace porofrac
{
  namespace app
  {
    /**
     * Runs the scene a parsed deck describes: builds the cut mesh, reports it, runs the physics
     * the deck asks for (`Physics`), and writes summary.json into @p output_directory.
     * @p deck_path locates relative file names; results that tests compare go to @p report;
     * @p options: checkpoints and restart (command line).
     */
    template <int dim>
    void
    run_scene(dealii::ParameterHandler &prm,
              const std::string        &deck_path,
              const std::string        &output_directory,
              std::ostream             &report,
              const io::RunOptions     &options = {});
  } // namespace app
} // namespace porofrac

#endif
