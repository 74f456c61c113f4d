// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_COUPLING_ENTRY_H
#define POROFRAC_MECHANICS_COUPLING_ENTRY_H

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
  } // namespace mechanics
} // namespace porofrac

#endif
