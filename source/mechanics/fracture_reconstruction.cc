// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <porofrac/mechanics/fracture_reconstruction.h>

#include <map>

namespace porofrac
{
  namespace mechanics
  {
    template <int dim>
    std::vector<FracturePointValues<dim>>
    reconstruct_fracture_fields(const ContactProblem<dim> &problem, const unsigned int n_points)
    {
      const auto                          &mesh    = problem.get_mesh();
      const auto                          &dh      = problem.get_dof_handler();
      const FiniteElement<dim>            &fe      = dh.get_fe();
      const Mapping<dim>                  &mapping = mesh.mapping();
      const QGaussSimplex<dim - 1>         face_quadrature(n_points);
      FEFaceValues<dim>                    fe_face(mapping,
                                fe,
                                face_quadrature,
                                update_values | update_quadrature_points | update_JxW_values);
      const FEValuesExtractors::Vector     disp(0);
      std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
      auto plus_cell = [&](const geometry::FractureFace<dim> &face, const unsigned int side) {
        return typename DoFHandler<dim>::active_cell_iterator(&mesh.triangulation,
                                                              face.cell[side]->level(),
                                                              face.cell[side]->index(),
                                                              &dh);
      };

      // Nodal tractions of the plus side: (B^T lambda)_i / int phi_i, per component.
      std::map<types::global_dof_index, std::pair<double, double>> nodal; // dof -> (force, mass)
      for (const auto &face : mesh.fracture_faces)
        {
          const auto cell = plus_cell(face, geometry::plus);
          fe_face.reinit(cell, face.face_no[geometry::plus]);
          cell->get_dof_indices(local);
          const Tensor<1, dim> l = problem.multiplier(face.index);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            if (fe.has_support_on_face(i, face.face_no[geometry::plus]))
              {
                const unsigned int comp = fe.system_to_component_index(i).first;
                // 2D: int phi_i. 3D: the P2 vertex functions integrate to zero on a triangle,
                // so every node of the face gets |sigma| / 3 (the integral of the P1 hat
                // function at a vertex, and of the P2 function at an edge midpoint).
                double m = 0;
                if (dim == 3)
                  m = face.measure / 3;
                else
                  for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                    m += fe_face.shape_value_component(i, q, comp) * fe_face.JxW(q);
                nodal[local[i]].first += l[comp] * m;
                nodal[local[i]].second += m;
              }
        }

      std::vector<FracturePointValues<dim>> values;
      std::vector<Tensor<1, dim>>           u_plus(face_quadrature.size());
      for (const auto &face : mesh.fracture_faces)
        {
          const auto cell = plus_cell(face, geometry::plus);
          fe_face.reinit(cell, face.face_no[geometry::plus]);
          fe_face[disp].get_function_values(problem.displacement(), u_plus);
          cell->get_dof_indices(local);
          // The minus side at the same physical points.
          const auto              minus = plus_cell(face, geometry::minus);
          std::vector<Point<dim>> unit(face_quadrature.size());
          for (unsigned int q = 0; q < face_quadrature.size(); ++q)
            unit[q] = mapping.transform_real_to_unit_cell(minus, fe_face.quadrature_point(q));
          FEValues<dim> fe_minus(mapping, fe, Quadrature<dim>(unit), update_values);
          fe_minus.reinit(minus);
          std::vector<Tensor<1, dim>> u_minus(face_quadrature.size());
          fe_minus[disp].get_function_values(problem.displacement(), u_minus);
          for (unsigned int q = 0; q < face_quadrature.size(); ++q)
            {
              FracturePointValues<dim> v;
              v.face     = face.index;
              v.x        = fe_face.quadrature_point(q);
              v.abscissa = face.abscissa + (dim == 2 ? (v.x - face.centre) * face.tangent : 0.);
              v.JxW      = fe_face.JxW(q);
              v.jump     = u_plus[q] - u_minus[q];
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                if (fe.has_support_on_face(i, face.face_no[geometry::plus]))
                  {
                    const unsigned int comp = fe.system_to_component_index(i).first;
                    const auto        &n    = nodal.at(local[i]);
                    if (n.second != 0)
                      v.lambda[comp] +=
                        n.first / n.second * fe_face.shape_value_component(i, q, comp);
                  }
              values.push_back(v);
            }
        }
      return values;
    }

    template std::vector<FracturePointValues<2>>
    reconstruct_fracture_fields(const ContactProblem<2> &, const unsigned int);
    template std::vector<FracturePointValues<3>>
    reconstruct_fracture_fields(const ContactProblem<3> &, const unsigned int);
  } // namespace mechanics
} // namespace porofrac
