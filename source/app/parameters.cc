// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/parameters.h>
#include <porofrac/coupling/parameters.h>
#include <porofrac/flow/parameters.h>
#include <porofrac/geometry/parameters.h>
#include <porofrac/io/output_parameters.h>
#include <porofrac/mechanics/parameters.h>

#include <map>

namespace porofrac
{
  namespace app
  {
    void
    declare_all_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii;
      prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "Space dimension of the scene.");
      prm.declare_entry(
        "Physics",
        "mesh only",
        Patterns::Selection("mesh only|contact mechanics|two-phase flow|poromechanics"),
        "What the scene solves. 'mesh only' builds, checks and writes the cut mesh.");
      prm.declare_entry(
        "Distributed",
        "auto",
        Patterns::Selection("auto|always"),
        "'auto' runs the distributed code (METIS partition, Trilinos, MUMPS or the iterative "
        "solver of Mechanics/Distributed linear solver; doc/parallel.md) when the run has more "
        "than one MPI process and the serial code otherwise; 'always' runs the distributed code "
        "on one process too. Poromechanics distributes its flow and solves the same serial "
        "contact problem on every process, or a distributed one with Coupling/Distributed "
        "contact mechanics; 'mesh only' runs on rank 0 while the other processes wait.");
      prm.declare_entry("Scene name",
                        "",
                        Patterns::Anything(),
                        "Name written to summary.json ('scene'); empty: the deck's file name.");

      io::OutputParameters::declare_parameters(prm);

      geometry::GeometryParameters::declare_parameters(prm);
      mechanics::ContactParameters::declare_parameters(prm);
      flow::FlowParameters::declare_parameters(prm);
      coupling::CouplingParameters::declare_parameters(prm);
    }



    std::vector<std::string>
    unused_parameters(const std::set<std::string> &assigned, const std::string &physics)
    {
      // The physics subsections each Physics reads (Geometry, Output and the top level: all).
      const std::map<std::string, std::set<std::string>> reads = {
        {"mesh only", {}},
        {"contact mechanics", {"Mechanics"}},
        {"two-phase flow", {"Flow"}},
        {"poromechanics", {"Mechanics", "Flow", "Coupling"}}};
      const std::set<std::string> physics_sections = {"Mechanics", "Flow", "Coupling"};
      const auto                  it               = reads.find(physics);
      std::vector<std::string>    unused;
      for (const std::string &path : assigned)
        {
          const std::string section = path.substr(0, path.find('/'));
          if (it != reads.end() && physics_sections.count(section) && !it->second.count(section))
            unused.push_back(path);
        }
      return unused;
    }
  } // namespace app
} // namespace porofrac
