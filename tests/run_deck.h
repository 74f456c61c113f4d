// SPDX-License-Identifier: LGPL-2.1-or-later
// Test helper: runs a deck as porofrac does, quietly, and reports an InputError as text.
#ifndef POROFRAC_TESTS_RUN_DECK_H
#define POROFRAC_TESTS_RUN_DECK_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/app/parameters.h>
#include <porofrac/app/simulator.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/io/deck.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace porofrac_tests
{
  /// The deck @p deck_file, relative to the directory of the test source @p test_source
  /// (its __FILE__).
  inline std::string
  deck_path(const std::string &test_source, const std::string &deck_file)
  {
    return (std::filesystem::path(test_source).parent_path() / deck_file)
      .lexically_normal()
      .string();
  }

  /// Runs the deck @p path with @p settings (then quiet, no timer table) into @p dir; returns
  /// "no error" or "InputError: " and the message. Other exceptions pass through.
  inline std::string
  run_deck(const std::string              &path,
           const std::vector<std::string> &settings,
           const std::string              &dir,
           const porofrac::io::RunOptions &options = {})
  {
    dealii::ParameterHandler prm;
    porofrac::app::declare_all_parameters(prm);
    porofrac::io::Deck deck(prm);
    deck.read(path);
    for (const auto &s : settings)
      deck.set(s);
    for (const char *s : {"Output/Verbosity=quiet", "Output/Timer output=none"})
      deck.set(s);
    std::ostringstream report;
    try
      {
        if (prm.get_integer("Dimension") == 2)
          porofrac::app::run_scene<2>(prm, path, dir, report, options);
        else
          porofrac::app::run_scene<3>(prm, path, dir, report, options);
      }
    catch (const porofrac::InputError &e)
      {
        return std::string("InputError: ") + e.what();
      }
    return "no error";
  }
} // namespace porofrac_tests

#endif
