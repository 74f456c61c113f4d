// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_IO_CHECKPOINT_H
#define POROFRAC_IO_CHECKPOINT_H

#include <deal.II/base/tensor.h>

#include <deal.II/lac/vector.h>

#include <array>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace porofrac
{
  namespace io
  {
    /**
     * The state of a time-dependent run, written between two time steps so that the run can be
     * resumed (`--checkpoint-every`, `--restart`). A checkpoint is a sequence of named values in
     * binary, bit-exact; the reader asks for the names in the writer's order, so that a
     * checkpoint of another scene, physics or version is refused with a clear message instead
     * of being misread.
     */
    class CheckpointWriter
    {
    public:
      void
      put(const std::string &name, const double value);
      void
      put(const std::string &name, const unsigned int value);
      void
      put(const std::string &name, const std::string &value);
      void
      put(const std::string &name, const std::vector<double> &values);
      void
      put(const std::string &name, const dealii::Vector<double> &values);
      void
      put(const std::string &name, const std::vector<std::array<double, 2>> &values);
      template <int dim>
      void
      put(const std::string &name, const std::vector<dealii::Tensor<1, dim>> &values);
      void
      put(const std::string &name, const std::vector<std::pair<double, std::string>> &values);

      /// Writes everything put so far to @p file (through a temporary file and a rename, so that
      /// an interrupted write never leaves a truncated checkpoint).
      void
      write(const std::string &file) const;

    private:
      void
      put_header(const std::string &name, const char type, const std::size_t size);
      void
      put_doubles(const double *values, const std::size_t n);

      std::ostringstream data;
    };

    /// Reads a checkpoint of CheckpointWriter; errors are InputErrors naming `--restart`.
    class CheckpointReader
    {
    public:
      explicit CheckpointReader(const std::string &file);

      void
      get(const std::string &name, double &value);
      void
      get(const std::string &name, unsigned int &value);
      void
      get(const std::string &name, std::string &value);
      void
      get(const std::string &name, std::vector<double> &values);
      void
      get(const std::string &name, dealii::Vector<double> &values);
      void
      get(const std::string &name, std::vector<std::array<double, 2>> &values);
      template <int dim>
      void
      get(const std::string &name, std::vector<dealii::Tensor<1, dim>> &values);
      void
      get(const std::string &name, std::vector<std::pair<double, std::string>> &values);

      /// Reads a value that must equal @p expected (a size, a name): an InputError saying that
      /// the checkpoint belongs to another run otherwise.
      void
      expect(const std::string &name, const unsigned int expected);
      void
      expect(const std::string &name, const std::string &expected);

    private:
      /// Reads the header of the next value: it must be @p name of @p type; returns its size.
      std::size_t
      get_header(const std::string &name, const char type);
      void
      get_doubles(double *values, const std::size_t n);

      std::string        file;
      std::istringstream data;
    };
  } // namespace io
} // namespace porofrac

#endif
