// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/io/checkpoint.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace porofrac
{
  namespace io
  {
    namespace
    {
      const std::string magic = "porofrac checkpoint 1\n";

      void
      put_size(std::ostream &out, const std::size_t n)
      {
        const std::uint64_t v = n;
        out.write(reinterpret_cast<const char *>(&v), sizeof(v));
      }

      std::size_t
      get_size(std::istream &in)
      {
        std::uint64_t v = 0;
        in.read(reinterpret_cast<char *>(&v), sizeof(v));
        return in ? std::size_t(v) : std::size_t(-1);
      }
    } // namespace



    void
    CheckpointWriter::put_header(const std::string &name, const char type, const std::size_t size)
    {
      put_size(data, name.size());
      data.write(name.data(), name.size());
      data.put(type);
      put_size(data, size);
    }



    void
    CheckpointWriter::put_doubles(const double *values, const std::size_t n)
    {
      data.write(reinterpret_cast<const char *>(values), n * sizeof(double));
    }



    void
    CheckpointWriter::put(const std::string &name, const double value)
    {
      put_header(name, 'd', 1);
      put_doubles(&value, 1);
    }



    void
    CheckpointWriter::put(const std::string &name, const unsigned int value)
    {
      put_header(name, 'u', value);
    }



    void
    CheckpointWriter::put(const std::string &name, const std::string &value)
    {
      put_header(name, 's', value.size());
      data.write(value.data(), value.size());
    }



    void
    CheckpointWriter::put(const std::string &name, const std::vector<double> &values)
    {
      put_header(name, 'v', values.size());
      put_doubles(values.data(), values.size());
    }



    void
    CheckpointWriter::put(const std::string &name, const dealii::Vector<double> &values)
    {
      put_header(name, 'v', values.size());
      put_doubles(values.data(), values.size());
    }



    void
    CheckpointWriter::put(const std::string &name, const std::vector<std::array<double, 2>> &values)
    {
      put_header(name, '2', values.size());
      for (const auto &v : values)
        put_doubles(v.data(), 2);
    }



    template <int dim>
    void
    CheckpointWriter::put(const std::string                         &name,
                          const std::vector<dealii::Tensor<1, dim>> &values)
    {
      put_header(name, char('0' + 3 * dim), values.size());
      for (const auto &v : values)
        for (unsigned int d = 0; d < dim; ++d)
          put_doubles(&v[d], 1);
    }



    void
    CheckpointWriter::put(const std::string                                 &name,
                          const std::vector<std::pair<double, std::string>> &values)
    {
      put_header(name, 'p', values.size());
      for (const auto &[t, s] : values)
        {
          put_doubles(&t, 1);
          put_size(data, s.size());
          data.write(s.data(), s.size());
        }
    }



    void
    CheckpointWriter::write(const std::string &file) const
    {
      const std::string temporary = file + ".tmp";
      {
        std::ofstream out(temporary, std::ios::binary);
        out << magic << data.str();
        out.close();
        check_input(!out.fail(), "--checkpoint-every", "cannot write '" + temporary + "'");
      }
      std::error_code ec;
      std::filesystem::rename(temporary, file, ec);
      check_input(!ec, "--checkpoint-every", "cannot write '" + file + "'");
    }



    CheckpointReader::CheckpointReader(const std::string &file)
        : file(file)
    {
      std::ifstream in(file, std::ios::binary);
      check_input(bool(in), "--restart", "cannot open the checkpoint '" + file + "'");
      std::ostringstream all;
      all << in.rdbuf();
      const std::string text = all.str();
      check_input(text.compare(0, magic.size(), magic) == 0,
                  "--restart",
                  "'" + file + "' is not a porofrac checkpoint");
      data.str(text.substr(magic.size()));
    }



    std::size_t
    CheckpointReader::get_header(const std::string &name, const char type)
    {
      const std::size_t length = get_size(data);
      std::string       found(length < 4096 ? length : 0, ' ');
      data.read(found.data(), found.size());
      const char found_type = data.get();
      check_input(data && found == name && found_type == type,
                  "--restart",
                  "the checkpoint '" + file + "' does not fit this run (expected '" + name +
                    "', found '" + found + "')");
      return get_size(data);
    }



    void
    CheckpointReader::get_doubles(double *values, const std::size_t n)
    {
      data.read(reinterpret_cast<char *>(values), n * sizeof(double));
      check_input(bool(data), "--restart", "the checkpoint '" + file + "' is truncated");
    }



    void
    CheckpointReader::get(const std::string &name, double &value)
    {
      get_header(name, 'd');
      get_doubles(&value, 1);
    }



    void
    CheckpointReader::get(const std::string &name, unsigned int &value)
    {
      value = get_header(name, 'u');
    }



    void
    CheckpointReader::get(const std::string &name, std::string &value)
    {
      value.assign(get_header(name, 's'), ' ');
      data.read(value.data(), value.size());
      check_input(bool(data), "--restart", "the checkpoint '" + file + "' is truncated");
    }



    void
    CheckpointReader::get(const std::string &name, std::vector<double> &values)
    {
      values.resize(get_header(name, 'v'));
      get_doubles(values.data(), values.size());
    }



    void
    CheckpointReader::get(const std::string &name, dealii::Vector<double> &values)
    {
      values.reinit(get_header(name, 'v'));
      get_doubles(values.data(), values.size());
    }



    void
    CheckpointReader::get(const std::string &name, std::vector<std::array<double, 2>> &values)
    {
      values.resize(get_header(name, '2'));
      for (auto &v : values)
        get_doubles(v.data(), 2);
    }



    template <int dim>
    void
    CheckpointReader::get(const std::string &name, std::vector<dealii::Tensor<1, dim>> &values)
    {
      values.resize(get_header(name, char('0' + 3 * dim)));
      for (auto &v : values)
        for (unsigned int d = 0; d < dim; ++d)
          get_doubles(&v[d], 1);
    }



    void
    CheckpointReader::get(const std::string                           &name,
                          std::vector<std::pair<double, std::string>> &values)
    {
      values.resize(get_header(name, 'p'));
      for (auto &[t, s] : values)
        {
          get_doubles(&t, 1);
          s.assign(get_size(data), ' ');
          data.read(s.data(), s.size());
        }
      check_input(bool(data), "--restart", "the checkpoint '" + file + "' is truncated");
    }



    void
    CheckpointReader::expect(const std::string &name, const unsigned int expected)
    {
      unsigned int found = 0;
      get(name, found);
      check_input(found == expected,
                  "--restart",
                  "the checkpoint '" + file + "' belongs to another run: " + name + " " +
                    std::to_string(found) + " there, " + std::to_string(expected) + " here");
    }



    void
    CheckpointReader::expect(const std::string &name, const std::string &expected)
    {
      std::string found;
      get(name, found);
      check_input(found == expected,
                  "--restart",
                  "the checkpoint '" + file + "' belongs to another run: " + name + " '" + found +
                    "' there, '" + expected + "' here");
    }

    template void
    CheckpointWriter::put<2>(const std::string &, const std::vector<dealii::Tensor<1, 2>> &);
    template void
    CheckpointWriter::put<3>(const std::string &, const std::vector<dealii::Tensor<1, 3>> &);
    template void
    CheckpointReader::get<2>(const std::string &, std::vector<dealii::Tensor<1, 2>> &);
    template void
    CheckpointReader::get<3>(const std::string &, std::vector<dealii::Tensor<1, 3>> &);
  } // namespace io
} // namespace porofrac
