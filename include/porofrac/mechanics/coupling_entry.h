// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_COUPLING_ENTRY_H
#define POROFRAC_MECHANICS_COUPLING_ENTRY_H

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

namespace porofrac
{
  namespace mechanics
  {
    /// One term of the coupling int_sigma lambda . [v] (paper eq. (10)) of a fracture face:
    /// displacement dof, its vector component and +-int_sigma phi_dof.
    struct CouplingEntry
    {
      dealii::types::global_dof_index dof;
      unsigned int                    component;
      double                          value;
    };

    /// The multiplier of face @p f: the multipliers are stored face by face, dim components
    /// each (global frame), in any vector type indexable by global index.
    template <int dim, typename VectorType>
    dealii::Tensor<1, dim>
    face_multiplier(const VectorType &lambda, const unsigned int f)
    {
      dealii::Tensor<1, dim> l;
      for (unsigned int d = 0; d < dim; ++d)
        l[d] = lambda(dim * f + d);
      return l;
    }
  } // namespace mechanics
} // namespace porofrac

#endif
