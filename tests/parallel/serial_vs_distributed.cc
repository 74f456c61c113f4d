// SPDX-License-Identifier: LGPL-2.1-or-later
// The distributed contact solver (2 MPI processes: METIS partition, Trilinos, MUMPS) against the
// serial one (rank 0: UMFPACK) on the six-fracture scene of Section 5.2.2 (the deck's coarse mesh,
// 168 fracture faces, the deck's globalization): for the active-set method from the stick guess
// and the semi-smooth Newton method from the open guess, the same iteration counts and face
// states, and displacements (gathered into the serial numbering), multipliers and face jumps equal
// to 1e-8 relative (they solve the same linear systems; only round-off differs).
// Then the iterative distributed solver (GMRES with the block preconditioner, inexact steps)
// against the direct one, for both methods, at a nonlinear tolerance of 1e-9: the same face
// states, 1 to 50 GMRES steps per contact iteration, multipliers and jumps equal to 1e-6
// relative (measured: at most 4e-8). The fields are compared at a tolerance tighter than the
// deck's 1e-6 because the contact residual weighs the jumps with c (1e9): at 1e-6 the
// semi-smooth Newton fields differ from the direct ones by up to 1e-4 relative, with the same
// face states (doc/parallel.md).
// mpi: 2
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <porofrac/geometry/distributed_cut_mesh.h>
#include <porofrac/mechanics/contact_output.h>
#include <porofrac/mechanics/contact_problem.h>
#include <porofrac/mechanics/distributed_contact_problem.h>

#include <iostream>
#include <memory>

#include "../mechanics/six_fractures.h"

using namespace porofrac;
using namespace dealii;

namespace
{
  /// max |a - b| / max |b|.
  double
  relative_difference(const Vector<double> &a, const Vector<double> &b)
  {
    Vector<double> d(a);
    d -= b;
    return d.linfty_norm() / b.linfty_norm();
  }

  /// max over the faces of |jump_a - jump_b| / max |jump_b| (local frames).
  double
  jump_difference(const std::vector<mechanics::ContactFaceValues<2>> &a,
                  const std::vector<mechanics::ContactFaceValues<2>> &b)
  {
    double d = 0, scale = 0;
    for (unsigned int f = 0; f < a.size(); ++f)
      {
        d     = std::max(d, (a[f].jump - b[f].jump).norm());
        scale = std::max(scale, b[f].jump.norm());
      }
    return d / scale;
  }

  unsigned int
  same_states(const std::vector<mechanics::ContactFaceValues<2>> &a,
              const std::vector<mechanics::ContactFaceValues<2>> &b)
  {
    unsigned int n = 0;
    for (unsigned int f = 0; f < a.size(); ++f)
      n += (a[f].state == b[f].state);
    return n;
  }

  /// The solution of a distributed solve, gathered on rank 0.
  struct Gathered
  {
    unsigned int                                 iterations, linear_iterations, reused;
    Vector<double>                               u, lambda;
    std::vector<mechanics::ContactFaceValues<2>> faces;
  };

