// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_PARAMETERS_H
#define POROFRAC_MECHANICS_PARAMETERS_H

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <porofrac/mechanics/friction_law.h>

#include <map>
#include <memory>
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

    /// What a contact-mechanics scene reports beyond the solution (subsection Mechanics).
    struct ContactReports
    {
      /// Time one linear elasticity solve (all fractures open) on the same mesh.
      bool linear_solve_time = false;
      /// Write fracture_p2.csv, the paper's P2 reconstructions on the fractures (2D).
      bool p2_reconstruction = false;
      /// Solve again for every method x c x initial guess (paper Tables 1-4).
      bool iteration_table = false;
      /// Print the range of each stress component at the cell centroids.
      bool stress_range = false;
      /// "none", "single fracture" (paper Section 5.2.1) or "penny crack" (3D) and the data.
      std::string analytical_solution  = "none";
      double      remote_stress        = 1e8; ///< sigma (Pa)
      double      fracture_angle       = 20;  ///< psi (degrees)
      double      fracture_half_length = 1;   ///< l (m); penny crack: radius a
    };

    /**
     * Deck subsection "Mechanics": elasticity data, loads and boundary conditions, friction,
     * the contact method with its globalization and linear solver, and the reports of
     * contact-mechanics scenes. The member defaults equal the declared ones, for code that
     * fills the struct without a deck.
     */
    struct ContactParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Reads the subsection for a scene of dimension @p dim and validates it.
      void
      parse_parameters(const dealii::ParameterHandler &prm, const unsigned int dim);
      /// InputError naming the entry for every impossible value (also for structs filled by
      /// code).
      void
      validate(const unsigned int dim) const;

      /// Isotropic linear elasticity, plane strain in 2D (Pa, -).
      double young_modulus = 25e9;
      double poisson_ratio = 0.25;
      /// Axisymmetric mode (2D only): the mesh is the radial section, coordinate 0 = x (axis),
      /// coordinate 1 = r >= 0; hoop strain u_r / r and integrals weighted by 2 pi r.
      bool                     axisymmetric    = false;
      double                   pre_stress_hoop = 0; ///< sigma0_theta theta (Pa), axisymmetric
      std::vector<std::string> body_force;          ///< dim expressions (empty: zero)
      std::vector<double>      pre_stress;          ///< dim*dim row-major, constant (empty: 0)

      /// boundary id -> component -> muparser expression of x, y (, z)
      std::map<dealii::types::boundary_id, std::map<unsigned int, std::string>> dirichlet;
      std::map<dealii::types::boundary_id, std::map<unsigned int, std::string>> traction;
      std::map<dealii::types::boundary_id, std::string>                         pressure;
      /// Fluid pressure in the fractures: fracture id (numbers::invalid_unsigned_int: every
      /// fracture) -> expression of x, y (, z).
      std::map<unsigned int, std::string> fracture_pressure;
      std::vector<PointConstraint>        point_constraints;

      /// Coefficient field F0: fracture id -> expression of x, y (, z) and d; `friction_all`
      /// for fractures not listed.
      std::map<unsigned int, std::string> friction;
      std::string                         friction_all = "0";
      /// The friction law (FrictionLawRegistry) and its parsed entries; null: Coulomb.
      std::string                        friction_law_name = "coulomb";
      std::shared_ptr<const FrictionLaw> friction_law;

      /// The contact method (ContactMethodRegistry) and the complementarity parameter c of
      /// (25)-(26) (Pa/m); initial guess (stick: lambda_n = initial_lambda_n, else open).
      std::string  method           = "active set";
      double       c                = 1e9;
      bool         stick_guess      = true;
      double       initial_lambda_n = 100;
      unsigned int max_iterations   = 50;
      double       tolerance        = 1e-6;

      /// Globalization (all off by default: the paper's plain method). Backtracking line
      /// search on the merit max(scaled (25)-(26) residual, mechanical residual).
      bool         line_search          = false;
      unsigned int line_search_halvings = 6; ///< at most this many step halvings
      unsigned int line_search_memory   = 1; ///< 1: monotone; M: compare with the last M merits
      /// Switch the line search on only once the relative residual stops decreasing.
      bool line_search_on_stagnation = false;
      /// Active-set cycling safeguard: when the face states of an iterate repeat those of an
      /// earlier, non-consecutive iterate, the step is multiplied by this factor (0: off).
      double cycle_damping = 0;
      /// Continuation in c: start with this c (0: off) and move c towards the target by the
      /// factor below whenever the face states stop changing.
      double c_start             = 0;
      double continuation_factor = 100;

      /// Multiplier stabilization alpha (doc/algorithms.md §2.2; 0: off, the paper's method):
      /// the contact conditions read the jump [u]_sigma - sum_sigma' s (lambda_sigma -
      /// lambda_sigma') over the neighbours sigma' of sigma in its fracture, s = alpha h / E'.
      double multiplier_stabilization = 0;

      /// The linear solver of the contact iterations (ContactLinearSolverRegistry).
      std::string linear_solver = "full system";
      /// Full system: GMRES preconditioned by the last LU factors, at most this many
      /// iterations before refactorizing (0: factorize whenever a face row changed).
      unsigned int reuse_iterations = 0;
      /// The linear solver of distributed runs (DistributedContactLinearSolverRegistry).
      std::string distributed_linear_solver = "direct";
      /// Iterative linear solvers: relative residual min(linear_tolerance, linear_forcing *
      /// relative residual of the last contact iterate).
      double linear_tolerance = 1e-2;
      double linear_forcing   = 1e-1;
      /// Iterative linear solvers: at most this many Krylov iterations per solve (then the
      /// step is solved directly).
      unsigned int max_linear_iterations = 200;
      /// Iterative linear solver: smoothed-aggregation AMG, else the unsmoothed (tentative)
      /// prolongator.
      bool amg_smoothed_prolongator = true;
      /// Iterative linear solver: gamma in the multiplier block S~ = D - gamma W B_0 diag(K)^-1
      /// B_0^T of its preconditioner.
      double schur_scaling = 1;

      ContactReports reports;
    };

    /**
     * Parses "id: x=expr, y=expr; id: ..." into id -> component -> expression. Components are
     * named x, y, z. Errors name @p parameter.
     */
    std::map<dealii::types::boundary_id, std::map<unsigned int, std::string>>
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
