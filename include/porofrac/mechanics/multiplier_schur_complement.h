// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_MULTIPLIER_SCHUR_COMPLEMENT_H
#define POROFRAC_MECHANICS_MULTIPLIER_SCHUR_COMPLEMENT_H

#include <deal.II/base/tensor.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <porofrac/mechanics/coupling_entry.h>
#include <porofrac/mechanics/multiplier_stabilization.h>
#include <porofrac/mechanics/sparse_cholesky.h>

#include <memory>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    /**
     * Linear solves of the contact iterations through the Schur complement on the multipliers.
     * The Jacobian of (27) with the face rows of doc/algorithms.md §2-§3 reads
     *
     *   [ K       B^T ] [du]   [r_u]        K: constrained elasticity (constant),
     *   [ A_j J   A_l ] [dl] = [r_l],       B^T: coupling, B^T = J^T M (M = face measures),
     *
     * with J the face-mean jump operator [u]_sigma of eq. (10) and A_l, A_j the dim x dim face
     * rows (global frame). K = P^T L L^T P is factorized once (Cholesky) and W = J K^{-1} B^T
     * (dim n_faces square, dense) is formed once from the sparse Y = L^{-1} P J^T, which is kept.
     * Each iteration then solves the small dense system (A_l - A_j W) dl = r_l - A_j Y^T z with
     * z = L^{-1} P r_u (LU, reused while the face rows do not change) and recovers
     * du = P^T L^{-T} (z - Y M dl): one sparse triangular solve pair per iteration, instead of
     * a sparse LU of the whole system.
     *
     * Face rows without a jump term (A_j row zero: every row of an open face, the tangential
     * row of a slipping face in the active-set method) do not involve W: they only tie the
     * face's own multiplier, E_f dl_f = e_f. They are eliminated before the LU: dl_f =
     * E_f^+ e_f + N_f t_f with N_f a basis of the null space of E_f, and the dense LU is done on
     * the remaining rows for t only (5.2.2 level 4, active set: 3,635 of 5,376 rows).
     */
    template <int dim>
    class MultiplierSchurComplement
    {
    public:
      /**
       * Factorizes the leading n_u block of @p base_matrix and forms W. Coupling entries on
       * constrained dofs (@p constrained) are left out, as in the full system. With a
       * multiplier stabilization S the face rows read A_l dl + A_j ([du] - S dl), so W + S
       * takes the place of W throughout.
       */
      MultiplierSchurComplement(const SparseMatrix<double>                    &base_matrix,
                                const unsigned int                             n_u,
                                const std::vector<std::vector<CouplingEntry>> &coupling,
                                const std::vector<double>                     &face_measures,
                                const std::vector<bool>                       &constrained,
                                const MultiplierStabilization                 &stabilization);

      /// Sets the face rows A_l R, A_j R; refactorizes the dense Schur complement only if they
      /// changed. Returns true when the previous LU factors were reused.
      bool
      set_rows(const std::vector<Tensor<2, dim>> &AlR, const std::vector<Tensor<2, dim>> &AjR);

      /// Forgets the face rows and the dense LU factors (the next set_rows() refactorizes);
      /// K, its Cholesky factors and W are kept.
      void
      clear_rows();

      /// Solves the Jacobian system for @p rhs = (r_u, r_l) (r_u zero on constrained dofs).
      void
      solve(const Vector<double> &rhs, Vector<double> &solution) const;

      /// Wall times (s): Cholesky factorization, forming W, dense LU factorizations so far, and
      /// the sparse triangular solves of solve().
      double         time_cholesky = 0, time_form_W = 0, time_dense_lu = 0;
      mutable double time_solves            = 0;
      unsigned int   n_dense_factorizations = 0;
      /// Nonzeros of Y = L^{-1} P J^T (sum of the reaches of the fracture-face columns).
      std::size_t reach_entries = 0;

      const SparseCholesky &
      cholesky() const
      {
        return K;
      }

    private:
      /**
       * Throws InsufficientMemory if what is still to be allocated needs more memory than this
       * run has (available_memory_mb()), counted once per process that holds a copy
       * (ReplicatedSerialSolves): the dense matrices (at least three of order dim x faces), with
       * the Cholesky factor of K (@p factor_mb, before its numeric factorization; 0 before its
       * symbolic analysis and once it is held) and Y = L^{-1} P J^T (@p solves_mb, before W is
       * formed; 0 before).
       */
      void
      check_memory(double factor_mb, double solves_mb) const;

      const unsigned int                      n_u, n_f;
      std::vector<std::vector<CouplingEntry>> entries; ///< unconstrained coupling entries
      std::vector<double>                     measures;
      SparseCholesky                          K;
      FullMatrix<double>                      W; ///< J K^{-1} B^T + S
      std::vector<Tensor<2, dim>>             rows_l, rows_j;
      /// Per face: rows with a jump term (kept in the dense system) and without (eliminated),
      /// E_f^+ (dim x free rows), the null-space basis N_f of E_f (dim x kept rows), and the
      /// offset of the face's kept rows / reduced unknowns t_f in the dense system.
      std::vector<std::vector<unsigned int>> kept_rows, free_rows;
      std::vector<FullMatrix<double>>        pseudo_inverse, null_basis;
      std::vector<unsigned int>              offset;
      /// LU factors of the equilibrated reduced Schur complement (A_l - A_j W) N on kept rows.
      LAPACKFullMatrix<double> S;
      std::vector<double>      row_scale;
      bool                     factorized = false;
      /// Orthonormal bases of the right and left null spaces of a numerically singular S
      /// (empty when S is regular).
      std::vector<Vector<double>> null_right, null_left;
      /// Numerical rank when S had an exactly zero pivot and holds its SVD instead (0: LU).
      unsigned int svd_rank = 0;

      /// Forms the per-face splitting and the equilibrated S of rows_l, rows_j.
      void
      assemble_reduced();
      /// @p n null vectors of the LU-factorized S (of S^T if @p transposed).
      std::vector<Vector<double>>
      null_space(const unsigned int n, const bool transposed) const;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
