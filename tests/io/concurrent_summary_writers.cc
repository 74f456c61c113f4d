// SPDX-License-Identifier: LGPL-2.1-or-later
// Json::write_file from two processes writing the same file at once (in a distributed run each
// process that fails alone writes summary.json): 500 writes each, of a short and a long text;
// afterwards the file holds one of the two texts whole, and no temporary file is left beside it.
#include <porofrac/io/json.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "../file_text.h"
#include <sys/wait.h>
#include <unistd.h>

namespace
{
  /// The text of writer @p k: a short one and one of about 20 kB.
  porofrac::io::Json
  summary_of(const int k)
  {
    porofrac::io::Json summary = porofrac::io::Json::object();
    summary["status"]          = "failed";
    summary["failed_on_rank"]  = k;
    summary["reason"]          = std::string(k == 0 ? 10 : 20000, k == 0 ? 'a' : 'b');
    return summary;
  }

  std::string
  text_of(const porofrac::io::Json &json)
  {
    std::ostringstream text;
    json.write(text);
    text << '\n';
    return text.str();
  }
} // namespace

int
main()
{
  const std::filesystem::path directory = "concurrent_summary_writers";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  const std::string file = (directory / "summary.json").string();

  pid_t writers[2];
  for (int k = 0; k < 2; ++k)
    if ((writers[k] = fork()) == 0)
      {
        const porofrac::io::Json summary = summary_of(k);
        try
          {
            for (unsigned int i = 0; i < 500; ++i)
              summary.write_file(file);
          }
        catch (const std::exception &)
          {
            _exit(1);
          }
        _exit(0);
      }
  bool written = true;
  for (const pid_t writer : writers)
    {
      int status = 0;
      waitpid(writer, &status, 0);
      written = written && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    }
  std::cout << "both writers finished without an error: " << (written ? "yes" : "no") << std::endl;

  const std::string text = porofrac_tests::text_of(file);
  std::cout << "the file holds one writer's text whole: "
            << (text == text_of(summary_of(0)) || text == text_of(summary_of(1)) ? "yes" : "no")
            << std::endl;
  unsigned int files = 0;
  for ([[maybe_unused]] const auto &entry : std::filesystem::directory_iterator(directory))
    ++files;
  std::cout << "files in the directory: " << files << std::endl;
  std::filesystem::remove_all(directory);
}
