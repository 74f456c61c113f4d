// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_DISTRIBUTED_ELASTICITY_SYSTEM_H
#define POROFRAC_MECHANICS_DISTRIBUTED_ELASTICITY_SYSTEM_H

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <porofrac/geometry/distributed_cut_mesh.h>
#include <porofrac/mechanics/elasticity_system.h>
#include <porofrac/mechanics/multiplier_stabilization.h>
#include <porofrac/mechanics/parameters.h>

#include <string>
#include <utility>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    /**
     * The linear part of the contact problem, distributed (step-40 style): the counterpart of
     * ElasticitySystem on a DistributedCutMesh, with Trilinos matrices and vectors
     * (doc/parallel.md says why Trilinos).
     *
     * Unknowns: the displacement dofs of the distributed DoFHandler (locally owned and relevant
     * as in step-40), then dim multiplier components per fracture face, face f at
     * n_u + dim f + i in a (u, lambda) step vector and at dim f + i in a multiplier vector. The
     * multipliers of a face are owned by the face's owner (the owner of its plus-side cell).
     *
     * Assembled once: the elasticity matrix K unconstrained (residuals) and with the homogeneous
     * constraints (Jacobians), the load f, and the coupling int_sigma lambda . [v] as matrices B
     * (multiplier rows, displacement columns; jumps [u]_sigma = (B u)_sigma / |sigma|) and, with
     * the columns of constrained dofs dropped, B_0 and B_0^T (the Jacobian's coupling blocks).
     * Each side of a fracture face is computed by the owner of its cell and sent to the rows'
     * owners by the matrices' compress(): the two cells of a face need not be on one process.
     *
     * The poromechanical loads of eq. (11b) are assembled on owned cells
     * (set_equivalent_pressures); the cell divergences and energies the coupling reads are the
     * serial ElasticitySystem's, on the state gathered from this one.
     */
    template <int dim>
    class DistributedElasticitySystem
    {
    public:
      DistributedElasticitySystem(const geometry::DistributedCutMesh<dim> &mesh,
                                  const ContactParameters                 &parameters,
                                  TimerOutput                             &timer);

      /// Dofs, constraints, matrices and loads. Collective; input errors are thrown on every
      /// process.
      void
      setup();

      types::global_dof_index
      n_displacement_dofs() const
      {
        return dof_handler.n_dofs();
      }
      types::global_dof_index
      n_dofs() const
      {
        return dof_handler.n_dofs() + dim * n_faces();
      }

      const geometry::CutMesh<dim> &
      get_mesh() const
      {
        return mesh.serial;
      }
      const geometry::DistributedCutMesh<dim> &
      get_distributed_mesh() const
      {
        return mesh;
      }
      MPI_Comm
      get_communicator() const
      {
        return mesh.get_communicator();
      }
      const FESystem<dim> &
      get_fe() const
      {
        return fe;
      }
      const DoFHandler<dim> &
      get_dof_handler() const
      {
        return dof_handler;
      }
      const AffineConstraints<double> &
      get_homogeneous_constraints() const
      {
        return constraints_hom;
      }
      /// Locally owned and relevant displacement dofs, owned multipliers (dim f + i of owned
      /// faces), and the owned entries of a (u, lambda) step vector.
      const IndexSet &
      owned_displacements() const
      {
        return owned_u;
      }
      const IndexSet &
      relevant_displacements() const
      {
        return relevant_u;
      }
      const IndexSet &
      owned_multipliers() const
      {
        return owned_lambda;
      }
      const IndexSet &
      owned_unknowns() const
      {
        return owned_all;
      }
      /// K with the homogeneous constraints (identity-like rows on constrained dofs).
      const TrilinosWrappers::SparseMatrix &
      get_constrained_matrix() const
      {
        return K_constrained;
      }
      /// B_0: rows dim f + i of the owned faces, columns the unconstrained displacement dofs.
      const TrilinosWrappers::SparseMatrix &
      get_free_coupling() const
      {
        return coupling_free;
      }
      /// B_0^T: rows the displacement dofs.
      const TrilinosWrappers::SparseMatrix &
      get_free_coupling_transpose() const
      {
        return coupling_free_T;
      }
      /// Weighted measure of an owned fracture face.
      double
      face_measure(const unsigned int f) const
      {
        return face_measures[f];
      }
      /// Local frame of face @p f, rows n+ then the tangent(s).
      Tensor<2, dim>
      frame(const unsigned int f) const;

      /// Poromechanical loads of eq. (11b) (see ElasticitySystem::set_equivalent_pressures):
      /// p_E per serial active cell index and per fracture face, given on every process.
      void
      set_equivalent_pressures(const std::vector<double> &p_E_matrix,
                               const std::vector<double> &p_E_fracture,
                               const double               biot);

      /// @name The interface of the contact iterations (see ElasticitySystem)
      /// @{
      using VectorType                                     = TrilinosWrappers::MPI::Vector;
      static constexpr const char *linear_solver_parameter = "Mechanics/Distributed linear solver";
      static std::string
      linear_solver_name(const ContactParameters &prm)
      {
        return prm.distributed_linear_solver;
      }
      unsigned int
      n_faces() const
      {
        return mesh.serial.fracture_faces.size();
      }
      bool
      owns_face(const unsigned int f) const
      {
        return mesh.owns_face(f);
      }
      /// Zero with the Dirichlet values, on the owned displacement dofs.
      void
      initial_displacement(VectorType &u) const;
      /// Face-mean jumps of the owned faces (other entries untouched).
      void
      face_jumps(const VectorType &u, std::vector<Tensor<1, dim>> &jumps) const;
      /// The jumps the contact conditions read on the owned faces: [u]_sigma - (S lambda)_sigma
      /// with the multiplier stabilization S (face_jumps when it is off).
      void
      contact_jumps(const VectorType            &u,
                    const VectorType            &lambda,
                    std::vector<Tensor<1, dim>> &jumps) const;
      /// The multiplier stabilization S (empty when Mechanics/Multiplier stabilization = 0).
      const MultiplierStabilization &
      get_multiplier_stabilization() const
      {
        return stabilization;
      }
      /// 1/2 a(u, u), integrated cell by cell over the owned cells and summed over the
      /// processes (collective).
      double
      elastic_energy(const VectorType &u) const;
      /// This process's share of the squared norms of f - K u - B^T lambda and of f over the
      /// unconstrained dofs.
      std::pair<double, double>
      mechanical_residual_norms(const VectorType &u, const VectorType &lambda) const;
      /// The displacement rows of a step vector: f - K u - B^T lambda, zero on constrained dofs.
      void
      mechanical_rhs(const VectorType &u, const VectorType &lambda, VectorType &rhs) const;
      types::global_dof_index
      multiplier_index(const unsigned int f, const unsigned int i) const
      {
        return dof_handler.n_dofs() + dim * f + i;
      }
      void
      reinit_multipliers(VectorType &lambda) const
      {
        lambda.reinit(owned_lambda, get_communicator());
      }
      void
      reinit_step(VectorType &x) const
      {
        x.reinit(owned_all, get_communicator());
      }
      void
      set_step(const VectorType &u_old,
               const VectorType &lambda_old,
               const VectorType &delta,
               const double      alpha,
               VectorType       &u,
               VectorType       &lambda) const;
      void
      sum_over_processes(std::vector<double> &values) const;
      bool
      all_processes(const bool value) const;
      /// @}

    private:
      void
      make_constraints();
      /// Patterns and values of the coupling matrices, and the face measures.
      void
      make_coupling();
      /// Whether @p cell has a dof constrained by the homogeneous constraints; its dofs go to
      /// @p local.
      bool
      has_constrained_dofs(const typename DoFHandler<dim>::active_cell_iterator &cell,
                           std::vector<types::global_dof_index>                 &local) const;
      /// K_constrained, K_boundary, f, and the fracture-pressure loads.
      void
      assemble();
      /// f - K u - B^T lambda on the owned displacement dofs (constrained rows not zeroed).
      void
      residual(const VectorType &u, const VectorType &lambda, VectorType &r) const;

      const geometry::DistributedCutMesh<dim> &mesh;
      const ContactParameters                 &prm;
      TimerOutput                             &timer;

      FESystem<dim>           fe;
      DoFHandler<dim>         dof_handler;
      IndexSet                owned_u, relevant_u, owned_lambda, owned_all;
      MultiplierStabilization stabilization;
      /// Scratch of contact_jumps: the owned multipliers and those of the owned faces'
      /// neighbours through S (ghosts), kept to allocate its ghost exchange once.
      mutable VectorType        neighbour_lambda;
      AffineConstraints<double> constraints, constraints_hom;

      /// K with the homogeneous constraints applied, and K - K_constrained (nonzero only on the
      /// cells with constrained dofs): K u = K_constrained u + K_boundary u on the unconstrained
      /// rows, without a second copy of K. Not on the constrained rows: the diagonal entries
      /// the constraints put there do not cancel, so u^T K u cannot be formed from the two.
      TrilinosWrappers::SparseMatrix K_constrained, K_boundary;
      TrilinosWrappers::SparseMatrix coupling, coupling_free, coupling_free_T;
      VectorType                     f;
      VectorType                     f_fixed; ///< f without the poromechanical loads
      std::vector<double>            face_measures;
      /// int div phi_i over an owned cell, per dof with a nonzero integral (the Biot load).
      struct CellDivergence
      {
        unsigned int                                            cell; ///< serial index
        std::vector<std::pair<types::global_dof_index, double>> entries;
      };
      std::vector<CellDivergence> divergence;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
