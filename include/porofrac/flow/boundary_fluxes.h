// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_BOUNDARY_FLUXES_H
#define POROFRAC_FLOW_BOUNDARY_FLUXES_H

#include <porofrac/flow/parameters.h>
#include <porofrac/flow/two_phase_solver.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/json.h>

#include <map>
#include <ostream>

namespace porofrac
{
  namespace flow
  {
    /// What crosses one outer boundary id (boundary_balances()).
    struct BoundaryBalance
    {
      /// Outflow of each phase (m^3/s, positive out of the domain).
      std::array<double, 2> outflow{{0., 0.}};
      /// Matrix face area (weighted by 2 pi r if axisymmetric).
      double area = 0;
      /// Area-weighted mean wetting pressure on the matrix faces (Pa).
      double mean_pressure_w = 0;
    };

    /**
     * Per outer boundary id with a Dirichlet or a Matrix flux condition: the outflow of each
     * phase through matrix faces and, for Dirichlet ids, fracture junctions; the matrix face
     * area; the mean wetting pressure on the matrix faces: the Dirichlet value, or for flux
     * faces p_K + q d_K / (K_K eta^w_K) (the two-point flux solved for the face pressure; d_K the
     * cell centre's half-transmissibility distance to the face, as in the grid).
     */
    template <int dim>
    std::map<types::boundary_id, BoundaryBalance>
    boundary_balances(const geometry::CutMesh<dim> &mesh,
                      const TwoPhaseSolver<dim>    &solver,
                      const FaceFlux               &matrix_flux,
                      const bool                    axisymmetric);

    /// summary.json form: keys are the ids as strings, members outflow_w, outflow_nw, area,
    /// mean_pressure_w.
    io::Json
    to_json(const std::map<types::boundary_id, BoundaryBalance> &balances);

    /// One report line per id (4 digits; outflows below 1e-12 of the largest printed as 0), in
    /// m^3/s, or in m^2/s (per metre out of the plane) if @p plane (2D, not axisymmetric).
    void
    report_boundary_balances(const std::map<types::boundary_id, BoundaryBalance> &balances,
                             bool                                                 plane,
                             std::ostream                                        &report);
  } // namespace flow
} // namespace porofrac

#endif
