// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_CONTACT_OUTPUT_H
#define POROFRAC_MECHANICS_CONTACT_OUTPUT_H

#include <deal.II/base/tensor.h>

#include <porofrac/geometry/mesh_output.h>
#include <porofrac/mechanics/contact_problem.h>

#include <array>
#include <ostream>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    /// "open", "stick" or "slip".
    const char *
    state_name(const FaceState state);

    /// Numbers of open, stick and slip faces (indexed by FaceState).
    using FaceStateCounts = std::array<unsigned int, 3>;

    /// Face-state counts of the faces of fracture @p fracture_id, or of all faces with -1.
    template <int dim>
    FaceStateCounts
    count_states(const ContactProblem<dim> &problem, const int fracture_id = -1);

    /// The contact quantities of one fracture face, in its local frame (n+, t1[, t2]).
    template <int dim>
    struct ContactFaceValues
    {
      Tensor<1, dim> jump;   ///< [u]_sigma: component 0 = [u]_n, then the tangential ones
      Tensor<1, dim> lambda; ///< lambda_sigma, same frame
      FaceState      state;
      double         friction;

      /// 2D: the signed tangential component; 3D: the magnitude of the tangential vector.
      static double
      tangential(const Tensor<1, dim> &v)
      {
        return dim == 2 ? v[1] : LocalContactLaw<dim>::tangential(v).norm();
      }
    };

    template <int dim>
    ContactFaceValues<dim>
    contact_face_values(const ContactProblem<dim> &problem, const unsigned int f);

    /// The contact values of every fracture face, in index order.
    template <int dim>
    std::vector<ContactFaceValues<dim>>
    contact_face_values(const ContactProblem<dim> &problem);

    /// Face-state counts of @p values (of the faces of fracture @p fracture_id of @p mesh, or
    /// of all faces with -1).
    template <int dim>
    FaceStateCounts
    count_states(const geometry::CutMesh<dim>              &mesh,
                 const std::vector<ContactFaceValues<dim>> &values,
                 const int                                  fracture_id = -1);

    /**
     * Appends the contact fields of every fracture face to @p fields (the fracture VTU of every
     * physics): jump_n, jump_t, lambda_n, lambda_t, state (0 open, 1 stick, 2 slip) and
     * friction. jump_t and lambda_t are signed in 2D; in 3D they are the magnitudes, and the
     * components along t1 and t2 follow as jump_t1, jump_t2, lambda_t1, lambda_t2.
     */
    template <int dim>
    void
    append_contact_fields(const ContactProblem<dim> &problem, geometry::FractureFields &fields);

    /// The same from the values of every face.
    template <int dim>
    void
    append_contact_fields(const std::vector<ContactFaceValues<dim>> &values,
                          geometry::FractureFields                  &fields);

    /**
     * Header of fractures.csv: fracture_id, face_id, s, x, y[, z], jump_n, jump_t[, jump_t1,
     * jump_t2], lambda_n, lambda_t[, lambda_t1, lambda_t2], state, aperture[, p_E, time] (3D
     * adds z and the tangential components; @p coupled adds the fracture's equivalent pressure
     * and the time).
     */
    void
    write_fracture_table_header(std::ostream &out, const unsigned int dim, const bool coupled);

    /// The flow columns of a coupled fracture table: per fracture face f, the aperture and the
    /// equivalent pressure p_E (11d) of the fracture cell f, and the time.
    struct CoupledFaceColumns
    {
      const std::vector<double> &aperture;
      const double              *p_E;
      double                     time;
    };

    /// One row per fracture face (see the header). Without @p coupled the aperture is
    /// max(0, -[u]_n) (the opening).
    template <int dim>
    void
    write_fracture_table_rows(std::ostream              &out,
                              const ContactProblem<dim> &problem,
                              const CoupledFaceColumns  *coupled = nullptr);

    /// The same from the values of every face of @p mesh.
    template <int dim>
    void
    write_fracture_table_rows(std::ostream                              &out,
                              const geometry::CutMesh<dim>              &mesh,
                              const std::vector<ContactFaceValues<dim>> &values,
                              const CoupledFaceColumns                  *coupled = nullptr);

    /// Writes the P2 displacement (patches of degree 2) as the field file @p basename (a path
    /// without extension; geometry::write_field_file) in @p format (vtu, vtk).
    template <int dim>
    void
    write_displacement(const ContactProblem<dim>    &problem,
                       const std::string            &basename,
                       const std::string            &format,
                       const geometry::OutputPieces &pieces = geometry::OutputPieces());
  } // namespace mechanics
} // namespace porofrac

#endif
