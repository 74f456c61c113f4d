// SPDX-License-Identifier: LGPL-2.1-or-later
// Test helper: the text of a file a run wrote, and the values a regular expression finds in it.
#ifndef POROFRAC_TESTS_FILE_TEXT_H
#define POROFRAC_TESTS_FILE_TEXT_H

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace porofrac_tests
{
  /// The whole text of @p file ("" if it cannot be read).
  inline std::string
  text_of(const std::string &file)
  {
    std::stringstream text;
    text << std::ifstream(file).rdbuf();
    return text.str();
  }

  /// Every capture of @p pattern's first group in @p text.
  inline std::vector<std::string>
  captures(const std::string &text, const std::string &pattern)
  {
    std::vector<std::string> result;
    const std::regex         re(pattern);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
         ++it)
      result.push_back((*it)[1]);
    return result;
  }
} // namespace porofrac_tests

#endif
