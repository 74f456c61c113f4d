// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_FRACTURE_RECONSTRUCTION_H
#define POROFRAC_MECHANICS_FRACTURE_RECONSTRUCTION_H

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <porofrac/mechanics/contact_problem.h>

#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /// Reconstructed fracture fields at one quadrature point of a fracture face (global frame).
    template <int dim>
    struct FracturePointValues
    {
      unsigned int   face;
      Point<dim>     x;
      double         abscissa; ///< 2D: curvilinear abscissa of x; 3D: that of the face centre
      double         JxW;
      Tensor<1, dim> jump;   ///< P2 jump u+ - u- at x (the natural P2 reconstruction)
      Tensor<1, dim> lambda; ///< node-based P2 multiplier at x
    };

    /**
     * The P2 reconstructions the paper uses for its error norms (Section 5, "natural P2
     * reconstruction for the jump [u] and node-based P2 reconstruction for the vector Lagrange
     * multiplier using the tractions stemming from the weak form"):
     * - [u](x) = u+(x) - u-(x), the traces of the P2 displacement on both sides;
     * - lambda(x) = sum_i lambda_i phi_i(x) over the P2 nodes i of the plus side of the
     *   fracture, with the nodal traction lambda_i = (sum_sigma int_sigma lambda_sigma phi_i) /
     *   (sum_sigma int_sigma phi_i), i.e. the weak-form coupling force B^T lambda of node i (which
     *   equals f - K u there at the solution) divided by the lumped fracture mass of the node.
     *   In 3D the P2 vertex functions integrate to zero on a triangle, and the weight of every
     *   node of a face is |sigma| / 3 instead (an area-weighted mean of the face multipliers).
     * Values at @p n_points Gauss points per fracture face.
     */
    template <int dim>
    std::vector<FracturePointValues<dim>>
    reconstruct_fracture_fields(const ContactProblem<dim> &problem, const unsigned int n_points);
  } // namespace mechanics
} // namespace porofrac

#endif
