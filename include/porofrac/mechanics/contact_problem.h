// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_CONTACT_PROBLEM_H
#define POROFRAC_MECHANICS_CONTACT_PROBLEM_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/vector.h>

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/mechanics/contact_law.h>
#include <porofrac/mechanics/contact_solver.h>
#include <porofrac/mechanics/elasticity_system.h>
#include <porofrac/mechanics/friction_field.h>
#include <porofrac/mechanics/parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    /**
     * Frictional contact mechanics on a cut mesh (paper eqs. (10)-(11c) with the Coulomb
     * conditions (25)-(26)): the ElasticitySystem, the FrictionField, the ContactSolver and
     * the state (u, lambda) they act on. What the scenes and the coupling use.
     */
    template <int dim>
    class ContactProblem
    {
    public:
      ContactProblem(const geometry::CutMesh<dim> &mesh,
                     const ContactParameters      &parameters,
                     ConditionalOStream           &progress,
                     TimerOutput                  &timer);

      /// Dofs, constraints, elasticity block and coupling (assembled once), friction field.
      /// With less than SystemAssembly::matrices the problem can hold and report a state
      /// (set_state()) but not solve: for a solution computed by the distributed code.
      void
      setup(SystemAssembly what = SystemAssembly::matrices);

      /**
       * Solves the contact problem (ContactSolver::solve) from the current (u, lambda) if
       * @p warm_start and a previous solve exists, else from the deck's initial guess. Throws
       * SolverFailure after max_iterations; statistics() then tells what happened.
       */
      const ContactStatistics &
      solve(const bool warm_start = false);

      /// Forgets the previous solve: the next solve() starts from the initial guess and
      /// refactorizes; what depends on the mesh only (K, its factors, W, the loads) is kept.
      void
      reset();

      /// Changes the contact method, c and initial guess and calls reset(): the next solve()
      /// is the cold start of a fresh problem with these settings (paper Tables 1-4).
      void
      set_contact_solver(const std::string &method, const double c, const bool stick_guess);

      /// Time-dependent problems: the current jumps become those of the previous time step,
      /// from which the tangential conditions (25) count the slip (ContactSolver).
      void
      accept_time_step()
      {
        std::vector<Tensor<1, dim>> jumps(system.get_mesh().fracture_faces.size());
        for (unsigned int f = 0; f < jumps.size(); ++f)
          jumps[f] = jump(f);
        solver.set_previous_jumps(jumps);
      }

      /// Poromechanical loads of eq. (11b) (ElasticitySystem::set_equivalent_pressures).
      void
      set_equivalent_pressures(const std::vector<double> &p_E_matrix,
                               const std::vector<double> &p_E_fracture,
                               const double               biot);

      const ContactStatistics &
      statistics() const
      {
        return solver.statistics();
      }
      /// The linear solver in use (Mechanics/Linear solver, or "full system" where the Schur
      /// complement is unavailable).
      std::string
      linear_solver_name() const
      {
        return solver.linear_solver_name();
      }
      /// LU (or dense Schur) factorizations over every solve so far.
      unsigned int
      n_factorizations() const;

      unsigned int
      n_dofs() const
      {
        return system.n_dofs();
      }
      unsigned int
      n_displacement_dofs() const
      {
        return system.n_displacement_dofs();
      }

      /// Face-averaged jump [u]_sigma (eq. (10)) and multiplier of face @p f, global frame.
      Tensor<1, dim>
      jump(const unsigned int f) const
      {
        return system.jump(u, f);
      }
      Tensor<1, dim>
      multiplier(const unsigned int f) const;
      /// [u]_n = n+ . [u]_sigma (<= 0 when admissible; d_f = d_0 - [u]_n, eq. (11d)).
      double
      normal_jump(const unsigned int f) const;
      /// Local frame rows: n+, then the tangent(s).
      Tensor<2, dim>
      frame(const unsigned int f) const
      {
        return system.frame(f);
      }
      /// Friction coefficient of face @p f at the current slip.
      double
      friction(const unsigned int f) const
      {
        return solver.friction(contact_jump(f), f);
      }
      /// The jump the contact conditions read: jump(f) minus the multiplier stabilization.
      Tensor<1, dim>
      contact_jump(const unsigned int f) const
      {
        return jump(f) -
               stabilization_term<dim>(system.get_multiplier_stabilization(),
                                       f,
                                       [this](const unsigned int g) { return multiplier(g); });
      }
      FaceState
      state(const unsigned int f) const
      {
        return solver.state(contact_jump(f), multiplier(f), f);
      }

      /// Per active cell: the mean of div u over the cell (weighted in axisymmetric mode).
      std::vector<double>
      cell_divergence() const
      {
        return system.cell_divergence(u);
      }
      double
      cell_measure(const unsigned int K) const
      {
        return system.cell_measure(K);
      }
      double
      face_measure(const unsigned int f) const
      {
        return system.face_measure(f);
      }
      /// 1/2 a(u, u) (J).
      double
      elastic_energy() const
      {
        return system.elastic_energy(u);
      }
      /// Work of the fixed loads on u - @p u_old.
      double
      external_work(const Vector<double> &u_old) const
      {
        return system.external_work(u, u_old);
      }
      /// Cauchy stress at a point of a cell: C eps(u) + pre-stress.
      SymmetricTensor<2, dim>
      stress(const typename DoFHandler<dim>::active_cell_iterator &cell,
             const Point<dim>                                     &unit_point) const
      {
        return system.stress(u, cell, unit_point);
      }

      const ElasticitySystem<dim> &
      get_system() const
      {
        return system;
      }
      const DoFHandler<dim> &
      get_dof_handler() const
      {
        return system.get_dof_handler();
      }
      const geometry::CutMesh<dim> &
      get_mesh() const
      {
        return system.get_mesh();
      }
      const ContactParameters &
      get_parameters() const
      {
        return prm;
      }
      const Vector<double> &
      displacement() const
      {
        return u;
      }
      /// dim components per fracture face, global frame.
      const Vector<double> &
      multipliers() const
      {
        return lambda;
      }
      /// Sets (u, lambda), e.g. to evaluate output of a given state; the next warm-started
      /// solve starts from it.
      void
      set_state(const Vector<double> &displacement, const Vector<double> &multipliers)
      {
        u      = displacement;
        lambda = multipliers;
      }

    private:
      /// Declared in this order: each is built from the ones above it.
      ContactParameters     prm;
      ElasticitySystem<dim> system;
      FrictionField<dim>    friction_field;
      ContactSolver<dim>    solver;
      Vector<double>        u;
      Vector<double>        lambda;
      bool                  solved_once = false;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
