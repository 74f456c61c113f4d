// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_FRICTION_FIELD_H
#define POROFRAC_MECHANICS_FRICTION_FIELD_H

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/mechanics/friction_law.h>
#include <porofrac/mechanics/parameters.h>

#include <memory>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /**
     * The friction coefficient of every fracture face: the deck's coefficient field F0(x, d)
     * (Mechanics/Friction coefficient, per fracture id, evaluated at the face centres with d
     * the distance to the fracture's tips) and the friction law that turns it into F at a
     * given slip.
     */
    template <int dim>
    class FrictionField
    {
    public:
      /// Evaluates and checks F0 on every face; InputError naming the entry.
      void
      initialize(const geometry::CutMesh<dim> &mesh, const ContactParameters &parameters);

      /// F of face @p f at slip |[u]_tau| = @p slip.
      double
      coefficient(const unsigned int f, const double slip) const
      {
        return law->coefficient(field[f], slip);
      }
      /// F0 of face @p f.
      double
      field_value(const unsigned int f) const
      {
        return field[f];
      }
      bool
      depends_on_slip() const
      {
        return law->depends_on_slip();
      }

    private:
      std::shared_ptr<const FrictionLaw> law;
      std::vector<double>                field;
    };
  } // namespace mechanics
} // namespace porofrac

#endif
