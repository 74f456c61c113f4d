// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/contact_problem.h>
#include <porofrac/mechanics/coupling_entry.h>

namespace porofrac
{
  namespace mechanics
  {
    template <int dim>
    ContactProblem<dim>::ContactProblem(const geometry::CutMesh<dim> &mesh,
                                        const ContactParameters      &parameters,
                                        ConditionalOStream           &progress,
                                        TimerOutput                  &timer)
        : prm(parameters)
        , system(mesh, prm, timer)
        , solver(system, friction_field, prm, progress, timer)
    {
    }



    template <int dim>
    void
    ContactProblem<dim>::setup(const SystemAssembly what)
    {
      system.setup(what);
      solver.clear();
      friction_field.initialize(system.get_mesh(), prm);
      u.reinit(system.n_displacement_dofs());
      lambda.reinit(dim * system.get_mesh().fracture_faces.size());
      solved_once = false;
    }



    template <int dim>
    const ContactStatistics &
    ContactProblem<dim>::solve(const bool warm_start)
    {
      AssertThrow(system.has_matrices(),
                  ExcMessage("ContactProblem::solve() needs setup() with the matrices"));
      const bool cold = !(warm_start && solved_once);
      solved_once     = true;
      return solver.solve(u, lambda, cold);
    }



    template <int dim>
    void
    ContactProblem<dim>::reset()
    {
      solved_once = false;
      solver.reset();
    }



    template <int dim>
    void
    ContactProblem<dim>::set_contact_solver(const std::string &method,
                                            const double       c,
                                            const bool         stick_guess)
    {
      prm.method      = method;
      prm.c           = c;
      prm.stick_guess = stick_guess;
      prm.validate(dim);
      reset();
    }



    template <int dim>
    void
    ContactProblem<dim>::set_equivalent_pressures(const std::vector<double> &p_E_matrix,
                                                  const std::vector<double> &p_E_fracture,
                                                  const double               biot)
    {
      system.set_equivalent_pressures(p_E_matrix, p_E_fracture, biot);
    }



    template <int dim>
    unsigned int
    ContactProblem<dim>::n_factorizations() const
    {
      const ContactLinearSolverStatistics *s = solver.linear_solver_statistics();
      return s ? s->factorizations : 0;
    }



    template <int dim>
    Tensor<1, dim>
    ContactProblem<dim>::multiplier(const unsigned int f) const
    {
      return face_multiplier<dim>(lambda, f);
    }



    template <int dim>
    double
    ContactProblem<dim>::normal_jump(const unsigned int f) const
    {
      return system.get_mesh().fracture_faces[f].normal * jump(f);
    }

    template class ContactProblem<2>;
    template class ContactProblem<3>;
  } // namespace mechanics
} // namespace porofrac
