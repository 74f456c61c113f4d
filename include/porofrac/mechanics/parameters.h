// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_PARAMETERS_H
#define POROFRAC_MECHANICS_PARAMETERS_H

#include <deal.II/base/types.h>

#include <porofrac/mechanics/contact_law.h>

#include <map>
#include <string>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /// A point constraint: fix components of u at the mesh vertices located at @p point.
    struct PointConstraint
    {
      std::vector<double>                 point;
      std::map<unsigned int, std::string> values; ///< component -> expression (constant)
    };

    /// Everything ContactProblem needs, independent of the deck.
    struct ContactParameters
    {
      double        young_modulus    = 1;
      double        poisson_ratio    = 0;
      ContactMethod method           = ContactMethod::active_set;
      double        c                = 1e9;
      bool          stick_guess      = true;
      double        initial_lambda_n = 100;
      unsigned int  max_iterations   = 50;
      double        tolerance        = 1e-6;
      /// boundary id -> component -> muparser expression of x, y (, z)
      std::map<types::boundary_id, std::map<unsigned int, std::string>> dirichlet;
      std::map<types::boundary_id, std::map<unsigned int, std::string>> traction;
      std::map<types::boundary_id, std::string>                         pressure;
      std::vector<PointConstraint>                                      point_constraints;
      /// fracture id -> expression of x, y (, z) and d; `all` used for fractures not listed.
      std::map<unsigned int, std::string> friction;
      std::string                         friction_all = "0";
      std::vector<std::string>            body_force; ///< dim expressions (empty: zero)
      std::vector<double>                 pre_stress; ///< dim*dim row-major, constant (empty: 0)
      /// Axisymmetric mode (2D only): the mesh is the radial section, coordinate 0 = x (axis),
      /// coordinate 1 = r >= 0; hoop strain u_r / r and integrals weighted by 2 pi r.
      bool   axisymmetric    = false;
      double pre_stress_hoop = 0; ///< sigma0_theta theta (Pa), axisymmetric mode only

      /// Globalization of the contact iterations (all off by default: the paper's plain method).
      /// Backtracking line search on the merit max(scaled (25)-(26) residual, mechanical residual).
      bool         line_search          = false;
      unsigned int line_search_halvings = 6; ///< at most this many step halvings
      unsigned int line_search_memory   = 1; ///< 1: monotone; M: compare with the last M merits
      /// Switch the line search on only once the relative residual stops decreasing.
      bool line_search_on_stagnation = false;
      /// Active-set cycling safeguard: when the face states of an iterate repeat those of an
      /// earlier, non-consecutive iterate, the step is multiplied by this factor (0: off).
      double cycle_damping = 0;
      /// Continuation in c (eqs. (25)-(26)): start with this c (0: off) and move c towards the
      /// target by the factor below whenever the face states stop changing.
      double c_start             = 0;
      double continuation_factor = 100;
      /// Reuse of the LU factors: GMRES preconditioned by the last factorization, at most this
      /// many iterations before refactorizing (0: factorize every iteration).
      unsigned int reuse_iterations = 0;
      /// Linear solves of the contact iterations: UMFPACK on the whole (u, lambda) system, or
      /// the Schur complement on the multipliers with one Cholesky factorization of K.
      bool schur_complement = false;
      /// Measure one linear elasticity solve (all fractures open) on the same mesh.
      bool time_linear_solve = false;
    };

    /**
     * Parses "id: x=expr, y=expr; id: ..." into id -> component -> expression. Components are
     * named x, y, z. Errors name @p parameter.
     */
    std::map<types::boundary_id, std::map<unsigned int, std::string>>
    parse_component_map(const std::string &text,
                        const unsigned int dim,
                        const std::string &parameter);

    /// Parses "id: expr; id: expr" (or one expression for all, key numbers::invalid_unsigned_int).
    std::map<unsigned int, std::string>
    parse_scalar_map(const std::string &text, const std::string &parameter);

    /// Parses "(px, py): x=v, y=v; (px, py): ..." into point constraints.
    std::vector<PointConstraint>
    parse_point_constraints(const std::string &text,
                            const unsigned int dim,
                            const std::string &parameter);
  } // namespace mechanics
} // namespace porofrac

#endif
