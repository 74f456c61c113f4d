// SPDX-License-Identifier: LGPL-2.1-or-later
// Test helper: a top-level string of a run's summary.json.
#ifndef POROFRAC_TESTS_SUMMARY_JSON_H
#define POROFRAC_TESTS_SUMMARY_JSON_H

#include <fstream>
#include <sstream>
#include <string>

namespace porofrac_tests
{
  /// The value of "key" in a flat JSON object (enough for summary.json's top-level strings);
  /// "(missing)" if there is none.
  inline std::string
  json_string(const std::string &file, const std::string &key)
  {
    std::stringstream text;
    text << std::ifstream(file).rdbuf();
    const std::string s = text.str();
    const auto        k = s.find("\"" + key + "\"");
    if (k == std::string::npos)
      return "(missing)";
    const auto begin = s.find('"', s.find(':', k) + 1) + 1;
    return s.substr(begin, s.find('"', begin) - begin);
  }
} // namespace porofrac_tests

#endif
