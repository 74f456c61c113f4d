// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_DECK_H
#define POROFRAC_IO_DECK_H

#include <deal.II/base/parameter_handler.h>

#include <set>
#include <string>
#include <vector>

namespace porofrac
{
  namespace io
  {
    using namespace dealii;

    /**
     * Reads an input deck (.prm) into a ParameterHandler whose entries are already declared, and
     * applies command-line overrides. Every problem becomes an InputError naming the parameter
     * ("Section/Name") and the line: unknown parameters or subsections, values that do not match
     * their pattern, unbalanced subsection/end, a missing file.
     */
    class Deck
    {
    public:
      explicit Deck(ParameterHandler &prm);

      /// Reads @p filename (format: `subsection`, `set Name = value`, `end`, `#` comments,
      /// trailing backslash continues a line).
      void
      read(const std::string &filename);

      /// Applies one override "Section/Subsection/Name=value" (the --set syntax).
      void
      set(const std::string &assignment);

      /// Sets the entry @p path ("Section/Name") to @p value, checking that it exists and matches.
      void
      set(const std::string &path, const std::string &value);

      /// All declared entry paths ("Section/Name").
      const std::set<std::string> &
      declared_entries() const
      {
        return entries;
      }

      /// The entry paths that the deck or an override set.
      const std::set<std::string> &
      assigned_entries() const
      {
        return assigned;
      }

    private:
      /// Reads @p filename, included from the files @p including (canonical paths, outermost
      /// first).
      void
      read(const std::string &filename, std::vector<std::string> including);
      /// Carries out one statement (continued lines joined) of @p filename; @p where locates it
      /// for error messages, @p path is the current subsection.
      void
      read_statement(const std::string              &statement,
                     const std::string              &where,
                     const std::string              &filename,
                     std::vector<std::string>       &path,
                     const std::vector<std::string> &including);

      ParameterHandler     &prm;
      std::set<std::string> entries;
      std::set<std::string> subsections;
      std::set<std::string> assigned;
    };
  } // namespace io
} // namespace porofrac

#endif
