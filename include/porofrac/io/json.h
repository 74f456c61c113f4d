// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_JSON_H
#define POROFRAC_IO_JSON_H

#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace porofrac
{
  namespace io
  {
    /**
     * A small JSON value (null, bool, number, string, array, object) used to build summary.json.
     * Object keys keep their insertion order so that files diff well. Non-finite numbers are
     * written as null (JSON has no inf/nan).
     */
    class Json
    {
    public:
      enum class Type
      {
        null,
        boolean,
        number,
        integer,
        string,
        array,
        object
      };

      Json();
      Json(const bool value);
      Json(const double value);
      Json(const int value);
      Json(const unsigned int value);
      Json(const long value);
      Json(const unsigned long value);
      Json(const long long value);
      Json(const unsigned long long value);
      Json(const char *value);
      Json(const std::string &value);
      Json(const std::vector<double> &values);
      Json(const std::vector<unsigned int> &values);

      static Json
      array();
      static Json
      object();

      /// Object access; inserts a null member if @p key is new (turns a null value into an object).
      Json &
      operator[](const std::string &key);
      /// Appends to an array (turns a null value into an array).
      void
      push_back(const Json &value);

      bool
      has(const std::string &key) const;
      /// The value of a number (integer or floating point); 0 for other types.
      double
      as_number() const;
      Type
      type() const
      {
        return kind;
      }

      /// Writes indented JSON.
      void
      write(std::ostream &out, const unsigned int indent = 0) const;
      /// Writes to @p filename, throwing on I/O failure.
      void
      write_file(const std::string &filename) const;

    private:
      Type                                      kind;
      bool                                      b       = false;
      double                                    number  = 0;
      long long                                 integer = 0;
      std::string                               text;
      std::vector<Json>                         items;
      std::vector<std::pair<std::string, Json>> members;
    };
  } // namespace io
} // namespace porofrac

#endif
