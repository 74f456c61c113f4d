// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_MULTIPLIER_STABILIZATION_H
#define POROFRAC_MECHANICS_MULTIPLIER_STABILIZATION_H

#include <deal.II/base/tensor.h>

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/mechanics/parameters.h>

#include <utility>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    /**
     * The multiplier stabilization of doc/algorithms.md §2.2 (deck: Mechanics/Multiplier
     * stabilization = alpha), a linear map S from multipliers to jumps,
     *
     *   (S lambda)_sigma = sum_{sigma'} s_{sigma sigma'} (lambda_sigma - lambda_sigma'),
     *   s_{sigma sigma'} = alpha (h_sigma + h_sigma') / (2 E'),   E' = E / (1 - nu^2),
     *
     * over the faces sigma' of the same fracture that share an edge (3D) or a vertex (2D) with
     * sigma, h the face size (length, or the square root of the area). The contact conditions
     * (25)-(26) read the jump [u]_sigma - (S lambda)_sigma: the compliance a face bubble would
     * add (of order h / E per face), which face-wise constant multipliers need to be stable
     * against P2 on tetrahedra. S is symmetric positive semi-definite and vanishes on
     * multipliers that are constant on each fracture.
     *
     * Stored per face: the pairs (sigma', s_{sigma sigma'}); empty lists when alpha = 0.
     */
    using MultiplierStabilization = std::vector<std::vector<std::pair<unsigned int, double>>>;

    template <int dim>
    MultiplierStabilization
    make_multiplier_stabilization(const geometry::CutMesh<dim> &mesh,
                                  const ContactParameters      &parameters);

    /// (S lambda)_f, global frame; @p lambda(g) returns the multiplier of face g.
    template <int dim, typename Multipliers>
    Tensor<1, dim>
    stabilization_term(const MultiplierStabilization &S,
                       const unsigned int             f,
                       const Multipliers             &lambda)
    {
      Tensor<1, dim> t;
      if (S.empty() || S[f].empty())
        return t;
      const Tensor<1, dim> own = lambda(f);
      for (const auto &[g, s] : S[f])
        t += s * (own - lambda(g));
      return t;
    }

    /**
     * The Jacobian entries the stabilization adds to the face rows A_l lambda + A_j ([u] -
     * S lambda) of face @p f, with @p A_j the rows' jump part (global frame): visit(i, g, k,
     * value) for row i and multiplier component k of face g, -A_j[i][k] sum_g' s_fg' on f
     * itself and A_j[i][k] s_fg on each neighbour g.
     */
    template <int dim, typename Visit>
    void
    for_stabilization_entries(const MultiplierStabilization &S,
                              const unsigned int             f,
                              const Tensor<2, dim>          &A_j,
                              const Visit                   &visit)
    {
      if (S.empty() || S[f].empty())
        return;
      double total = 0;
      for (const auto &neighbour : S[f])
        total += neighbour.second;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int k = 0; k < dim; ++k)
          if (A_j[i][k] != 0)
            {
              visit(i, f, k, -A_j[i][k] * total);
              for (const auto &[g, s] : S[f])
                visit(i, g, k, A_j[i][k] * s);
            }
    }
  } // namespace mechanics
} // namespace porofrac

#endif
