// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/io/deck.h>
#include <porofrac/io/text.h>

#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>

namespace porofrac
{
  namespace io
  {
    namespace
    {
      std::string
      join(const std::vector<std::string> &path, const std::string &last)
      {
        std::string result;
        for (const auto &p : path)
          result += p + "/";
        return result + last;
      }

      /// Extracts the pattern description from deal.II's "does not match the pattern" message.
      std::string
      pattern_of(const std::string &message)
      {
        const std::string key = "does not match the given pattern <";
        const auto        pos = message.find(key);
        if (pos == std::string::npos)
          return "";
        const std::string rest    = message.substr(pos + key.size());
        std::string       pattern = rest.substr(0, rest.find(">."));
        // Collapse deal.II's line breaks and indentation into single spaces.
        std::string collapsed;
        for (const char c : pattern)
          if (!std::isspace(static_cast<unsigned char>(c)) ||
              (!collapsed.empty() && collapsed.back() != ' '))
            collapsed += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
        return collapsed;
      }
    } // namespace



    Deck::Deck(ParameterHandler &prm)
        : prm(prm)
    {
      // Learn the declared entries from the handler's own short listing.
      std::stringstream listing;
      prm.print_parameters(listing, ParameterHandler::ShortPRM);
      std::vector<std::string> path;
      std::string              line;
      while (std::getline(listing, line))
        {
          line = trim(line);
          if (line.rfind("subsection ", 0) == 0)
            {
              path.push_back(trim(line.substr(11)));
              subsections.insert(join(path, "").substr(0, join(path, "").size() - 1));
            }
          else if (line == "end")
            path.pop_back();
          else if (line.rfind("set ", 0) == 0)
            entries.insert(join(path, trim(line.substr(4, line.find('=') - 4))));
        }
    }



    void
    Deck::set(const std::string &path, const std::string &value)
    {
      if (!entries.count(path))
        {
          std::string       hint;
          const auto        slash   = path.rfind('/');
          const std::string section = slash == std::string::npos ? "" : path.substr(0, slash);
          if (!section.empty() && !subsections.count(section))
            hint = " (there is no subsection '" + section + "')";
          throw InputError(path,
                           "is not a known parameter" + hint +
                             "; `porofrac --print-parameters` lists them all");
        }
      std::vector<std::string> parts;
      std::stringstream        s(path);
      std::string              part;
      while (std::getline(s, part, '/'))
        parts.push_back(part);
      for (unsigned int i = 0; i + 1 < parts.size(); ++i)
        prm.enter_subsection(parts[i]);
      std::string error;
      try
        {
          prm.set(parts.back(), value);
        }
      catch (const std::bad_alloc &)
        {
          for (unsigned int i = 0; i + 1 < parts.size(); ++i)
            prm.leave_subsection();
          throw;
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
      for (unsigned int i = 0; i + 1 < parts.size(); ++i)
        prm.leave_subsection();
      assigned.insert(path);
      if (!error.empty())
        {
          const std::string pattern = pattern_of(error);
          throw InputError(path,
                           "value '" + value + "' is not allowed" +
                             (pattern.empty() ? "" : " (expected " + pattern + ")"));
        }
    }



    void
    Deck::set(const std::string &assignment)
    {
      const auto equal = assignment.find('=');
      if (equal == std::string::npos || trim(assignment.substr(0, equal)).empty())
        throw InputError("--set", "'" + assignment + "' is not of the form \"Section/Name=value\"");
      set(trim(assignment.substr(0, equal)), trim(assignment.substr(equal + 1)));
    }



    void
    Deck::read(const std::string &filename)
    {
      read(filename, {});
    }



    void
    Deck::read(const std::string &filename, std::vector<std::string> including)
    {
      namespace fs         = std::filesystem;
      const std::string me = fs::path(filename).filename().string();
      std::error_code   ec;
      if (fs::is_directory(filename, ec))
        throw InputError("deck", "'" + me + "' is a directory, not a deck file");
      std::ifstream in(filename);
      if (!in)
        throw InputError("deck", "cannot open '" + me + "'");
      // A file that includes itself, directly or through others, would be read forever.
      const std::string key = fs::weakly_canonical(filename, ec).string();
      for (const std::string &f : including)
        if (f == key)
          throw InputError("deck", "'include " + me + "' forms a cycle of includes");
      including.push_back(key);

      // Lines of an included file name the file; those of the deck itself only the line.
      const std::string        prefix = including.size() > 1 ? me + ", " : "";
      std::vector<std::string> path;
      std::string              line, logical;
      unsigned int             line_no = 0, start_line = 0;
      const auto               statement_done = [&]() {
        const std::string statement = trim(logical);
        logical.clear();
        if (!statement.empty())
          read_statement(statement,
                         prefix + "line " + std::to_string(start_line) + ": ",
                         filename,
                         path,
                         including);
      };
      while (std::getline(in, line))
        {
          ++line_no;
          const auto hash = line.find('#');
          if (hash != std::string::npos)
            line = line.substr(0, hash);
          if (logical.empty())
            start_line = line_no;
          const std::string t = trim(line);
          if (!t.empty() && t.back() == '\\')
            {
              logical += t.substr(0, t.size() - 1) + " ";
              continue;
            }
          logical += t;
          statement_done();
        }
      // A continued last line is a statement too.
      statement_done();
      if (!path.empty())
        throw InputError("deck",
                         prefix + "subsection '" + path.back() + "' is not closed with 'end'");
    }



    void
    Deck::read_statement(const std::string              &statement,
                         const std::string              &where,
                         const std::string              &filename,
                         std::vector<std::string>       &path,
                         const std::vector<std::string> &including)
    {
      if (statement.rfind("subsection ", 0) == 0)
        {
          path.push_back(trim(statement.substr(11)));
          std::string full = join(path, "");
          full             = full.substr(0, full.size() - 1);
          if (!subsections.count(full))
            throw InputError(full, where + "is not a known subsection");
        }
      else if (statement == "end")
        {
          if (path.empty())
            throw InputError("deck", where + "'end' without a matching 'subsection'");
          path.pop_back();
        }
      else if (statement.rfind("set ", 0) == 0)
        {
          const auto equal = statement.find('=');
          if (equal == std::string::npos)
            throw InputError("deck", where + "expected 'set Name = value'");
          const std::string name = join(path, trim(statement.substr(4, equal - 4)));
          try
            {
              set(name, trim(statement.substr(equal + 1)));
            }
          catch (const InputError &e)
            {
              throw InputError(e.parameter, where + e.reason);
            }
        }
      else if (statement.rfind("include ", 0) == 0)
        {
          // Shared fragments (e.g. a scene's geometry), relative to this deck, top level only.
          if (!path.empty())
            throw InputError("deck", where + "'include' is only allowed outside subsections");
          std::string file  = trim(statement.substr(8));
          const auto  slash = filename.rfind('/');
          if (!file.empty() && file[0] != '/' && slash != std::string::npos)
            file = filename.substr(0, slash + 1) + file;
          try
            {
              read(file, including);
            }
          catch (const InputError &e)
            {
              throw InputError(e.parameter, where + e.reason);
            }
        }
      else
        throw InputError("deck",
                         where + "cannot read '" + statement.substr(0, 40) +
                           "' (expected 'subsection', 'set' or 'end')");
    }
  } // namespace io
} // namespace porofrac
