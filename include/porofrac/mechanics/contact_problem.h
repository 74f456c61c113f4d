// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_CONTACT_PROBLEM_H
#define POROFRAC_MECHANICS_CONTACT_PROBLEM_H

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <porofrac/base/sparse_lu.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/mechanics/contact_law.h>
#include <porofrac/mechanics/multiplier_schur_complement.h>
#include <porofrac/mechanics/parameters.h>

#include <memory>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    /**
     * Linear elasticity (P2 simplices, plane strain in 2D) on a cut mesh with one multiplier
     * lambda_sigma in R^dim per fracture face (paper eq. (10)) and Coulomb friction through the
     * complementarity functions (25)-(26). Unknowns: all displacement dofs, then dim multiplier
     * components per fracture face (global frame), in one sparse matrix solved by UMFPACK.
     */
    template <int dim>
    class ContactProblem
    {
    public:
      ContactProblem(const geometry::CutMesh<dim> &mesh,
                     const ContactParameters      &parameters,
                     ConditionalOStream           &progress,
                     TimerOutput                  &timer);

      /// Dofs, constraints, elasticity block (assembled once), coupling block.
      void
      setup();

      /**
       * Runs the contact iterations; throws SolverFailure after max_iterations. With
       * @p warm_start (and a previous solve), starts from the current (u, lambda) instead of
       * the deck's initial guess. At least one iteration is always done, so that small load
       * changes (finite differences of a coupled map) are resolved exactly; with an unchanged
       * active set it costs one solve with the stored factorization.
       */
      void
      solve(const bool warm_start = false);

      /**
       * Forgets the previous solve: the next solve() starts from the deck's initial guess (even
       * when warm-started) and refactorizes every matrix that depends on face rows (the LU of
       * the full system, the dense LU of the Schur complement). What depends on the mesh only
       * (K, its Cholesky factors, W = J K^{-1} B^T, the loads) is kept.
       */
      void
      reset();

      /**
       * Changes the contact method, c and initial guess of the next solve() and calls reset(),
       * so that the next solve() is a cold start identical to that of a fresh ContactProblem
       * with these parameters (the iteration tables of paper Tables 1-4 in one process).
       */
      void
      set_contact_solver(const ContactMethod method, const double c, const bool stick_guess);

      /**
       * Poromechanical loads of paper eq. (11b): the weak form gains - int_Omega b p_E,m div v
       * + int_Gamma p_E,f [v]_n, with @p p_E_matrix constant per active cell (index
       * active_cell_index()) and @p p_E_fracture constant per fracture face (CutMesh index).
       * Only the load vector changes (no reassembly); calling it again replaces the previous
       * pressures.
       */
      void
      set_equivalent_pressures(const std::vector<double> &p_E_matrix,
                               const std::vector<double> &p_E_fracture,
                               const double               biot);

      /// Per active cell: the mean over the cell of div u (weighted by 2 pi r in axisymmetric
      /// mode, where div u = d_x u_x + d_r u_r + u_r / r), i.e. int_K div u / |K|.
      std::vector<double>
      cell_divergence() const;
      /// Weighted measure of active cell K (2 pi r dA in axisymmetric mode, else |K|).
      double
      cell_measure(const unsigned int K) const
      {
        return cell_measures[K];
      }
      /// Weighted measure of fracture face f (int_sigma 2 pi r ds in axisymmetric mode).
      double
      face_measure(const unsigned int f) const
      {
        return face_measures[f];
      }
      /// [u]_n = n+ . [u]_sigma of face f (<= 0 when admissible; d_f = d_0 - [u]_n).
      double
      normal_jump(const unsigned int f) const;
      /// 1/2 a(u, u), the elastic energy of the current displacement (J).
      double
      elastic_energy() const;
      /// Work of the fixed loads (body force, tractions, pressures, pre-stress; not the
      /// p_E loads) on u - @p u_old.
      double
      external_work(const Vector<double> &u_old) const;

      unsigned int
      n_dofs() const;
      unsigned int
      n_displacement_dofs() const
      {
        return dof_handler.n_dofs();
      }

      /// Face-averaged jump [u]_sigma and multiplier of face @p f, in the global frame.
      Tensor<1, dim>
      jump(const unsigned int f) const;
      Tensor<1, dim>
      multiplier(const unsigned int f) const;
      /// Local frame rows: n+, then tangent(s).
      Tensor<2, dim>
      frame(const unsigned int f) const;
      double
      friction(const unsigned int f) const
      {
        return friction_values[f];
      }
      FaceState
      state(const unsigned int f) const;

      /// Factorizes and solves the system with every fracture open (lambda = 0): the cost of one
      /// linear elasticity solve on this mesh, in seconds (wall clock). Leaves u, lambda untouched.
      double
      time_linear_solve() const;
      /// The same linear elasticity solve with the sparse Cholesky factorization of the
      /// elasticity block that `Linear solver = schur complement` uses (factorization + solve).
      double
      time_linear_solve_cholesky() const;

      unsigned int        iterations = 0;
      bool                converged  = false;
      std::vector<double> residual_history;
      /// Diagnostic: |G(x_k)| / |G(x_0)| with G of eq. (27) unscaled (mechanical rows in N,
      /// C_n in Pa, C_tau in Pa^2), x_0 the initial guess: one reading of the paper's 'relative
      /// residual' (not used for stopping).
      std::vector<double> initial_relative_history;
      /// Step lengths taken (1 = full step), line-search backtracks, detected active-set cycles.
      std::vector<double> step_history;
      unsigned int        backtracks      = 0;
      unsigned int        cycles_detected = 0;
      /// LU factorizations, and linear solves done by GMRES on the previous LU factors.
      unsigned int factorizations = 0, reused_factorizations = 0;
      /// Wall time (s) spent in solve() on: contact rows, factorization, triangular solves,
      /// residual / line-search evaluations.
      double time_contact_rows = 0, time_factorization = 0, time_solves = 0, time_residuals = 0;
      /// Schur complement path (Linear solver = schur complement): Cholesky factorization of the
      /// elasticity block and forming W = J K^{-1} B^T, once per setup() (0 when reused).
      double time_cholesky = 0, time_form_W = 0;

      const DoFHandler<dim> &
      get_dof_handler() const
      {
        return dof_handler;
      }
      const Vector<double> &
      displacement() const
      {
        return u;
      }
      const geometry::CutMesh<dim> &
      get_mesh() const
      {
        return mesh;
      }

      /// Cauchy stress at a point of a cell (for tests): C eps(u) + pre-stress.
      SymmetricTensor<2, dim>
      stress(const typename DoFHandler<dim>::active_cell_iterator &cell,
             const Point<dim>                                     &unit_point) const;

      /// True when the Schur complement solver was asked for but the elasticity block alone
      /// is singular, so that the full system is solved.
      bool
      schur_complement_unavailable() const
      {
        return schur_unavailable;
      }

    private:
      void
      make_constraints();
      void
      assemble_elasticity();
      void
      assemble_coupling();
      /// Squared, |sigma|-weighted norms at the current iterate with parameter @p c: scaled
      /// complementarity residual (25)-(26), multipliers, c [u]; mechanical residual and load.
      struct ResidualParts
      {
        double contact = 0, lambda = 0, c_jump = 0, mechanical = 0, load = 0;
        /// |sigma|-weighted squared norm of the unscaled (25)-(26) (C_tau in Pa^2).
        double contact_unscaled = 0;
      };
      ResidualParts
      residual_parts(const double c) const;
      /// Scaled contact residual (stress units) and mechanical residual, relative.
      double
      relative_residual() const;
      /// Line-search merit: like relative_residual() but with a given multiplier scale.
      static double
      merit(const ResidualParts &r, const double scale2);
      /// r = K u (unconstrained elasticity operator).
      void
      apply_elasticity(Vector<double> &r) const;

      const geometry::CutMesh<dim> &mesh;
      ContactParameters             prm; ///< only the contact solver may change
      ConditionalOStream           &progress;
      TimerOutput                  &timer;

      FESystem<dim>             fe;
      DoFHandler<dim>           dof_handler;
      AffineConstraints<double> constraints;     ///< inhomogeneous, for u
      AffineConstraints<double> constraints_hom; ///< homogeneous, for increments

      SparsityPattern      sparsity;
      SparseMatrix<double> K_full;      ///< unconstrained elasticity (residuals)
      SparseMatrix<double> base_matrix; ///< constrained K + B^T
      SparseMatrix<double> system_matrix;
      Vector<double>       f;       ///< load vector (unconstrained): f_fixed + p_E loads
      Vector<double>       f_fixed; ///< the deck's loads only
      /// Per active cell: (dof, int_K div phi_dof) so that int_K div u = sum value * u(dof).
      std::vector<std::vector<std::pair<types::global_dof_index, double>>> divergence;
      std::vector<double> cell_measures, face_measures;
      bool                solved_once = false;
      /// The last LU factorization of the contact Jacobian and the face rows it was built with.
      std::unique_ptr<SparseLU>   factorization;
      std::vector<Tensor<2, dim>> factorized_AlR, factorized_AjR;
      /// Schur complement on the multipliers (built at the first solve(), kept while K is).
      /// y = J x for the linearization of solve() with face rows AlR, AjR (Schur refinement).
      void
      apply_linearization(const std::vector<Tensor<2, dim>> &AlR,
                          const std::vector<Tensor<2, dim>> &AjR,
                          const Vector<double>              &x,
                          Vector<double>                    &y) const;
      std::unique_ptr<MultiplierSchurComplement<dim>> schur;
      /// The elasticity block is singular (Cholesky failed): the full system is solved.
      bool schur_unavailable = false;

    public:
      /// LU factorizations computed so far (each solve() reuses the last one while no face row
      /// of the Jacobian changes).
      unsigned int   n_factorizations = 0;
      Vector<double> u;      ///< displacement
      Vector<double> lambda; ///< dim per face

      /// B: for face f, entries (dof, component, +-int_sigma phi) so that int [u] = sum.
      using CouplingEntry = mechanics::CouplingEntry;
      std::vector<std::vector<CouplingEntry>> coupling;
      std::vector<double>                     friction_values;
      double                                  lambda_scale = 1;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
