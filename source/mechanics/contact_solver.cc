// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/timer.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/interrupt.h>
#include <porofrac/mechanics/contact_solver.h>
#include <porofrac/mechanics/coupling_entry.h>
#include <porofrac/mechanics/distributed_elasticity_system.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace porofrac
{
  namespace mechanics
  {
    template <int dim, typename System>
    ContactSolver<dim, System>::ContactSolver(const System             &system,
                                              const FrictionField<dim> &friction,
                                              const ContactParameters  &parameters,
                                              ConditionalOStream       &progress,
                                              TimerOutput              &timer)
        : system(system)
        , friction_field(friction)
        , prm(parameters)
        , progress(progress)
        , timer(timer)
    {
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::reset()
    {
      if (linear_solver)
        linear_solver->reset();
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::clear()
    {
      linear_solver.reset();
    }



    template <int dim, typename System>
    std::string
    ContactSolver<dim, System>::linear_solver_name() const
    {
      return linear_solver ? linear_solver->name() : std::string();
    }



    template <int dim, typename System>
    const ContactLinearSolverStatistics *
    ContactSolver<dim, System>::linear_solver_statistics() const
    {
      return linear_solver ? &linear_solver->statistics() : nullptr;
    }



    template <int dim, typename System>
    LocalContactLaw<dim>
    ContactSolver<dim, System>::local_law(const unsigned int f,
                                          const double       slip,
                                          const double       c) const
    {
      return {friction_field.coefficient(f, slip), c};
    }



    template <int dim, typename System>
    typename ContactSolver<dim, System>::FaceValues
    ContactSolver<dim, System>::local_values(const Tensor<1, dim> &jump,
                                             const Tensor<1, dim> &lambda,
                                             const unsigned int    f) const
    {
      const Tensor<2, dim> R = system.frame(f);
      FaceValues           v;
      v.lambda = R * lambda;
      v.jump   = R * jump;
      v.slip   = LocalContactLaw<dim>::tangential(v.jump).norm();
      // Paper (25): the tangential part is the increment over the time step.
      if (!previous_jump.empty())
        v.jump -= LocalContactLaw<dim>::tangential(R * previous_jump[f]);
      return v;
    }



    template <int dim, typename System>
    bool
    ContactSolver<dim, System>::same_states(const std::vector<FaceState> &a,
                                            const std::vector<FaceState> &b) const
    {
      return system.all_processes(a == b);
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::set_previous_jumps(const std::vector<Tensor<1, dim>> &jumps)
    {
      previous_jump = jumps;
    }



    template <int dim, typename System>
    double
    ContactSolver<dim, System>::friction(const Tensor<1, dim> &jump, const unsigned int f) const
    {
      const double slip = LocalContactLaw<dim>::tangential(system.frame(f) * jump).norm();
      return friction_field.coefficient(f, slip);
    }



    template <int dim, typename System>
    FaceState
    ContactSolver<dim, System>::state(const Tensor<1, dim> &jump,
                                      const Tensor<1, dim> &lambda,
                                      const unsigned int    f) const
    {
      const FaceValues v = local_values(jump, lambda, f);
      return local_law(f, v.slip, prm.c).state(v.lambda, v.jump);
    }



    template <int dim, typename System>
    typename ContactSolver<dim, System>::ResidualParts
    ContactSolver<dim, System>::residual_parts(const VectorType &u,
                                               const VectorType &lambda,
                                               const double      c) const
    {
      // Mechanical rows: f - K u - B^T lambda on unconstrained dofs.
      const auto [mechanical, load] = system.mechanical_residual_norms(u, lambda);
      // Contact rows, (25)-(26) scaled to stress units, weighted by |sigma|.
      std::vector<Tensor<1, dim>> jumps;
      system.contact_jumps(u, lambda, jumps);
      double contact = 0, contact_unscaled = 0, lambda2 = 0, c_jump = 0, jump = 0, measure = 0,
             stick_slip = 0;
      for (unsigned int fi = 0; fi < system.n_faces(); ++fi)
        {
          if (!system.owns_face(fi))
            continue;
          const FaceValues      v = local_values(jumps[fi], face_multiplier<dim>(lambda, fi), fi);
          const Tensor<1, dim> &l = v.lambda, &j = v.jump;
          const LocalContactLaw<dim> law = local_law(fi, v.slip, c);
          const double               w   = system.face_measure(fi);
          contact += w * law.residual(l, j, true).norm_square();
          contact_unscaled += w * law.residual(l, j, false).norm_square();
          lambda2 += w * l.norm_square();
          c_jump += w * (c * j).norm_square();
          jump += w * j.norm_square();
          measure += w;
          if (law.state(l, j) == FaceState::stick)
            stick_slip += w * LocalContactLaw<dim>::tangential(j).norm_square();
        }
      std::vector<double> sums = {
        mechanical, load, contact, contact_unscaled, lambda2, c_jump, jump, measure, stick_slip};
      system.sum_over_processes(sums);
      ResidualParts parts;
      parts.mechanical       = sums[0];
      parts.load             = sums[1];
      parts.contact          = sums[2];
      parts.contact_unscaled = sums[3];
      parts.lambda           = sums[4];
      parts.c_jump           = sums[5];
      parts.jump             = sums[6];
      parts.measure          = sums[7];
      parts.stick_slip       = sums[8];
      parts.u_max            = u.linfty_norm();
      return parts;
    }



    template <int dim, typename System>
    double
    ContactSolver<dim, System>::merit(const ResidualParts &r, const double scale2)
    {
      const double rel_c = (scale2 > 0 ? std::sqrt(r.contact / scale2) : std::sqrt(r.contact));
      const double rel_m = (r.load > 0 ? std::sqrt(r.mechanical / r.load) : 0.);
      return std::max(rel_c, rel_m);
    }



    template <int dim, typename System>
    std::array<double, 3>
    ContactSolver<dim, System>::stopping_terms(const VectorType &u, const VectorType &lambda) const
    {
      const ResidualParts r = residual_parts(u, lambda, prm.c);
      // lambda is the scale of C unless it is zero or round-off against c [u] (every face open:
      // C = lambda there, so |C| / |lambda| would stay 1 at the exact solution).
      const double scale2 = r.lambda > 1e-24 * r.c_jump ? r.lambda : r.c_jump;
      // A stick face may keep a slip of about tol |lambda| / c under the C test alone: bound it
      // by the problem's own displacement scale, the jumps or else the largest displacement.
      const double slip_scale2 = std::max(r.jump, r.measure * r.u_max * r.u_max);
      return {{scale2 > 0 ? std::sqrt(r.contact / scale2) : std::sqrt(r.contact),
               r.load > 0 ? std::sqrt(r.mechanical / r.load) : 0.,
               slip_scale2 > 0 ? std::sqrt(r.stick_slip / slip_scale2) : 0.}};
    }



    template <int dim, typename System>
    std::array<unsigned int, 4>
    ContactSolver<dim, System>::state_counts(const std::vector<FaceState> &states) const
    {
      std::vector<double> counts(4, 0.);
      for (unsigned int fi = 0; fi < states.size(); ++fi)
        if (system.owns_face(fi))
          {
            counts[static_cast<unsigned int>(states[fi])] += 1;
            if (!seen_states.empty() && seen_states.back()[fi] != states[fi])
              counts[3] += 1;
          }
      system.sum_over_processes(counts);
      return {{static_cast<unsigned int>(counts[0]),
               static_cast<unsigned int>(counts[1]),
               static_cast<unsigned int>(counts[2]),
               static_cast<unsigned int>(counts[3])}};
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::set_initial_guess(VectorType &u, VectorType &lambda) const
    {
      // u = 0 with the Dirichlet values; open: lambda = 0, stick: lambda_n = given.
      system.initial_displacement(u);
      system.reinit_multipliers(lambda);
      if (prm.stick_guess)
        for (const auto &face : system.get_mesh().fracture_faces)
          if (system.owns_face(face.index))
            for (unsigned int d = 0; d < dim; ++d)
              lambda(dim * face.index + d) = prm.initial_lambda_n * face.normal[d];
      lambda.compress(VectorOperation::insert);
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::linearize(const VectorType       &u,
                                          const VectorType       &lambda,
                                          const double            c,
                                          FaceRows<dim>          &rows,
                                          VectorType             &rhs,
                                          std::vector<FaceState> &states) const
    {
      rhs = 0;
      // Mechanical residual f - K u - B^T lambda.
      system.mechanical_rhs(u, lambda, rhs);
      // Face rows A_l R lambda + A_j R [u] = r of the contact method, for the increment.
      std::vector<Tensor<1, dim>> jumps;
      system.contact_jumps(u, lambda, jumps);
      for (unsigned int fi = 0; fi < system.n_faces(); ++fi)
        {
          if (!system.owns_face(fi))
            continue;
          const Tensor<2, dim>  R = system.frame(fi);
          const FaceValues      v = local_values(jumps[fi], face_multiplier<dim>(lambda, fi), fi);
          const Tensor<1, dim> &l = v.lambda, &j = v.jump;
          LocalRows<dim>        lr;
          states[fi]              = method->rows(local_law(fi, v.slip, c), l, j, lr);
          const Tensor<1, dim> rs = lr.rhs - lr.A_lambda * l - lr.A_jump * j;
          rows.lambda[fi]         = lr.A_lambda * R;
          rows.jump[fi]           = lr.A_jump * R;
          for (unsigned int i = 0; i < dim; ++i)
            rhs(system.multiplier_index(fi, i)) = rs[i];
        }
      rhs.compress(VectorOperation::insert);
    }



    template <int dim, typename System>
    double
    ContactSolver<dim, System>::cycle_damping_factor(const std::vector<FaceState> &states,
                                                     const unsigned int            iteration)
    {
      // States equal to those of an earlier iterate other than the previous one mean that the
      // iteration revisits a set: damp the step.
      if (prm.cycle_damping > 0)
        for (unsigned int k = 0; k + 1 < seen_states.size(); ++k)
          if (same_states(seen_states[k], states) && !same_states(seen_states.back(), states))
            {
              ++stats.cycles_detected;
              progress << "    contact iteration " << iteration
                       << ": face states repeat those of iteration " << k + 1 << "; step damped by "
                       << prm.cycle_damping << std::endl;
              return prm.cycle_damping;
            }
      return 1.;
    }



    template <int dim, typename System>
    double
    ContactSolver<dim, System>::take_step(const VectorType &u_old,
                                          const VectorType &lambda_old,
                                          const VectorType &delta,
                                          const double      alpha_max,
                                          const double      c,
                                          VectorType       &u,
                                          VectorType       &lambda)
    {
      const auto set_step = [&](const double alpha) {
        system.set_step(u_old, lambda_old, delta, alpha, u, lambda);
      };
      double alpha = alpha_max;
      set_step(alpha);
      // The line search runs from the start, or (trigger on stagnation) from the first iterate
      // whose relative residual did not decrease.
      const auto        &history = stats.residual_history;
      const unsigned int nr      = history.size();
      if (prm.line_search && !line_search_on &&
          (!prm.line_search_on_stagnation || (nr > 1 && history[nr - 1] >= history[nr - 2])))
        line_search_on = true;
      if (!line_search_on)
        return alpha;
      // Backtracking (Armijo) on the merit max(|C|/S, |r_mech|/|f|) of (25)-(26) with one
      // multiplier scale S for all trial steps (the larger of the current and the full-step
      // multipliers).
      const ResidualParts trial   = residual_parts(u, lambda, c);
      const ResidualParts current = residual_parts(u_old, lambda_old, c);
      double              scale2  = std::max(trial.lambda, current.lambda);
      if (scale2 <= 0)
        scale2 = std::max(trial.c_jump, current.c_jump);
      // Non-monotone reference (Grippo-Lampariello-Lucidi): the largest of the current merit
      // and the relative residuals of the last `memory - 1` iterates.
      double phi0 = merit(current, scale2);
      for (unsigned int k = 1; k < prm.line_search_memory && k < history.size(); ++k)
        phi0 = std::max(phi0, history[history.size() - 1 - k]);
      double       phi  = merit(trial, scale2);
      double       best = phi, best_alpha = alpha;
      unsigned int halvings = 0;
      while (phi > (1 - 1e-4 * alpha) * phi0 && halvings < prm.line_search_halvings)
        {
          alpha /= 2;
          ++halvings;
          ++stats.backtracks;
          set_step(alpha);
          phi = merit(residual_parts(u, lambda, c), scale2);
          if (phi < best)
            {
              best       = phi;
              best_alpha = alpha;
            }
        }
      // No sufficient decrease: keep the best step tried.
      if (phi > (1 - 1e-4 * alpha) * phi0 && best_alpha != alpha)
        {
          alpha = best_alpha;
          set_step(alpha);
        }
      return alpha;
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::stop_if_interrupted() const
    {
      if (system.all_processes(interrupt_signal() == 0))
        return;
      throw_if_interrupted("in a contact iteration");
      throw Interrupted("another process received a signal; stopped in a contact iteration");
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::prepare()
    {
      stats = ContactStatistics();
      seen_states.clear();
      line_search_on = false;
      if (!method || method_name != prm.method)
        {
          method = ContactMethodRegistry<dim>::instance().create(prm.method, "Mechanics/Solver");
          method_name = prm.method;
        }
      if (!linear_solver)
        {
          linear_solver = ContactLinearSolverRegistry<dim, System>::instance().create(
            System::linear_solver_name(prm),
            System::linear_solver_parameter,
            system,
            prm,
            progress,
            timer);
          stats.time_cholesky = linear_solver->statistics().time_cholesky;
          stats.time_form_W   = linear_solver->statistics().time_form_W;
        }
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::solve_linear_system(const FaceRows<dim>          &rows,
                                                    const std::vector<FaceState> &states,
                                                    const VectorType             &rhs,
                                                    VectorType                   &delta)
    {
      TimerOutput::Scope t(timer, "Mechanics: factorization and solve");
      unsigned int       changed = 0;
      if (!seen_states.empty())
        for (unsigned int fi = 0; fi < states.size(); ++fi)
          changed += (seen_states.back()[fi] != states[fi]);
      // Inexact steps: the linear residual follows the nonlinear one (Eisenstat-Walker's
      // choice 2 without safeguards), capped by the deck's tolerance.
      const double last = stats.residual_history.empty() ? 1. : stats.residual_history.back();
      linear_solver->set_tolerance(std::min(prm.linear_tolerance, prm.linear_forcing * last));
      linear_solver->solve(rows, changed, rhs, delta);
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::record_linear_statistics(const ContactLinearSolverStatistics &start)
    {
      const ContactLinearSolverStatistics &now = linear_solver->statistics();
      stats.factorizations                     = now.factorizations - start.factorizations;
      stats.reused_factorizations   = now.reused_factorizations - start.reused_factorizations;
      stats.linear_iterations       = now.linear_iterations - start.linear_iterations;
      stats.direct_fallbacks        = now.direct_fallbacks - start.direct_fallbacks;
      stats.fallback_factorizations = now.fallback_factorizations - start.fallback_factorizations;
      stats.direct_workspace_retries =
        now.direct_workspace_retries - start.direct_workspace_retries;
      stats.time_factorization = now.time_factorization - start.time_factorization;
      stats.time_solves        = now.time_solves - start.time_solves;
    }



    template <int dim, typename System>
    const ContactStatistics &
    ContactSolver<dim, System>::solve(VectorType &u, VectorType &lambda, const bool cold_start)
    {
      prepare();
      const ContactLinearSolverStatistics start = linear_solver->statistics();
      if (cold_start)
        set_initial_guess(u, lambda);
      const ResidualParts g0       = residual_parts(u, lambda, prm.c);
      const double        g0_norm2 = g0.mechanical + g0.contact_unscaled;
      // Continuation in c: the complementarity functions (25)-(26) have the same zeros for
      // every c > 0, so c may move from c_start to the target during the iterations.
      double     c_now = (prm.c_start > 0 ? prm.c_start : prm.c);
      VectorType rhs, delta, u_old(u), lambda_old(lambda);
      system.reinit_step(rhs);
      system.reinit_step(delta);
      FaceRows<dim> rows;
      rows.lambda.resize(system.n_faces());
      rows.jump.resize(system.n_faces());
      Timer clock;
      for (stats.iterations = 1; stats.iterations <= prm.max_iterations; ++stats.iterations)
        {
          stop_if_interrupted();
          std::vector<FaceState> states(system.n_faces());
          {
            TimerOutput::Scope t(timer, "Mechanics: contact update");
            clock.restart();
            linearize(u, lambda, c_now, rows, rhs, states);
            stats.time_contact_rows += clock.wall_time();
          }
          try
            {
              solve_linear_system(rows, states, rhs, delta);
            }
          catch (const InsufficientMemory &e)
            {
              throw InsufficientMemory(linear_failure_message(e.what()));
            }
          catch (const SolverFailure &e)
            {
              throw SolverFailure(linear_failure_message(e.what()));
            }
          const double alpha_max = cycle_damping_factor(states, stats.iterations);
          stats.face_state_history.push_back(state_counts(states));
          seen_states.push_back(states);

          TimerOutput::Scope t(timer, "Mechanics: contact update");
          clock.restart();
          u_old              = u;
          lambda_old         = lambda;
          const double alpha = take_step(u_old, lambda_old, delta, alpha_max, c_now, u, lambda);
          stats.step_history.push_back(alpha);
          const std::array<double, 3> terms = stopping_terms(u, lambda);
          const double                res   = std::max({terms[0], terms[1], terms[2]});
          stats.time_residuals += clock.wall_time();
          stats.residual_terms_history.push_back(terms);
          stats.residual_history.push_back(res);
          {
            const ResidualParts g = residual_parts(u, lambda, prm.c);
            stats.initial_relative_history.push_back(
              g0_norm2 > 0 ? std::sqrt((g.mechanical + g.contact_unscaled) / g0_norm2) : 0.);
          }
          record_linear_statistics(start);
          report_iteration(res, alpha, c_now);
          if (res <= prm.tolerance && c_now == prm.c)
            {
              stats.converged = true;
              return stats;
            }
          // Continuation: move c towards the target once the face states are those of the
          // previous iterate (the active set has settled for this c).
          if (c_now != prm.c && seen_states.size() > 1 &&
              same_states(seen_states[seen_states.size() - 2], states))
            c_now = (c_now < prm.c ? std::min(prm.c, c_now * prm.continuation_factor) :
                                     std::max(prm.c, c_now / prm.continuation_factor));
        }
      stats.iterations = prm.max_iterations;
      std::ostringstream s;
      s << "contact solver (" << prm.method << ") did not converge in " << prm.max_iterations
        << " iterations; last relative residual " << std::scientific << std::setprecision(3)
        << stats.residual_history.back();
      throw SolverFailure(s.str());
    }



    template <int dim, typename System>
    std::string
    ContactSolver<dim, System>::linear_failure_message(const std::string &reason) const
    {
      std::ostringstream s;
      s << "contact solver (" << prm.method << ") stopped in iteration " << stats.iterations << ": "
        << reason << "; last relative residual " << std::scientific << std::setprecision(3)
        << (stats.residual_history.empty() ? 1. : stats.residual_history.back());
      return s.str();
    }



    template <int dim, typename System>
    void
    ContactSolver<dim, System>::report_iteration(const double res,
                                                 const double alpha,
                                                 const double c_now)
    {
      progress << "    contact iteration " << stats.iterations << ": relative residual "
               << std::scientific << std::setprecision(3) << res << std::defaultfloat;
      if (alpha != 1)
        progress << ", step " << alpha;
      if (c_now != prm.c)
        progress << ", c = " << c_now;
      if (stats.linear_iterations > 0)
        progress << ", " << stats.linear_iterations << " linear iterations so far";
      progress << std::endl;
    }

    template class ContactSolver<2>;
    template class ContactSolver<3>;
    template class ContactSolver<2, DistributedElasticitySystem<2>>;
    template class ContactSolver<3, DistributedElasticitySystem<3>>;
  } // namespace mechanics
} // namespace porofrac
