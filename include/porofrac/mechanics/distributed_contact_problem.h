// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_DISTRIBUTED_CONTACT_PROBLEM_H
#define POROFRAC_MECHANICS_DISTRIBUTED_CONTACT_PROBLEM_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <porofrac/geometry/distributed_cut_mesh.h>
#include <porofrac/mechanics/contact_output.h>
#include <porofrac/mechanics/contact_solver.h>
#include <porofrac/mechanics/distributed_elasticity_system.h>
#include <porofrac/mechanics/friction_field.h>
#include <porofrac/mechanics/parameters.h>

#include <string>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /**
     * Frictional contact mechanics on a DistributedCutMesh: the DistributedElasticitySystem,
     * the FrictionField (evaluated on the replicated fracture-face table) and the ContactSolver
     * on Trilinos vectors, with the state (u, lambda). The distributed counterpart of
     * ContactProblem for static scenes; results are gathered to rank 0 for the report, the CSV
     * tables and the postprocessors.
     */
    template <int dim>
    class DistributedContactProblem
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;

      DistributedContactProblem(const geometry::DistributedCutMesh<dim> &mesh,
                                const ContactParameters                 &parameters,
                                ConditionalOStream                      &progress,
                                TimerOutput                             &timer);

      /// Dofs, constraints, matrices, loads, friction field. Collective.
      void
      setup();

      /// Solves (ContactSolver::solve) from the current (u, lambda) if @p warm_start and a
      /// previous solve exists, else from the deck's initial guess. Collective; throws
      /// SolverFailure on every process.
      const ContactStatistics &
      solve(const bool warm_start = false);

      /// Poromechanical loads of eq. (11b) (DistributedElasticitySystem); every process gives
      /// all of p_E.
      void
      set_equivalent_pressures(const std::vector<double> &p_E_matrix,
                               const std::vector<double> &p_E_fracture,
                               const double               biot)
      {
        system.set_equivalent_pressures(p_E_matrix, p_E_fracture, biot);
      }

      /// (u, lambda) in the numbering of @p serial_dofs (the same FE on the serial cut mesh) on
      /// every process. Collective.
      void
      replicate_state(const DoFHandler<dim> &serial_dofs,
                      Vector<double>        &displacement,
                      Vector<double>        &multipliers) const;
      /// Sets (u, lambda) from the serial numbering of @p serial_dofs (the same on every
      /// process); the next warm-started solve starts from it.
      void
      set_state(const DoFHandler<dim> &serial_dofs,
                const Vector<double>  &displacement,
                const Vector<double>  &multipliers);

      const ContactStatistics &
      statistics() const
      {
        return solver.statistics();
      }
      std::string
      linear_solver_name() const
      {
        return solver.linear_solver_name();
      }
      types::global_dof_index
      n_dofs() const
      {
        return system.n_dofs();
      }
      types::global_dof_index
      n_displacement_dofs() const
      {
        return system.n_displacement_dofs();
      }
      const ContactParameters &
      get_parameters() const
      {
        return prm;
      }
      const DistributedElasticitySystem<dim> &
      get_system() const
      {
        return system;
      }
      const VectorType &
      displacement() const
      {
        return u;
      }
      const VectorType &
      multipliers() const
      {
        return lambda;
      }

      /// 1/2 a(u, u) (J). Collective.
      double
      elastic_energy() const
      {
        return system.elastic_energy(u);
      }

      /// The contact values of every fracture face, in index order, on rank 0 (empty on the
      /// other ranks). Collective.
      std::vector<ContactFaceValues<dim>>
      gather_face_values() const;
      /// u in the numbering of @p serial_dofs (the same FE on the serial cut mesh; given on
      /// rank 0 only), on rank 0 (empty elsewhere, and without @p serial_dofs). Collective.
      Vector<double>
      gather_displacement(const DoFHandler<dim> *serial_dofs) const;
      /// The multipliers of every face (dim per face, global frame), on rank 0. Collective.
      Vector<double>
      gather_multipliers() const;
      /// u with the ghost entries of the relevant dofs.
      VectorType
      ghosted_displacement() const;

    private:
      ContactParameters                                    prm;
      DistributedElasticitySystem<dim>                     system;
      FrictionField<dim>                                   friction_field;
      ContactSolver<dim, DistributedElasticitySystem<dim>> solver;
      VectorType                                           u, lambda;
      bool                                                 solved_once = false;
    };

    /**
     * Writes the P2 displacement of @p problem as one piece per process,
     * @p basename_NNNN.vtu, with the subdomain of each cell, and (rank 0) the record
     * @p basename.pvtu listing them; with @p format "vtk" legacy pieces only. Collective.
     */
    template <int dim>
    void
    write_distributed_displacement(const DistributedContactProblem<dim> &problem,
                                   const std::string                    &directory,
                                   const std::string                    &basename,
                                   const std::string                    &format);
  } // namespace mechanics
} // namespace porofrac

#endif
