// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/io/expression.h>
#include <porofrac/mechanics/friction_field.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace porofrac
{
  namespace mechanics
  {
    template <int dim>
    void
    FrictionField<dim>::initialize(const geometry::CutMesh<dim> &mesh, const ContactParameters &prm)
    {
      law = prm.friction_law;
      if (!law)
        law =
          FrictionLawRegistry::instance().create(prm.friction_law_name, "Mechanics/Friction law");
      const std::string parameter = "Mechanics/Friction coefficient";
      for (const auto &[id, expression] : prm.friction)
        check_input(std::count(mesh.fracture_ids.begin(), mesh.fracture_ids.end(), id) > 0,
                    parameter,
                    "fracture id " + std::to_string(id) + " (in '" + std::to_string(id) + ": " +
                      expression + "') is not a fracture of the mesh");
      std::map<unsigned int, std::unique_ptr<dealii::FunctionParser<dim>>> functions;
      for (const unsigned int id : mesh.fracture_ids)
        {
          const auto it = prm.friction.find(id);
          functions[id] =
            io::parse_expressions<dim>({it != prm.friction.end() ? it->second : prm.friction_all},
                                       parameter,
                                       "d");
        }
      field.resize(mesh.fracture_faces.size());
      for (const auto &face : mesh.fracture_faces)
        {
          dealii::FunctionParser<dim> &F0 = *functions[face.fracture_id];
          F0.set_time(std::isfinite(face.distance_to_tip) ? face.distance_to_tip : 1e100);
          field[face.index] = F0.value(face.centre);
          law->check_coefficient(field[face.index], face.fracture_id);
        }
    }

    template class FrictionField<2>;
    template class FrictionField<3>;
  } // namespace mechanics
} // namespace porofrac
