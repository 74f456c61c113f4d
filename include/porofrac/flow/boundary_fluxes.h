// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_BOUNDARY_FLUXES_H
#define POROFRAC_FLOW_BOUNDARY_FLUXES_H

#include <porofrac/flow/parameters.h>
#include <porofrac/flow/two_phase_solver.h>
#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/io/json.h>

namespace porofrac
{
  namespace flow
  {
    /**
     * Per outer boundary id with a Dirichlet or a Matrix flux condition, the outflow of each
     * phase (m^3/s, positive out of the domain; through matrix faces and, for Dirichlet ids,
     * fracture junctions), the matrix face area, and the area-weighted mean wetting pressure on
     * the matrix faces: the Dirichlet value, or for flux faces p_K + q d_K / (K_K eta^w_K) (the
     * two-point flux solved for the face pressure; d_K the cell centre's distance to the face,
     * as in the grid). Keys are the ids as strings: {"outflow_w", "outflow_nw", "area",
     * "mean_pressure_w"}.
     */
    template <int dim>
    io::Json
    boundary_fluxes(const geometry::CutMesh<dim>  &mesh,
                    const TwoPhaseSolver<dim>     &solver,
                    const FaceFlux                &matrix_flux,
                    const bool                     axisymmetric);
  } // namespace flow
} // namespace porofrac

#endif
