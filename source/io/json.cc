// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/io/json.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace porofrac
{
  namespace io
  {
    Json::Json()
        : kind(Type::null)
    {
    }
    Json::Json(const bool value)
        : kind(Type::boolean)
        , b(value)
    {
    }
    Json::Json(const double value)
        : kind(Type::number)
        , number(value)
    {
    }
    Json::Json(const int value)
        : kind(Type::integer)
        , integer(value)
    {
    }
    Json::Json(const unsigned int value)
        : kind(Type::integer)
        , integer(value)
    {
    }
    Json::Json(const long value)
        : kind(Type::integer)
        , integer(value)
    {
    }
    Json::Json(const unsigned long value)
        : kind(Type::integer)
        , integer(static_cast<long long>(value))
    {
    }
    Json::Json(const long long value)
        : kind(Type::integer)
        , integer(value)
    {
    }
    Json::Json(const unsigned long long value)
        : kind(Type::integer)
        , integer(static_cast<long long>(value))
    {
    }
    Json::Json(const char *value)
        : kind(Type::string)
        , text(value)
    {
    }
    Json::Json(const std::string &value)
        : kind(Type::string)
        , text(value)
    {
    }
    Json::Json(const std::vector<double> &values)
        : kind(Type::array)
    {
      for (const double v : values)
        items.emplace_back(v);
    }
    Json::Json(const std::vector<unsigned int> &values)
        : kind(Type::array)
    {
      for (const unsigned int v : values)
        items.emplace_back(v);
    }

    Json
    Json::array()
    {
      Json j;
      j.kind = Type::array;
      return j;
    }

    Json
    Json::object()
    {
      Json j;
      j.kind = Type::object;
      return j;
    }

    Json &
    Json::operator[](const std::string &key)
    {
      if (kind == Type::null)
        kind = Type::object;
      if (kind != Type::object)
        throw std::logic_error("JSON value is not an object (key '" + key + "')");
      for (auto &m : members)
        if (m.first == key)
          return m.second;
      members.emplace_back(key, Json());
      return members.back().second;
    }

    double
    Json::as_number() const
    {
      return kind == Type::number ? number : (kind == Type::integer ? double(integer) : 0.);
    }



    bool
    Json::has(const std::string &key) const
    {
      for (const auto &m : members)
        if (m.first == key)
          return true;
      return false;
    }

    void
    Json::push_back(const Json &value)
    {
      if (kind == Type::null)
        kind = Type::array;
      if (kind != Type::array)
        throw std::logic_error("JSON value is not an array");
      items.push_back(value);
    }

    namespace
    {
      void
      write_string(std::ostream &out, const std::string &s)
      {
        out << '"';
        for (const char c : s)
          switch (c)
            {
              case '"':
                out << "\\\"";
                break;
              case '\\':
                out << "\\\\";
                break;
              case '\n':
                out << "\\n";
                break;
              case '\t':
                out << "\\t";
                break;
              default:
                if (static_cast<unsigned char>(c) < 0x20)
                  out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c)
                      << std::dec << std::setfill(' ');
                else
                  out << c;
            }
        out << '"';
      }
    } // namespace

    void
    Json::write(std::ostream &out, const unsigned int indent) const
    {
      const std::string pad(indent + 2, ' '), close(indent, ' ');
      switch (kind)
        {
          case Type::null:
            out << "null";
            break;
          case Type::boolean:
            out << (b ? "true" : "false");
            break;
          case Type::integer:
            out << integer;
            break;
          case Type::number:
            if (std::isfinite(number))
              {
                std::ostringstream s;
                s << std::setprecision(10) << number;
                out << s.str();
              }
            else
              out << "null";
            break;
          case Type::string:
            write_string(out, text);
            break;
          case Type::array:
            {
              bool scalars = true;
              for (const auto &i : items)
                scalars = scalars && i.kind != Type::array && i.kind != Type::object;
              out << '[';
              for (std::size_t i = 0; i < items.size(); ++i)
                {
                  if (!scalars)
                    out << '\n' << pad;
                  items[i].write(out, indent + 2);
                  if (i + 1 < items.size())
                    out << (scalars ? ", " : ",");
                }
              if (!scalars && !items.empty())
                out << '\n' << close;
              out << ']';
              break;
            }
          case Type::object:
            out << '{';
            for (std::size_t i = 0; i < members.size(); ++i)
              {
                out << '\n' << pad;
                write_string(out, members[i].first);
                out << ": ";
                members[i].second.write(out, indent + 2);
                if (i + 1 < members.size())
                  out << ',';
              }
            if (!members.empty())
              out << '\n' << close;
            out << '}';
            break;
        }
    }

    void
    Json::write_file(const std::string &filename) const
    {
      // Written beside it and renamed over it, so that a run stopped while writing leaves the
      // previous file whole; the temporary is this process's own, so that processes writing the
      // same file at once (each stopping alone) leave one of their files whole.
      const std::string temporary = filename + ".tmp." + std::to_string(getpid());
      {
        std::ofstream out(temporary);
        if (!out)
          throw std::runtime_error("cannot write '" + filename + "'");
        write(out);
        out << '\n';
        if (!out.flush())
          throw std::runtime_error("cannot write '" + filename + "'");
      }
      std::error_code error;
      std::filesystem::rename(temporary, filename, error);
      if (error)
        {
          std::filesystem::remove(temporary, error);
          throw std::runtime_error("cannot write '" + filename + "'");
        }
    }
  } // namespace io
} // namespace porofrac
