// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/mechanics/fracture_table.h>

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



    void
    write_fracture_table_header(std::ostream &out, const unsigned int dim, const bool with_time)
    {
      out << "fracture_id,face_id,s,x,y," << (dim == 3 ? "z," : "")
          << "jump_n,jump_t,lambda_n,lambda_t,state,aperture" << (with_time ? ",time" : "") << '\n';
    }



    template <int dim>
    void
    write_fracture_table_rows(std::ostream              &out,
                              const ContactProblem<dim> &problem,
                              const std::vector<double> *aperture,
                              const double              *time)
    {
      const auto precision = out.precision(10);
      for (const auto &face : problem.get_mesh().fracture_faces)
        {
          const Tensor<2, dim> R  = problem.frame(face.index);
          const Tensor<1, dim> j  = R * problem.jump(face.index);
          const Tensor<1, dim> l  = R * problem.multiplier(face.index);
          double               jt = j[1], lt = l[1];
          if (dim == 3)
            {
              jt = std::hypot(j[1], j[dim - 1]);
              lt = std::hypot(l[1], l[dim - 1]);
            }
          out << face.fracture_id << ',' << face.index << ',' << face.abscissa << ','
              << face.centre[0] << ',' << face.centre[1] << ',';
          if (dim == 3)
            out << face.centre[dim - 1] << ',';
          out << j[0] << ',' << jt << ',' << l[0] << ',' << lt << ','
              << state_name(problem.state(face.index)) << ','
              << (aperture ? (*aperture)[face.index] : std::max(0., -j[0]));
          if (time)
            out << ',' << *time;
          out << '\n';
        }
      out.precision(precision);
    }

    template void
    write_fracture_table_rows(std::ostream &,
                              const ContactProblem<2> &,
                              const std::vector<double> *,
                              const double *);
    template void
    write_fracture_table_rows(std::ostream &,
                              const ContactProblem<3> &,
                              const std::vector<double> *,
                              const double *);
  } // namespace mechanics
} // namespace porofrac
