// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_ELASTICITY_SYSTEM_H
#define POROFRAC_MECHANICS_ELASTICITY_SYSTEM_H

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/mechanics/coupling_entry.h>
#include <porofrac/mechanics/multiplier_stabilization.h>
#include <porofrac/mechanics/parameters.h>

#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    /// The multiplier rows of the contact Jacobian, per fracture face: A_lambda R and A_jump R
    /// (the local rows of the contact method times the face frame R, i.e. in the global frame).
    template <int dim>
    struct FaceRows
    {
      std::vector<Tensor<2, dim>> lambda;
      std::vector<Tensor<2, dim>> jump;
    };

    /// What ElasticitySystem::setup() assembles:
    /// - state: dofs, constraints and B, enough to read a state computed elsewhere (jumps,
    ///   fields, reconstructions);
    /// - loads: also the loads and the per-cell divergences, what the poromechanical coupling
    ///   reads of a state computed by the distributed code (its elastic energy is then computed
    ///   cell by cell);
    /// - matrices: also the saddle-point pattern and K, what a solve needs.
    enum class SystemAssembly
    {
      state,
      loads,
      matrices
    };

    template <int dim>
    struct DeckLoads;

    /**
     * What the contact iterations (ContactSolver) need from a system, serial or distributed:
     * - VectorType: displacements, multipliers (dim per fracture face) and the (u, lambda)
     *   steps, whose multiplier entries have the indices multiplier_index(f, i);
     * - face data: owns_face (the faces whose rows this process computes), frame, face_measure,
     *   face_jumps;
     * - the mechanical residual f - K u - B^T lambda (mechanical_residual_norms,
     *   mechanical_rhs), the initial guess and the step update (set_step);
     * - sums and votes over the processes (sum_over_processes, all_processes), so that every
     *   process takes the same decisions.
     * ElasticitySystem is the serial model; DistributedElasticitySystem the distributed one.
     */
    /**
     * The linear part of the contact problem of paper eqs. (10)-(11b) on a cut mesh: P2
     * displacements (plane strain in 2D, axisymmetric on a radial section, 3D), one multiplier
     * lambda_sigma in R^dim per fracture face, and
     * - the constraints of the Dirichlet conditions and point constraints;
     * - the elasticity matrix K and the coupling B: int_sigma lambda . [v] ([v] = v+ - v-), with
     *   B^T = J^T M for the face-mean jump operator J of eq. (10) and the face measures M;
     * - the load vector: body force, tractions, pressures, pre-stress, and the equivalent
     *   pressures of eq. (11b) (set_equivalent_pressures);
     * - the weights of the integrals (2 pi r in axisymmetric mode).
     *
     * Unknowns of the saddle point: all displacement dofs, then dim multiplier components per
     * fracture face (global frame). This class holds what does not depend on the contact state:
     * the contact solvers add the face rows.
     */
    template <int dim>
    class ElasticitySystem
    {
    public:
      ElasticitySystem(const geometry::CutMesh<dim> &mesh,
                       const ContactParameters      &parameters,
                       TimerOutput                  &timer);

      /// Dofs, constraints, B and, as @p what says, the loads and K.
      void
      setup(SystemAssembly what = SystemAssembly::matrices);

      /// Whether setup() assembled the pattern and K.
      bool
      has_matrices() const
      {
        return matrices_assembled;
      }

      unsigned int
      n_displacement_dofs() const
      {
        return dof_handler.n_dofs();
      }
      /// Displacement dofs plus dim per fracture face.
      unsigned int
      n_dofs() const;

      const geometry::CutMesh<dim> &
      get_mesh() const
      {
        return mesh;
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
      /// Inhomogeneous constraints (for u) and homogeneous ones (for increments).
      const AffineConstraints<double> &
      get_constraints() const
      {
        return constraints;
      }
      const AffineConstraints<double> &
      get_homogeneous_constraints() const
      {
        return constraints_hom;
      }
      /// The pattern of the whole (u, lambda) Jacobian.
      const SparsityPattern &
      get_sparsity_pattern() const
      {
        return sparsity;
      }
      /// K with the homogeneous constraints applied, plus B^T: the displacement rows of the
      /// Jacobian, on the saddle-point pattern (its multiplier rows are zero).
      const SparseMatrix<double> &
      get_constrained_matrix() const
      {
        return base_matrix;
      }
      /// B per fracture face.
      const std::vector<std::vector<CouplingEntry>> &
      get_coupling() const
      {
        return coupling;
      }
      /// Weighted measure of fracture face f (int_sigma 2 pi r ds in axisymmetric mode).
      double
      face_measure(const unsigned int f) const
      {
        return face_measures[f];
      }
      const std::vector<double> &
      get_face_measures() const
      {
        return face_measures;
      }
      /// Weighted measure of active cell K (2 pi r dA in axisymmetric mode, else |K|).
      double
      cell_measure(const unsigned int K) const
      {
        return cell_measures[K];
      }
      /// Local frame of face f, rows n+ then the tangent(s) t (and n+ x t in 3D).
      Tensor<2, dim>
      frame(const unsigned int f) const;

      /**
       * Poromechanical loads of eq. (11b): the weak form gains - int_Omega b p_E,m div v +
       * int_Gamma p_E,f [v]_n, with @p p_E_matrix constant per active cell and @p p_E_fracture
       * constant per fracture face. Replaces the previous pressures.
       */
      void
      set_equivalent_pressures(const std::vector<double> &p_E_matrix,
                               const std::vector<double> &p_E_fracture,
                               const double               biot);
      /// The load vector f (fixed loads and p_E loads, unconstrained).
      const Vector<double> &
      load() const
      {
        return f;
      }
      /// The initial displacement: zero with the Dirichlet values.
      void
      initial_displacement(Vector<double> &u) const;

      /// K u, K unconstrained (needs setup() with the matrices).
      void
      apply_elasticity(const Vector<double> &u, Vector<double> &Ku) const;
      /// 1/2 u^T K u cell by cell, without K (setup() without the matrices).
      double
      elastic_energy_by_cells(const Vector<double> &u) const;
      /// y = J x for the Jacobian with face rows @p rows: K x_u + B^T x_lambda on the
      /// displacement rows (constrained rows as in the Jacobian), A_l R x_lambda + A_j R ([x_u]
      /// - S x_lambda) on the face rows (S: the multiplier stabilization).
      void
      apply_jacobian(const FaceRows<dim> &rows, const Vector<double> &x, Vector<double> &y) const;
      /// Face-mean jump [u]_sigma of eq. (10), global frame.
      Tensor<1, dim>
      jump(const Vector<double> &u, const unsigned int f) const;
      /// Per active cell: int_K div u / |K| (weighted, with the hoop term u_r / r in
      /// axisymmetric mode).
      std::vector<double>
      cell_divergence(const Vector<double> &u) const;
      /// 1/2 a(u, u).
      double
      elastic_energy(const Vector<double> &u) const;
      /// Work of the fixed loads (not the p_E loads) on u - @p u_old.
      double
      external_work(const Vector<double> &u, const Vector<double> &u_old) const;
      /// Cauchy stress C eps(u) + pre-stress at a point of a cell.
      SymmetricTensor<2, dim>
      stress(const Vector<double>                                 &u,
             const typename DoFHandler<dim>::active_cell_iterator &cell,
             const Point<dim>                                     &unit_point) const;


      /// @name The interface of the contact iterations (see FaceRows above)
      /// @{
      using VectorType = Vector<double>;
      /// The deck entry that chooses the linear solver (ContactLinearSolverRegistry<dim>).
      static constexpr const char *linear_solver_parameter = "Mechanics/Linear solver";
      static std::string
      linear_solver_name(const ContactParameters &prm)
      {
        return prm.linear_solver;
      }
      unsigned int
      n_faces() const
      {
        return coupling.size();
      }
      /// Every face is this process's.
      bool
      owns_face(const unsigned int) const
      {
        return true;
      }
      /// Face-mean jumps of every face.
      void
      face_jumps(const Vector<double> &u, std::vector<Tensor<1, dim>> &jumps) const;
      /// The jumps the contact conditions read: [u]_sigma - (S lambda)_sigma with the
      /// multiplier stabilization S (face_jumps when it is off).
      void
      contact_jumps(const Vector<double>        &u,
                    const Vector<double>        &lambda,
                    std::vector<Tensor<1, dim>> &jumps) const;
      /// The multiplier stabilization S (empty when Mechanics/Multiplier stabilization = 0).
      const MultiplierStabilization &
      get_multiplier_stabilization() const
      {
        return stabilization;
      }
      /// Squared norms of f - K u - B^T lambda and of f over the unconstrained dofs.
      std::pair<double, double>
      mechanical_residual_norms(const Vector<double> &u, const Vector<double> &lambda) const;
      /// The displacement rows of a (u, lambda) step vector: f - K u - B^T lambda, zero on
      /// constrained dofs.
      void
      mechanical_rhs(const Vector<double> &u,
                     const Vector<double> &lambda,
                     Vector<double>       &rhs) const;
      /// Index of multiplier component @p i of face @p f in a (u, lambda) step vector.
      types::global_dof_index
      multiplier_index(const unsigned int f, const unsigned int i) const
      {
        return dof_handler.n_dofs() + dim * f + i;
      }
      void
      reinit_multipliers(Vector<double> &lambda) const
      {
        lambda.reinit(dim * coupling.size());
      }
      void
      reinit_step(Vector<double> &x) const
      {
        x.reinit(n_dofs());
      }
      /// (u, lambda) = (u_old, lambda_old) + alpha delta.
      void
      set_step(const Vector<double> &u_old,
               const Vector<double> &lambda_old,
               const Vector<double> &delta,
               const double          alpha,
               Vector<double>       &u,
               Vector<double>       &lambda) const;
      /// One process: sums and votes are the values themselves.
      void
      sum_over_processes(std::vector<double> &) const
      {
      }
      bool
      all_processes(const bool value) const
      {
        return value;
      }
      /// @}

    private:
      void
      make_constraints();
      void
      make_coupling(DynamicSparsityPattern *dsp);
      void
      assemble();
      void
      add_coupling_to_matrix();
      /// Adds the load of Mechanics/Fracture pressure to f.
      void
      add_fracture_pressure(const DeckLoads<dim> &loads);

      const geometry::CutMesh<dim> &mesh;
      const ContactParameters      &prm;
      TimerOutput                  &timer;

      FESystem<dim>             fe;
      DoFHandler<dim>           dof_handler;
      AffineConstraints<double> constraints;
      AffineConstraints<double> constraints_hom;

      SparsityPattern                         sparsity;
      SparseMatrix<double>                    K_full;      ///< unconstrained elasticity (residuals)
      SparseMatrix<double>                    base_matrix; ///< constrained K + B^T
      bool                                    matrices_assembled = false;
      Vector<double>                          f;       ///< load vector: f_fixed + p_E loads
      Vector<double>                          f_fixed; ///< the deck's loads only
      std::vector<std::vector<CouplingEntry>> coupling;
      /// Per active cell: (dof, int_K div phi_dof) so that int_K div u = sum value * u(dof).
      std::vector<std::vector<std::pair<types::global_dof_index, double>>> divergence;
      std::vector<double>     cell_measures, face_measures;
      MultiplierStabilization stabilization;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
