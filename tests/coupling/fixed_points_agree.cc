// SPDX-License-Identifier: LGPL-2.1-or-later
// The coupled Newton-Krylov, Anderson and plain fixed-point iterations (and the fixed point on u)
// solve the same discrete problem, whether each step starts from the last state or from the
// extrapolation of the last two: on the fractured drainage scene with contact (energy_drainage.prm,
// 15 steps) and on its 3D counterpart (energy_drainage_3d.prm on a coarser mesh, 123 faces, for
// 200 s, 2 steps: three fractures with intersection lines, stick, slip and open faces), the final
// normal jumps and multipliers of every fracture face agree to a fraction of the coupling
// tolerance. Printed: the largest difference of [u]_n relative to max
// |[u]_n| and of lambda_n relative to max |lambda_n| between each pair of methods (asserted <
// 1e-4), and whether the final face states coincide.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <porofrac/app/parameters.h>
#include <porofrac/app/simulator.h>
#include <porofrac/io/deck.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  struct Face
  {
    double      jump_n, lambda_n;
    std::string state;
  };

  std::vector<std::string>
  split(const std::string &line)
  {
    std::vector<std::string> c;
    std::stringstream        ss(line);
    std::string              item;
    while (std::getline(ss, item, ','))
      c.push_back(item);
    return c;
  }

  /// Rows of fractures.csv at the last time written (columns found by name, 2D or 3D).
  std::vector<Face>
  final_faces(const std::string &file)
  {
    std::ifstream            in(file);
    std::string              line;
    std::vector<std::string> rows;
    std::getline(in, line);
    const auto header = split(line);
    const auto column = [&](const std::string &name) {
      return std::find(header.begin(), header.end(), name) - header.begin();
    };
    const auto jump = column("jump_n"), lambda = column("lambda_n"), state = column("state");
    while (std::getline(in, line))
      rows.push_back(line);
    const std::string last_time = rows.back().substr(rows.back().rfind(',') + 1);
    std::vector<Face> faces;
    for (const auto &r : rows)
      if (r.substr(r.rfind(',') + 1) == last_time)
        {
          const auto c = split(r);
          faces.push_back({std::stod(c[jump]), std::stod(c[lambda]), c[state]});
        }
    return faces;
  }

  template <int dim>
  std::vector<Face>
  run(const std::string &deck_name,
      const std::string &method,
      const std::string &variable,
      const bool         extrapolate = false)
  {
    dealii::ParameterHandler prm;
    porofrac::app::declare_all_parameters(prm);
    porofrac::io::Deck deck(prm);
    const std::string  path = (std::filesystem::path(__FILE__).parent_path() / deck_name).string();
    deck.read(path);
    deck.set("Coupling/Method=" + method);
    deck.set("Coupling/Fixed point=" + variable);
    deck.set(std::string("Coupling/Extrapolate initial guess=") + (extrapolate ? "true" : "false"));
    deck.set("Output/Verbosity=quiet");
    deck.set("Output/Timer output=none");
    if (dim == 3) // the 3D runs dominate the test's time in the Debug build
      {
        deck.set("Flow/Final time=200");
        deck.set("Geometry/Mesh size=0.35");
        deck.set("Geometry/Fracture mesh size=0.175");
      }
    const std::string dir = "out-" + std::to_string(dim) + "d-" + method.substr(0, 5) + "-" +
                            variable.substr(0, 5) + (extrapolate ? "-ex" : "");
    std::ostringstream report;
    porofrac::app::run_scene<dim>(prm, path, dir, report);
    return final_faces(dir + "/fractures.csv");
  }

  void
  compare(const char *label, const std::vector<Face> &a, const std::vector<Face> &b)
  {
    double jmax = 0, lmax = 0, dj = 0, dl = 0;
    bool   same_states = a.size() == b.size();
    for (unsigned int i = 0; i < a.size() && i < b.size(); ++i)
      {
        jmax        = std::max(jmax, std::abs(a[i].jump_n));
        lmax        = std::max(lmax, std::abs(a[i].lambda_n));
        dj          = std::max(dj, std::abs(a[i].jump_n - b[i].jump_n));
        dl          = std::max(dl, std::abs(a[i].lambda_n - b[i].lambda_n));
        same_states = same_states && a[i].state == b[i].state;
      }
    std::cout << label << ": " << a.size() << " faces, [u]_n and lambda_n agree to 1e-4: "
              << (dj <= 1e-4 * jmax && dl <= 1e-4 * lmax ? "yes" : "NO")
              << ", same face states: " << (same_states ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  // run_scene is collective over MPI_COMM_WORLD (one process here).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        deck = "energy_drainage.prm";
  const auto nk_p    = run<2>(deck, "newton-krylov", "equivalent pressure");
  const auto plain_p = run<2>(deck, "fixed point", "equivalent pressure");
  const auto nk_u    = run<2>(deck, "newton-krylov", "displacement");
  const auto and_p   = run<2>(deck, "anderson", "equivalent pressure");
  const auto and_p_x = run<2>(deck, "anderson", "equivalent pressure", /*extrapolate=*/true);
  compare("Newton-Krylov vs plain, p_E", nk_p, plain_p);
  compare("Newton-Krylov on p_E vs on u", nk_p, nk_u);
  compare("Newton-Krylov vs Anderson, p_E", nk_p, and_p);
  compare("Anderson from the last state vs from the extrapolation", and_p, and_p_x);

  const std::string deck_3d = "energy_drainage_3d.prm";
  const auto        nk_p3   = run<3>(deck_3d, "newton-krylov", "equivalent pressure");
  const auto        nk_u3   = run<3>(deck_3d, "newton-krylov", "displacement");
  const auto        and_p3  = run<3>(deck_3d, "anderson", "equivalent pressure");
  compare("3D: Newton-Krylov on p_E vs on u", nk_p3, nk_u3);
  compare("3D: Newton-Krylov vs Anderson, p_E", nk_p3, and_p3);
}