  Gathered
  solve_distributed(const geometry::DistributedCutMesh<2> &mesh,
                    const mechanics::ContactParameters    &c,
                    const DoFHandler<2>                   *serial_dofs,
                    ConditionalOStream                    &quiet,
                    TimerOutput                           &timer)
  {
    mechanics::DistributedContactProblem<2> problem(mesh, c, quiet, timer);
    problem.setup();
    const auto &s = problem.solve();
    return {s.iterations,
            s.linear_iterations,
            s.reused_factorizations,
            problem.gather_displacement(serial_dofs),
            problem.gather_multipliers(),
            problem.gather_face_values()};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                       rank_0 = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  ConditionalOStream               out(std::cout, rank_0);
  ConditionalOStream               quiet(std::cout, false);
  TimerOutput                      timer(quiet, TimerOutput::never, TimerOutput::wall_times);

  auto                            mesh = six_fractures::mesh(0.05, 0.02);
  geometry::DistributedCutMesh<2> distributed(*mesh, MPI_COMM_WORLD);
  const unsigned int              n_faces = mesh->fracture_faces.size();
  const unsigned int              owned   = distributed.locally_owned_faces().size();
  out << "fracture faces: " << n_faces << ", owned by every process: "
      << (Utilities::MPI::min(owned, MPI_COMM_WORLD) > 0 ? "yes" : "no") << ", partition of them: "
      << (Utilities::MPI::sum(owned, MPI_COMM_WORLD) == n_faces ? "yes" : "no") << std::endl;

  mechanics::ContactParameters c = six_fractures::contact_parameters();
  c.line_search                  = true;
  c.line_search_on_stagnation    = true;
  c.cycle_damping                = 0.5;
  for (const bool ssn : {false, true})
    {
      c.method                    = ssn ? "semismooth newton" : "active set";
      c.stick_guess               = !ssn;
      c.distributed_linear_solver = "direct";
      std::unique_ptr<mechanics::ContactProblem<2>> serial;
      if (rank_0)
        {
          serial = std::make_unique<mechanics::ContactProblem<2>>(*mesh, c, quiet, timer);
          serial->setup();
          serial->solve();
        }
      const Gathered direct = solve_distributed(
        distributed, c, serial ? &serial->get_dof_handler() : nullptr, quiet, timer);
      // The iterative solver (GMRES with the block preconditioner, inexact steps), at a
      // nonlinear tolerance of 1e-9 for the comparison of the fields.
      mechanics::ContactParameters tight = c;
      tight.distributed_linear_solver    = "iterative";
      tight.tolerance                    = 1e-9;
      const Gathered iterative = solve_distributed(distributed, tight, nullptr, quiet, timer);
      mechanics::ContactParameters reuse = c;
      reuse.reuse_iterations             = 30;
      const Gathered reused = solve_distributed(distributed, reuse, nullptr, quiet, timer);
      if (!rank_0)
        continue;
      const auto faces = mechanics::contact_face_values(*serial);
      out << c.method << ", " << (ssn ? "open" : "stick") << " guess: iterations serial "
          << serial->statistics().iterations << ", distributed " << direct.iterations
          << "; equal face states " << same_states(faces, direct.faces) << " of " << n_faces
          << "; u, lambda, jumps equal to 1e-8: "
          << (relative_difference(direct.u, serial->displacement()) < 1e-8 &&
                  relative_difference(direct.lambda, serial->multipliers()) < 1e-8 &&
                  jump_difference(direct.faces, faces) < 1e-8 ?
                "yes" :
                "no")
          << std::endl;
      out << "  iterative solver, tolerance " << tight.tolerance
          << ": converged; equal face states " << same_states(iterative.faces, direct.faces)
          << " of " << n_faces << "; linear iterations per contact iteration in [1, 50]: "
          << (iterative.linear_iterations >= iterative.iterations &&
                  iterative.linear_iterations <= 50 * iterative.iterations ?
                "yes" :
                "no")
          << "; lambda and jumps equal to 1e-6: "
          << (relative_difference(iterative.lambda, direct.lambda) < 1e-6 &&
                  jump_difference(iterative.faces, direct.faces) < 1e-6 ?
                "yes" :
                "no")
          << std::endl;
      out << "  direct solver reusing its factors: iterations " << reused.iterations
          << "; factors reused: " << (reused.reused > 0 ? "yes" : "no") << "; equal face states "
          << same_states(reused.faces, direct.faces) << " of " << n_faces
          << "; lambda and jumps equal to 1e-8: "
          << (relative_difference(reused.lambda, direct.lambda) < 1e-8 &&
                  jump_difference(reused.faces, direct.faces) < 1e-8 ?
                "yes" :
                "no")
          << std::endl;
    }
}
