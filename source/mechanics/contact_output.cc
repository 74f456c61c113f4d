// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/numerics/data_out.h>

#include <porofrac/mechanics/contact_output.h>

#include <cmath>
#include <iomanip>

namespace porofrac
{
  namespace mechanics
  {
    const char *
    state_name(const FaceState s)
    {
      return s == FaceState::open ? "open" : (s == FaceState::stick ? "stick" : "slip");
    }



    template <int dim>
    FaceStateCounts
    count_states(const ContactProblem<dim> &problem, const int fracture_id)
    {
      FaceStateCounts c{{0, 0, 0}};
      for (const auto &face : problem.get_mesh().fracture_faces)
        if (fracture_id < 0 || int(face.fracture_id) == fracture_id)
          ++c[static_cast<unsigned int>(problem.state(face.index))];
      return c;
    }



    template <int dim>
    ContactFaceValues<dim>
    contact_face_values(const ContactProblem<dim> &problem, const unsigned int f)
    {
      const Tensor<2, dim> R = problem.frame(f);
      return {R * problem.jump(f),
              R * problem.multiplier(f),
              problem.state(f),
              problem.friction(f)};
    }



    template <int dim>
    std::vector<ContactFaceValues<dim>>
    contact_face_values(const ContactProblem<dim> &problem)
    {
      std::vector<ContactFaceValues<dim>> values;
      for (const auto &face : problem.get_mesh().fracture_faces)
        values.push_back(contact_face_values(problem, face.index));
      return values;
    }



    template <int dim>
    FaceStateCounts
    count_states(const geometry::CutMesh<dim>              &mesh,
                 const std::vector<ContactFaceValues<dim>> &values,
                 const int                                  fracture_id)
    {
      FaceStateCounts c{{0, 0, 0}};
      for (const auto &face : mesh.fracture_faces)
        if (fracture_id < 0 || int(face.fracture_id) == fracture_id)
          ++c[static_cast<unsigned int>(values[face.index].state)];
      return c;
    }



    template <int dim>
    void
    append_contact_fields(const ContactProblem<dim> &problem, geometry::FractureFields &fields)
    {
      append_contact_fields(contact_face_values(problem), fields);
    }



    template <int dim>
    void
    append_contact_fields(const std::vector<ContactFaceValues<dim>> &values,
                          geometry::FractureFields                  &fields)
    {
      std::vector<std::string> names = {"jump_n", "jump_t", "lambda_n", "lambda_t"};
      if (dim == 3)
        names.insert(names.end(), {"jump_t1", "jump_t2", "lambda_t1", "lambda_t2"});
      names.insert(names.end(), {"state", "friction"});
      const unsigned int first = fields.size();
      for (const std::string &name : names)
        fields.emplace_back(name, std::vector<double>());
      for (const ContactFaceValues<dim> &v : values)
        {
          using V                 = ContactFaceValues<dim>;
          std::vector<double> row = {v.jump[0],
                                     V::tangential(v.jump),
                                     v.lambda[0],
                                     V::tangential(v.lambda)};
          if (dim == 3)
            row.insert(row.end(), {v.jump[1], v.jump[dim - 1], v.lambda[1], v.lambda[dim - 1]});
          row.insert(row.end(), {static_cast<double>(v.state), v.friction});
          for (unsigned int k = 0; k < row.size(); ++k)
            fields[first + k].second.push_back(row[k]);
        }
    }



    void
    write_fracture_table_header(std::ostream &out, const unsigned int dim, const bool coupled)
    {
      out << "fracture_id,face_id,s,x,y," << (dim == 3 ? "z," : "") << "jump_n,jump_t,"
          << (dim == 3 ? "jump_t1,jump_t2," : "") << "lambda_n,lambda_t,"
          << (dim == 3 ? "lambda_t1,lambda_t2," : "") << "state,aperture"
          << (coupled ? ",p_E,time" : "") << '\n';
    }



