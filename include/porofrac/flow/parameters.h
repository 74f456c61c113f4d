// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_PARAMETERS_H
#define POROFRAC_FLOW_PARAMETERS_H

#include <deal.II/base/types.h>

#include <porofrac/base/amg_preconditioner.h>
#include <porofrac/flow/rock_type.h>

#include <array>
#include <map>
#include <memory>
#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace porofrac
{
  namespace flow
  {
    /// Stopping rules and safeguards of the flow Newton method (doc/flow.md).
    struct NewtonParameters
    {
      unsigned int max_iterations = 50;
      /// Stop when ||R||_2 / ||R_0||_2 < residual_tolerance ...
      double residual_tolerance = 1e-5;
      /// ... or max |delta p| / max |p| < update_tolerance ...
      double update_tolerance = 1e-4;
      /// ... and, in both cases, the relative mass defect of each phase < mass_tolerance.
      double mass_tolerance = 1e-11;
      /// Largest change of a node's capillary pressure per iteration, in units of the pressure
      /// scale of its rock's saturation law (SaturationLaw::pressure_scale()); 0 = no limit.
      double capillary_chop = 1.;
      /// Largest change of a node's non-wetting saturation per iteration (Appleyard chop); at
      /// interface nodes under both the matrix and the fracture law. 0 = no limit.
      double saturation_chop = 0.;
      /// Jacobian only: use the entry slope S'(p_e+) instead of 0 where p_c <= p_e, the entry
      /// pressure of the law (inexact Newton across the kink of S). false = exact Jacobian.
      bool entry_slope = true;
      /// Number of Newton iterations per step that use the entry slope.
      unsigned int entry_slope_iterations = 1000;
      /// Give up (so that the caller cuts the time step) after this many iterations in which
      /// neither the residual nor the mass defect fell below half its best value; 0 = never.
      unsigned int stagnation_iterations = 10;
      /// If positive, a stagnated solve whose last normalized update is below this value and
      /// whose mass defect meets mass_tolerance counts as converged (inner solves of a coupling
      /// loop ask for tighter tolerances than Newton's noise floor allows).
      double stagnation_update_tolerance = 0.;
      /// Mass-defect bound of that fallback (0: mass_tolerance).
      double stagnation_mass_tolerance = 0.;
      /// A node leaving the two-phase region (p_c > p_e to p_c < p_e) stops at p_c = p_e first.
      bool kink_stop = true;
      /// Keep p_c >= p_e at every node (projection after each update; the Jacobian uses S'(p_e+)
      /// at the bound). S = 0 for p_c <= p_e, so with no non-wetting mobility floor the bound
      /// does not change the solution: it removes the non-wetting pressure of a saturated node,
      /// which no equation determines, from the Newton iteration.
      bool capillary_bound = false;
      /// Backtracking: halve the update (at most line_search_steps times) while |R| grows.
      bool         line_search       = false;
      unsigned int line_search_steps = 4;
      /// Registered name of the linear solver of the Newton steps (SerialLinearSolverRegistry).
      std::string linear_solver = "umfpack";
      /// Registered name of the solver of the distributed Newton systems
      /// (DistributedLinearSolverRegistry).
      std::string distributed_linear_solver = "mumps";
      /// Iterative linear solvers: relative residual min(linear_tolerance, linear_forcing
      /// |R|/|R_0|), at least 1e-12 (direct solvers ignore it).
      double linear_tolerance = 1e-4;
      double linear_forcing   = 1;
      /// Krylov iterations before an iterative solver hands the system to MUMPS.
      unsigned int max_linear_iterations = 200;
      /// The AMG of cpr-gmres and amg-gmres: aggregation threshold and scheme.
      AmgSettings amg;
    };

    /// Time stepping: dt_{k+1/2} = min(rho dt_{k-1/2}, dt_max), halved after a failed step.
    struct TimeStepping
    {
      double       final_time   = 1;
      double       initial_step = 0.01;
      double       maximum_step = 1e100;
      double       growth       = 1.1; ///< rho
      unsigned int maximum_cuts = 20;
      unsigned int output_every = 1;
      /// Steps the rule may take to the final time (without cuts) before the deck is refused.
      unsigned int maximum_steps = 100000;
    };

    /// Dirichlet phase pressures (p^w, p^nw) in Pa by boundary id.
    using DirichletData = std::map<dealii::types::boundary_id, std::array<double, 2>>;
    /// Inflow of each phase through the faces of one boundary id: per face area (m/s), or with
    /// `total` the whole rate (m^3/s), spread over the faces in proportion to their area.
    struct BoundaryFlux
    {
      std::array<double, 2> rate{{0., 0.}};
      bool                  total = false;
    };
    using FluxData = std::map<dealii::types::boundary_id, BoundaryFlux>;
    /// Inflow (q^w, q^nw) per face area in m/s by boundary id.
    using FaceFlux = std::map<dealii::types::boundary_id, std::array<double, 2>>;

    /**
     * The deck's "Flow" subsection: the two rock types (sub-subsections Matrix and Fracture,
     * where the registered saturation and relative permeability laws declare their own entries),
     * the initial state, the boundary conditions, the Newton method and the time stepping. The
     * member defaults equal the declared ones (the laws excepted: parse_parameters() builds them).
     */
    struct FlowParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Reads the subsection, builds the laws and the boundary data and calls validate().
      void
      parse_parameters(const dealii::ParameterHandler &prm);
      /// InputError naming the first parameter with an impossible value. Checks that need the
      /// mesh (boundary ids, source expressions) are made by make_flow_model.
      void
      validate() const;

      /// Weight volumes and face measures by 2 pi r, r = the second coordinate.
      bool axisymmetric = false;
      /// Laws, viscosities and mobility floors of the matrix and of the fracture (index Rock).
      std::array<RockType, 2> rocks;
      /// Initial (p^w, p^nw) of matrix cells (and interfaces) and of fracture nodes (Pa).
      std::array<std::array<double, 2>, 2> initial_pressure{{{{4e6, 4e6}}, {{1e5, 1e5}}}};
      double                               porosity     = 0.15;  ///< phi_0 (-)
      double                               permeability = 5e-20; ///< K_0 (m^2)
      /// Matrix permeability as an expression of x, y (, z) at cell centroids; empty: K_0.
      std::string permeability_expression;
      /// Matrix sources h^w, h^nw (1/s): muparser expressions of x, y (, z).
      std::array<std::string, 2> source{{"0", "0"}};
      double                     aperture                = 1e-3; ///< d_0 (m)
      double                     normal_transmissibility = 1e-9; ///< Lambda_f of eq. (3) (m)
      double                     damaged_layer_thickness = 0;    ///< d_a (m)
      double                     damaged_layer_porosity  = 0;    ///< phi_a (-)
      DirichletData              matrix_dirichlet;
      DirichletData              fracture_dirichlet;
      /// Neumann inflow through matrix boundary faces (ids without a Dirichlet condition).
      FluxData matrix_flux;
      /// auto | circumcentre | centroid (TpfaGrid::Centres; auto: circumcentres in 2D only).
      std::string cell_centres = "auto";
      /// "name: (x, y, z) (x, y, z) [n]; ..." (parse_sample_lines), written at the end.
      std::string sample_lines;
      /// Pressures are stored relative to this value (Pa).
      double           reference_pressure = 0;
      NewtonParameters newton;
      TimeStepping     stepping;
    };

    /**
     * Parses "id: p_w = v, p_nw = v; id: s_nw = v, p_nw = v; ..." (two of p_w, p_nw, s_nw, s_w
     * per id) into phase pressures, a saturation converted with the saturation law of @p rock.
     * Errors name @p parameter.
     */
    DirichletData
    parse_dirichlet(const std::string &text, const RockType &rock, const std::string &parameter);

    /// Parses "id: q_w = v, q_nw = v; ..." (per area) or "id: Q_w = v, Q_nw = v" (total rates),
    /// a missing phase 0; errors name @p parameter.
    FluxData
    parse_flux(const std::string &text, const std::string &parameter);

    /**
     * A law built outside a deck (programs, tests): the registered law @p name with the entries
     * @p values (entry name -> value, the others at their declared defaults) of rock subsection
     * Flow/Matrix or Flow/Fracture (@p rock); errors name "Flow/<rock>/<entry>".
     */
    std::shared_ptr<const SaturationLaw>
    make_saturation_law(const std::string                        &name,
                        const std::map<std::string, std::string> &values = {},
                        const Rock                                rock   = matrix_rock);
    std::shared_ptr<const RelativePermeability>
    make_relative_permeability(const std::string                        &name,
                               const std::map<std::string, std::string> &values = {},
                               const Rock                                rock   = matrix_rock);
  } // namespace flow
} // namespace porofrac

#endif
