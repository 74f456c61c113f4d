// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_BASE_REGISTRY_H
#define POROFRAC_BASE_REGISTRY_H

#include <deal.II/base/parameter_handler.h>

#include <porofrac/base/exceptions.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace porofrac
{
  /**
   * The named implementations of one extension point (friction laws, saturation laws, linear
   * solvers, ...), in the manner of ASPECT's plugin lists. An implementation registers itself
   * from its own source file with POROFRAC_REGISTER (one line); the deck's selection pattern and
   * the `--print-parameters` documentation are built from the registered names and descriptions,
   * so adding an implementation touches no other file.
   *
   * @p Interface is the abstract base class, @p Arguments what a factory receives (for instance
   * the parsed parameters it needs). Each implementation may also declare its own parameters
   * (entries of the subsection the extension point's owner is in when it calls
   * declare_parameters()).
   */
  template <typename Interface, typename... Arguments>
  class Registry
  {
  public:
    using Factory = std::function<std::unique_ptr<Interface>(Arguments...)>;
    using Declare = std::function<void(dealii::ParameterHandler &)>;

    struct Entry
    {
      std::string name;
      std::string description;
      Factory     create;
      Declare     declare;
    };

    /// The one registry of this extension point (built on first use, so that registrations
    /// from static initializers in any translation unit find it).
    static Registry &
    instance()
    {
      static Registry registry;
      return registry;
    }

    /// Registers @p create under @p name; returns true so that it can initialize a static.
    bool
    add(const std::string &name,
        const std::string &description,
        const Factory     &create,
        const Declare     &declare = {})
    {
      for (const Entry &e : list)
        if (e.name == name)
          throw std::logic_error("two implementations registered as '" + name + "'");
      list.push_back({name, description, create, declare});
      return true;
    }

    /// Registered entries in the order of registration.
    const std::vector<Entry> &
    entries() const
    {
      return list;
    }

    bool
    has(const std::string &name) const
    {
      for (const Entry &e : list)
        if (e.name == name)
          return true;
      return false;
    }

    /// "a|b|c": the names, sorted, for Patterns::Selection.
    std::string
    selection() const
    {
      std::vector<std::string> names;
      for (const Entry &e : list)
        names.push_back(e.name);
      std::sort(names.begin(), names.end());
      std::string s;
      for (const std::string &n : names)
        s += (s.empty() ? "" : "|") + n;
      return s;
    }

    /// "a: description a; b: description b", for the documentation of the selecting entry.
    std::string
    documentation() const
    {
      std::string s;
      for (const Entry &e : sorted())
        s += (s.empty() ? "" : " ") + e.name + ": " + e.description;
      return s;
    }

    /// Calls the declare function of every entry that has one, in name order.
    void
    declare_parameters(dealii::ParameterHandler &prm) const
    {
      for (const Entry &e : sorted())
        if (e.declare)
          e.declare(prm);
    }

    /// A new instance of @p name; an InputError naming @p parameter if there is none.
    std::unique_ptr<Interface>
    create(const std::string &name, const std::string &parameter, Arguments... arguments) const
    {
      for (const Entry &e : list)
        if (e.name == name)
          return e.create(std::forward<Arguments>(arguments)...);
      throw InputError(parameter, "'" + name + "' is not one of " + selection());
    }

  private:
    Registry() = default;

    std::vector<Entry>
    sorted() const
    {
      std::vector<Entry> s = list;
      std::sort(s.begin(), s.end(), [](const Entry &a, const Entry &b) { return a.name < b.name; });
      return s;
    }

    std::vector<Entry> list;
  };
} // namespace porofrac

#define POROFRAC_REGISTRY_CONCAT_(a, b) a##b
#define POROFRAC_REGISTRY_CONCAT(a, b) POROFRAC_REGISTRY_CONCAT_(a, b)

/**
 * Registers an implementation from its source file, with the registry's type alias (a type
 * without commas) declared next to the interface:
 *   POROFRAC_REGISTER(FrictionLawRegistry<2>, "coulomb", "description", factory, declare)
 * The module libraries are CMake OBJECT libraries, so that every registering translation unit is
 * linked into every executable (a static archive would drop the unreferenced ones).
 */
#define POROFRAC_REGISTER(RegistryType, ...)                                                  \
  namespace                                                                                   \
  {                                                                                           \
    [[maybe_unused]] const bool POROFRAC_REGISTRY_CONCAT(porofrac_registered_, __COUNTER__) = \
      RegistryType::instance().add(__VA_ARGS__);                                              \
  }

#endif