    template <int dim>
    void
    write_fracture_table_rows(std::ostream              &out,
                              const ContactProblem<dim> &problem,
                              const CoupledFaceColumns  *coupled)
    {
      write_fracture_table_rows(out, problem.get_mesh(), contact_face_values(problem), coupled);
    }



    template <int dim>
    void
    write_fracture_table_rows(std::ostream                              &out,
                              const geometry::CutMesh<dim>              &mesh,
                              const std::vector<ContactFaceValues<dim>> &values,
                              const CoupledFaceColumns                  *coupled)
    {
      using V              = ContactFaceValues<dim>;
      const auto precision = out.precision(10);
      for (const auto &face : mesh.fracture_faces)
        {
          const V &v = values[face.index];
          out << face.fracture_id << ',' << face.index << ',' << face.abscissa << ','
              << face.centre[0] << ',' << face.centre[1] << ',';
          if (dim == 3)
            out << face.centre[dim - 1] << ',';
          out << v.jump[0] << ',' << V::tangential(v.jump) << ',';
          if (dim == 3)
            out << v.jump[1] << ',' << v.jump[dim - 1] << ',';
          out << v.lambda[0] << ',' << V::tangential(v.lambda) << ',';
          if (dim == 3)
            out << v.lambda[1] << ',' << v.lambda[dim - 1] << ',';
          out << state_name(v.state) << ',';
          if (coupled)
            out << coupled->aperture[face.index] << ',' << coupled->p_E[face.index] << ','
                << coupled->time;
          else
            out << std::max(0., -v.jump[0]);
          out << '\n';
        }
      out.precision(precision);
    }

    template <int dim>
    void
    write_displacement(const ContactProblem<dim>    &problem,
                       const std::string            &basename,
                       const std::string            &format,
                       const geometry::OutputPieces &pieces)
    {
      DataOut<dim> data_out;
      data_out.attach_dof_handler(problem.get_dof_handler());
      std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
        dim, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(problem.displacement(),
                               std::vector<std::string>(dim, "displacement"),
                               DataOut<dim>::type_dof_data,
                               interpretation);
      const auto &mesh = problem.get_mesh();
      geometry::write_field_file(
        data_out, mesh.triangulation, mesh.mapping(), 2, basename, format, pieces);
    }

#define POROFRAC_INSTANTIATE_FRACTURE_FIELDS(dim)                                                        \
  template FaceStateCounts        count_states(const ContactProblem<dim> &, const int);                  \
  template ContactFaceValues<dim> contact_face_values(const ContactProblem<dim> &,                       \
                                                      const unsigned int);                               \
  template void append_contact_fields(const ContactProblem<dim> &, geometry::FractureFields &);          \
  template std::vector<ContactFaceValues<dim>> contact_face_values(const ContactProblem<dim> &);         \
  template FaceStateCounts                     count_states(const geometry::CutMesh<dim> &,              \
                                                            const std::vector<ContactFaceValues<dim>> &, \
                                                            const int);                                  \
  template void append_contact_fields(const std::vector<ContactFaceValues<dim>> &,                       \
                                      geometry::FractureFields &);                                       \
  template void write_fracture_table_rows(std::ostream &,                                                \
                                          const geometry::CutMesh<dim> &,                                \
                                          const std::vector<ContactFaceValues<dim>> &,                   \
                                          const CoupledFaceColumns *);                                   \
  template void write_fracture_table_rows(std::ostream &,                                                \
                                          const ContactProblem<dim> &,                                   \
                                          const CoupledFaceColumns *);                                   \
  template void write_displacement(const ContactProblem<dim> &,                                          \
                                   const std::string &,                                                  \
                                   const std::string &,                                                  \
                                   const geometry::OutputPieces &);
    POROFRAC_INSTANTIATE_FRACTURE_FIELDS(2)
    POROFRAC_INSTANTIATE_FRACTURE_FIELDS(3)
#undef POROFRAC_INSTANTIATE_FRACTURE_FIELDS
  } // namespace mechanics
} // namespace porofrac
