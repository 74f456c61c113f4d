// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/interrupt.h>
#include <porofrac/flow/two_phase_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <numeric>
#include <sstream>

namespace porofrac
{
  namespace flow
  {
    namespace
    {
      /// Non-wetting saturation below which the phase counts as absent in the Jacobian (entry
      /// slope, virtual pore volume of massless nodes): S errors below it are round-off in the
      /// mass balance.
      constexpr double absent_saturation = 1e-12;
      /// The same with the capillary bound, which keeps p_c >= p_e and so sees S just above 0.
      constexpr double bound_absent_saturation = 1e-6;
    } // namespace

    template <int dim>
    TwoPhaseSolver<dim>::TwoPhaseSolver(const TpfaGrid<dim>           &grid,
                                        const std::array<RockType, 2> &rocks,
                                        const NewtonParameters        &parameters,
                                        const bool                     serial_pattern)
        : grid(grid)
        , rocks(rocks)
        , parameters(parameters)
    {
      number_unknowns({});
      if (serial_pattern)
        make_pattern({}, 0);
      virtual_pore_volume =
        1e-3 * total_pore_volume() / std::max(1u, grid.n_matrix_cells + grid.n_fracture_cells);
      linear_solver = create_serial_linear_solver(parameters.linear_solver, "Flow/Linear solver");
      storage       = std::make_shared<GridPorosity<dim>>(grid);
      state.assign(grid.n_nodes(), {{0., 0.}});
      begin_time_step();
    }

    template <int dim>
    void
    TwoPhaseSolver<dim>::number_unknowns(const std::vector<unsigned int> &node_owner)
    {
      // Unknowns process by process (node order within each): one contiguous range each.
      std::vector<unsigned int> order(grid.n_nodes());
      std::iota(order.begin(), order.end(), 0u);
      if (!node_owner.empty())
        std::stable_sort(order.begin(),
                         order.end(),
                         [&](const unsigned int a, const unsigned int b) {
                           return node_owner[a] < node_owner[b];
                         });
      node_dof.assign(grid.n_nodes(), numbers::invalid_unsigned_int);
      n_free = 0;
      for (const unsigned int i : order)
        if (!grid.is_dirichlet(i))
          node_dof[i] = n_free++;
    }



    template <int dim>
    void
    TwoPhaseSolver<dim>::make_pattern(const std::vector<unsigned int> &node_owner,
                                      const unsigned int               rank)
    {
      // The rows this process assembles (all of them without @p node_owner): a distributed
      // run keeps no pattern for the other processes' rows.
      const auto has_rows = [&](const unsigned int i) {
        return node_dof[i] != numbers::invalid_unsigned_int &&
               (node_owner.empty() || node_owner[i] == rank);
      };
      IndexSet rows(2 * n_free);
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        if (has_rows(i))
          rows.add_range(dof(i, 0), dof(i, 1) + 1);
      rows.compress();
      DynamicSparsityPattern dsp(2 * n_free, 2 * n_free, rows);
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        if (has_rows(i))
          for (unsigned int p = 0; p < 2; ++p)
            for (unsigned int q = 0; q < 2; ++q)
              dsp.add(dof(i, p), dof(i, q));
      for (const auto &c : grid.connections)
        if (node_dof[c.a] != numbers::invalid_unsigned_int &&
            node_dof[c.b] != numbers::invalid_unsigned_int)
          for (unsigned int p = 0; p < 2; ++p)
            for (unsigned int q = 0; q < 2; ++q)
              {
                if (has_rows(c.a))
                  dsp.add(dof(c.a, p), dof(c.b, q));
                if (has_rows(c.b))
                  dsp.add(dof(c.b, p), dof(c.a, q));
              }
      jacobian.clear();
      set_up_jacobian.clear();
      sparsity.copy_from(dsp);
      jacobian.reinit(sparsity);
    }



    template <int dim>
    void
    TwoPhaseSolver<dim>::distribute(const MPI_Comm                   communicator,
                                    const std::vector<unsigned int> &node_owner)
    {
      AssertDimension(node_owner.size(), grid.n_nodes());
      const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
      number_unknowns(node_owner);
      make_pattern(node_owner, rank);
      owned_node.assign(grid.n_nodes(), false);
      IndexSet owned(2 * n_free);
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        if (node_owner[i] == rank && node_dof[i] != numbers::invalid_unsigned_int)
          {
            owned_node[i] = true;
            owned.add_range(dof(i, 0), dof(i, 1) + 1);
          }
      owned.compress();
      distribution = std::make_unique<DistributedNewtonSystem>(communicator,
                                                               sparsity,
                                                               owned,
                                                               parameters.distributed_linear_solver,
                                                               parameters.max_linear_iterations,
                                                               parameters.amg);
    }



    template <int dim>
    void
    TwoPhaseSolver<dim>::begin_time_step()
    {
      old_state = state;
      old_pore_volume.resize(grid.n_nodes());
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        old_pore_volume[i] = pore_volume(old_state, i);
    }

    template <int dim>
    void
    TwoPhaseSolver<dim>::set_storage_model(const std::shared_ptr<const StorageModel> &model)
    {
      AssertThrow(model != nullptr, ExcMessage("TwoPhaseSolver needs a storage model"));
      storage = model;
    }

    template <int dim>
    double
    TwoPhaseSolver<dim>::pore_volume(const State &s, const unsigned int i) const
    {
      std::array<double, 2> d;
      return pore_volume(s, i, d);
    }

    template <int dim>
    double
    TwoPhaseSolver<dim>::pore_volume(const State           &s,
                                     const unsigned int     i,
                                     std::array<double, 2> &d) const
    {
      if (i >= grid.n_matrix_cells)
        {
          d = {{0., 0.}};
          return grid.pore_volume(i);
        }
      return storage->pore_volume(i, pressure(s, i, 0), s[i][1] - s[i][0], d);
    }

    template <int dim>
    EnergyExchange
    TwoPhaseSolver<dim>::energy_exchange(const State &s, const double dt) const
    {
      EnergyExchange        e;
      std::array<double, 4> d;
      for (const auto &c : grid.connections)
        {
          const bool da = grid.is_dirichlet(c.a), db = grid.is_dirichlet(c.b);
          if (da && db)
            continue;
          for (unsigned int phase = 0; phase < 2; ++phase)
            {
              const double F = flux(c, s, phase, d); // a -> b
              if (!da && !db)
                e.dissipation += dt * F * (s[c.a][phase] - s[c.b][phase]);
              else if (db)
                e.boundary_work -= dt * F * (s[c.b][phase] + reference_pressure);
              else // Dirichlet node a: the flux into it from b is -F.
                e.boundary_work += dt * F * (s[c.a][phase] + reference_pressure);
            }
        }
      // Sources supply dt |K| h^alpha p^alpha.
      if (!source.empty())
        for (unsigned int i = 0; i < grid.n_nodes(); ++i)
          if (!grid.is_dirichlet(i))
            for (unsigned int phase = 0; phase < 2; ++phase)
              e.boundary_work += dt * source[i][phase] * (s[i][phase] + reference_pressure);
      return e;
    }

    template <int dim>
    void
    TwoPhaseSolver<dim>::apply_dirichlet(State &s) const
    {
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        if (grid.is_dirichlet(i))
          {
            const auto &table = grid.nodes[i].kind == TpfaGrid<dim>::NodeKind::dirichlet_matrix ?
                                  matrix_dirichlet :
                                  fracture_dirichlet;
            const auto  it    = table.find(grid.nodes[i].boundary_id);
            Assert(it != table.end(), ExcInternalError());
            s[i] = {{it->second[0] - reference_pressure, it->second[1] - reference_pressure}};
          }
    }

    template <int dim>
    double
    TwoPhaseSolver<dim>::flux(const typename TpfaGrid<dim>::Connection &c,
                              const State                              &s,
                              const unsigned int                        phase,
                              std::array<double, 4>                    &derivative) const
    {
      const double       delta    = s[c.a][phase] - s[c.b][phase];
      const bool         up_a     = delta >= 0;
      const unsigned int e        = up_a ? c.a : c.b;
      const RockType    &rock     = rocks[up_a ? c.rock_a : c.rock_b];
      const double       pc       = s[e][1] - s[e][0];
      const double       S        = rock.saturation->saturation(pc);
      const double       eta      = rock.mobility(phase, S);
      const double       deta_dpc = rock.mobility_derivative(phase, S) * slope(rock, pc);
      const double       T        = c.transmissibility;
      derivative                  = {{0., 0., 0., 0.}};
      derivative[phase] += T * eta;
      derivative[2 + phase] -= T * eta;
      const unsigned int o = up_a ? 0 : 2;
      derivative[o + 1] += T * delta * deta_dpc;
      derivative[o + 0] -= T * delta * deta_dpc;
      return T * eta * delta;
    }

    template <int dim>
    void
    TwoPhaseSolver<dim>::assemble(const State          &s,
                                  const State          &old,
                                  const double          dt,
                                  Vector<double>       &residual,
                                  SparseMatrix<double> *J) const
    {
      residual.reinit(2 * n_free);
      if (J)
        *J = 0;
      // Accumulation (PV S)^{n+1} - PV_old S^n (scheme (11a)), PV with the Biot storage (11d).
      std::array<double, 2>     dPV;
      std::vector<unsigned int> massless;
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        {
          if (node_dof[i] == numbers::invalid_unsigned_int || !assembles(i))
            continue;
          if (J)
            hold_absent_wetting_pressure(s, i, *J);
          const double PV = pore_volume(s, i, dPV), PV_old = old_pore_volume[i];
          if (PV == 0 && PV_old == 0)
            {
              if (J)
                massless.push_back(i);
              // Massless node where the non-wetting phase is absent (with the entry slope active
              // or the capillary bound), where the phase's mobilities can all vanish: a
              // Jacobian-only virtual pore volume keeps its rows non-singular. Above the absent
              // saturation the Jacobian stays exact (quadratic convergence).
              const SaturationLaw &law    = *rocks[grid.nodes[i].rock].saturation;
              const double         pc     = s[i][1] - s[i][0];
              const bool           absent = parameters.capillary_bound ?
                                              law.saturation(pc) < bound_absent_saturation :
                                              entry_slope_replaces_tangent(law, pc);
              if (!(J && absent))
                continue;
              const double dS  = slope(rocks[grid.nodes[i].rock], pc);
              const double PVv = virtual_pore_volume;
              J->add(dof(i, 1), dof(i, 1), PVv * dS);
              J->add(dof(i, 1), dof(i, 0), -PVv * dS);
              J->add(dof(i, 0), dof(i, 1), -PVv * dS);
              J->add(dof(i, 0), dof(i, 0), PVv * dS);
              continue;
            }
          const RockType &rock  = rocks[grid.nodes[i].rock];
          const double    pc    = s[i][1] - s[i][0];
          const double    S     = rock.saturation->saturation(pc);
          const double    S_old = rock.saturation->saturation(old[i][1] - old[i][0]);
          const double    dSdpc = slope(rock, pc);
          residual(dof(i, 1)) += PV * S - PV_old * S_old;
          residual(dof(i, 0)) += PV * (1. - S) - PV_old * (1. - S_old);
          if (J)
            {
              // d/dp^w and d/dp^nw: dS/dp^w = -S', dS/dp^nw = S'.
              J->add(dof(i, 1), dof(i, 0), dPV[0] * S - PV * dSdpc);
              J->add(dof(i, 1), dof(i, 1), dPV[1] * S + PV * dSdpc);
              J->add(dof(i, 0), dof(i, 0), dPV[0] * (1. - S) + PV * dSdpc);
              J->add(dof(i, 0), dof(i, 1), dPV[1] * (1. - S) - PV * dSdpc);
            }
        }
      // Sources |K| h^alpha (scheme (11a)), on the right-hand side.
      if (!source.empty())
        for (unsigned int i = 0; i < grid.n_nodes(); ++i)
          if (node_dof[i] != numbers::invalid_unsigned_int && assembles(i))
            for (unsigned int phase = 0; phase < 2; ++phase)
              residual(dof(i, phase)) -= dt * source[i][phase];
      // Fluxes.
      std::array<double, 4> d;
      for (const auto &c : grid.connections)
        if (assembles(c.a) || assembles(c.b))
          for (unsigned int phase = 0; phase < 2; ++phase)
            {
              const double                      F    = dt * flux(c, s, phase, d);
              const std::array<unsigned int, 2> rows = {{dof(c.a, phase), dof(c.b, phase)}};
              const std::array<unsigned int, 4> cols = {
                {dof(c.a, 0), dof(c.a, 1), dof(c.b, 0), dof(c.b, 1)}};
              for (unsigned int r = 0; r < 2; ++r)
                {
                  if (rows[r] == numbers::invalid_unsigned_int || !assembles(r == 0 ? c.a : c.b))
                    continue;
                  const double sign = (r == 0 ? 1. : -1.);
                  residual(rows[r]) += sign * F;
                  if (J)
                    for (unsigned int k = 0; k < 4; ++k)
                      if (cols[k] != numbers::invalid_unsigned_int && d[k] != 0)
                        J->add(rows[r], cols[k], sign * dt * d[k]);
                }
            }
      if (J)
        hold_unheld_massless_pressures(massless, *J);
      if (distribution)
        distribution->sum(residual);
    }

    namespace
    {
      /// The p_c closest to @p pc_new such that |S(p_c) - S(pc_old)| <= max_change.
      double
      limit_saturation_change(const SaturationLaw &law,
                              const double         pc_old,
                              const double         pc_new,
                              const double         max_change)
      {
        const double S_old = law.saturation(pc_old), S_new = law.saturation(pc_new);
        if (std::abs(S_new - S_old) <= max_change)
          return pc_new;
        const double S_target = S_new > S_old ? S_old + max_change : S_old - max_change;
        // S_target lies strictly between S_old and S_new, so in [0, 1).
        return law.inverse(std::min(std::max(S_target, 0.), 1. - 1e-16), "Flow/Saturation chop");
      }
    } // namespace

    template <int dim>
    void
    TwoPhaseSolver<dim>::hold_absent_wetting_pressure(const State          &s,
                                                      const unsigned int    i,
                                                      SparseMatrix<double> &J) const
    {
      // Where the wetting phase is absent (S^nw = 1 to round-off, S' = 0) and immobile (k_r^w = 0
      // without a mobility floor), no equation holds p^w: its mass PV (1 - S) and all its fluxes
      // vanish for every nearby p^w. A Jacobian-only virtual compressibility fixes the Newton
      // update of p^w there; the residual is unchanged.
      const RockType &rock = rocks[grid.nodes[i].rock];
      const double    S    = rock.saturation->saturation(s[i][1] - s[i][0]);
      if (1. - S >= absent_saturation || rock.mobility(0, S) != 0)
        return;
      const double PVv = std::max(grid.pore_volume(i), virtual_pore_volume);
      J.add(dof(i, 0), dof(i, 0), PVv / rock.saturation->pressure_scale());
    }

    template <int dim>
    void
    TwoPhaseSolver<dim>::hold_unheld_massless_pressures(const std::vector<unsigned int> &massless,
                                                        SparseMatrix<double>            &J) const
    {
      // A massless node downstream on every connection of neighbours without the phase's
      // mobility: its p^alpha enters the Jacobian only through the neighbours' mobility
      // derivatives, and the row has no pivot of its own. The virtual compressibility of
      // hold_absent_wetting_pressure regularizes it; the residual is unchanged.
      for (const unsigned int i : massless)
        for (unsigned int phase = 0; phase < 2; ++phase)
          if (J.diag_element(dof(i, phase)) == 0)
            J.add(dof(i, phase),
                  dof(i, phase),
                  virtual_pore_volume / rocks[grid.nodes[i].rock].saturation->pressure_scale());
    }

    template <int dim>
    bool
    TwoPhaseSolver<dim>::entry_slope_applies() const
    {
      return parameters.capillary_bound || (parameters.entry_slope && entry_slope_active);
    }

    template <int dim>
    bool
    TwoPhaseSolver<dim>::entry_slope_replaces_tangent(const SaturationLaw &law,
                                                      const double         pc) const
    {
      return entry_slope_applies() && law.saturation(pc) < absent_saturation &&
             law.derivative(pc) < 0.5 * law.entry_slope();
    }

    template <int dim>
    double
    TwoPhaseSolver<dim>::slope(const RockType &rock, const double pc) const
    {
      // Where the non-wetting phase is absent (S < absent_saturation, p_c <= p_e included) and
      // the tangent is below half the law's entry slope, the Jacobian uses the entry slope: an
      // inexact Newton that lets an absent phase enter and keeps its pressure in an equation
      // (van Genuchten: S' -> 0 as p_c -> 0+). Corey and Brooks-Corey keep S' there (S' is
      // above half the entry slope where S < absent_saturation). The residual is unchanged.
      const SaturationLaw &law = *rock.saturation;
      return entry_slope_replaces_tangent(law, pc) ? law.entry_slope() : law.derivative(pc);
    }

    template <int dim>
    double
    TwoPhaseSolver<dim>::total_pore_volume() const
    {
      double V = 0;
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        V += grid.pore_volume(i);
      return V;
    }

    template <int dim>
    std::array<double, 2>
    TwoPhaseSolver<dim>::phase_volumes(const State &s) const
    {
      std::array<double, 2> m{{0., 0.}};
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        if (!grid.is_dirichlet(i))
          {
            const double S  = saturation(s, i, grid.nodes[i].rock);
            const double PV = pore_volume(s, i);
            m[1] += PV * S;
            m[0] += PV * (1. - S);
          }
      return m;
    }

    template <int dim>
    std::array<double, 2>
    TwoPhaseSolver<dim>::mass_defect(const State &s, const State &old, const double dt) const
    {
      const auto            m_new = phase_volumes(s);
      std::array<double, 2> m_old{{0., 0.}};
      double                V = 0;
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        if (!grid.is_dirichlet(i))
          {
            const double S = saturation(old, i, grid.nodes[i].rock);
            m_old[1] += old_pore_volume[i] * S;
            m_old[0] += old_pore_volume[i] * (1. - S);
            V += old_pore_volume[i];
          }
      std::array<double, 2> outflow{{0., 0.}}, throughput{{0., 0.}};
      std::array<double, 4> d;
      for (const auto &c : grid.connections)
        {
          const bool da = grid.is_dirichlet(c.a), db = grid.is_dirichlet(c.b);
          if (da == db)
            continue;
          for (unsigned int phase = 0; phase < 2; ++phase)
            {
              const double F = (db ? 1. : -1.) * dt * flux(c, s, phase, d);
              outflow[phase] += F;
              throughput[phase] += std::abs(F);
            }
        }
      // Sources add volume: m_new - m_old = dt sum |K| h - outflow.
      if (!source.empty())
        for (unsigned int i = 0; i < grid.n_nodes(); ++i)
          if (!grid.is_dirichlet(i))
            for (unsigned int phase = 0; phase < 2; ++phase)
              {
                outflow[phase] -= dt * source[i][phase];
                throughput[phase] += std::abs(dt * source[i][phase]);
              }
      // Relative to the larger of the pore volume and the volume that crossed the boundary.
      return {{std::abs(m_new[0] - m_old[0] + outflow[0]) / std::max(V, throughput[0]),
               std::abs(m_new[1] - m_old[1] + outflow[1]) / std::max(V, throughput[1])}};
    }

    template <int dim>
    bool
    TwoPhaseSolver<dim>::stagnation_fallback_holds(const double mass_defect,
                                                   const double update) const
    {
      const double mass_bound = parameters.stagnation_mass_tolerance > 0 ?
                                  parameters.stagnation_mass_tolerance :
                                  parameters.mass_tolerance;
      return parameters.stagnation_iterations > 0 && mass_defect < mass_bound &&
             update < parameters.stagnation_update_tolerance;
    }

    template <int dim>
    double
    TwoPhaseSolver<dim>::capillary_chop_limit(const unsigned int i) const
    {
      // Appleyard-type chop: the capillary pressure of a node changes by at most capillary_chop
      // times the pressure scale of its saturation law per iteration. Interface nodes carry both
      // laws (matrix on the cell side): the larger scale.
      const bool   interface = grid.nodes[i].kind == TpfaGrid<dim>::NodeKind::interface;
      const double scale     = interface ? std::max(rocks[matrix_rock].saturation->pressure_scale(),
                                                rocks[fracture_rock].saturation->pressure_scale()) :
                                           rocks[grid.nodes[i].rock].saturation->pressure_scale();
      return parameters.capillary_chop * scale;
    }



    template <int dim>
    double
    TwoPhaseSolver<dim>::limit_capillary_change(const unsigned int i,
                                                const double       pc_old,
                                                double             dpc,
                                                const double       lim) const
    {
      const bool           interface = grid.nodes[i].kind == TpfaGrid<dim>::NodeKind::interface;
      const SaturationLaw &law       = *rocks[grid.nodes[i].rock].saturation;
      if (lim > 0 && std::abs(dpc) > lim)
        dpc = dpc > 0 ? lim : -lim;
      // Stop at the kink of S at p_c = p_e when leaving the two-phase region.
      const double p_e = law.entry_pressure();
      if (parameters.kink_stop && pc_old > p_e && pc_old + dpc < p_e)
        dpc = -(pc_old - p_e);
      // Entering: the entry-slope linearization is about p_c = p_e, so a node with p_c < p_e that
      // the Newton step pushes up starts from the kink.
      if (parameters.entry_slope && pc_old < p_e && dpc > 0)
        dpc -= pc_old - p_e;
      // Bound: p_c >= p_e (the non-wetting pressure of a saturated node is p^w + p_e).
      if (parameters.capillary_bound && pc_old + dpc < p_e)
        dpc = -(pc_old - p_e);
      // Saturation chop: |Delta S| <= saturation_chop under the node's law (both laws at
      // interface nodes, whose matrix-side mobility uses the matrix law).
      if (parameters.saturation_chop > 0)
        {
          double pc_new = pc_old + dpc;
          for (unsigned int r = 0; r < 2; ++r)
            if (interface || r == grid.nodes[i].rock)
              pc_new = limit_saturation_change(*rocks[r].saturation,
                                               pc_old,
                                               pc_new,
                                               parameters.saturation_chop);
          dpc = pc_new - pc_old;
        }
      return dpc;
    }

    template <int dim>
    void
    TwoPhaseSolver<dim>::report_largest_residual(const Vector<double> &residual,
                                                 ConditionalOStream   &verbose) const
    {
      // Where the residual is largest: which node and phase hold Newton back.
      unsigned int imax = 0, ph = 0;
      double       rmax = 0;
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        for (unsigned int a = 0; a < 2; ++a)
          if (dof(i, a) != numbers::invalid_unsigned_int && std::abs(residual(dof(i, a))) > rmax)
            {
              rmax = std::abs(residual(dof(i, a)));
              imax = i;
              ph   = a;
            }
      verbose << "        largest residual " << residual(dof(imax, ph)) << " (phase " << ph
              << ") at node " << imax << " (kind " << static_cast<int>(grid.nodes[imax].kind)
              << ", p_w = " << pressure(state, imax, 0)
              << ", p_c = " << state[imax][1] - state[imax][0]
              << ", old p_c = " << old_state[imax][1] - old_state[imax][0] << ")" << std::endl;
    }



    template <int dim>
    bool
    TwoPhaseSolver<dim>::solve_linear_system(const Vector<double> &residual,
                                             Vector<double>       &update,
                                             const double          tolerance,
                                             std::string          &failure)
    {
      std::unique_ptr<TimerOutput::Scope> t;
      if (timer)
        t =
          std::make_unique<TimerOutput::Scope>(*timer,
                                               "Flow: linear solve (" + linear_solver_name() + ")");
      // A singular or failed factorisation is a failed step (converged = false): the caller
      // cuts the time step. Only a factorisation refused for lack of memory stops the run.
      const bool reuse = jacobian_unchanged();
      reused_setups += reuse;
      try
        {
          if (distribution)
            distribution->solve(jacobian, residual, update, tolerance, reuse);
          else
            {
              if (!reuse)
                linear_solver->initialize(jacobian);
              linear_solver->solve(residual, update, tolerance);
            }
        }
      catch (const InsufficientMemory &e)
        {
          // A shorter time step needs the same memory.
          throw InsufficientMemory("two-phase flow: " + std::string(e.what()));
        }
      catch (const SolverFailure &e)
        {
          set_up_jacobian.clear();
          failure = "linear solver failed (" + std::string(e.what()) + ")";
          return false;
        }
      return true;
    }



    template <int dim>
    bool
    TwoPhaseSolver<dim>::jacobian_unchanged()
    {
      // Compares with the kept values and keeps the new ones in one pass.
      bool same = set_up_jacobian.size() == jacobian.n_nonzero_elements();
      set_up_jacobian.resize(jacobian.n_nonzero_elements());
      auto kept = set_up_jacobian.begin();
      for (const auto &entry : jacobian)
        {
          same    = same && *kept == entry.value();
          *kept++ = entry.value();
        }
      return distribution ? distribution->all_processes(same) : same;
    }



    template <int dim>
    double
    TwoPhaseSolver<dim>::apply_update(const Vector<double> &update,
                                      ConditionalOStream   &verbose,
                                      unsigned int         &n_capillary_chopped)
    {
      double       p_max = 0, du_max = 0;
      unsigned int argmax = 0, n_kink_crossings = 0, n_chopped = 0;
      n_capillary_chopped = 0;
      for (unsigned int i = 0; i < grid.n_nodes(); ++i)
        if (!grid.is_dirichlet(i))
          {
            const std::array<double, 2> dp     = {{-update(dof(i, 0)), -update(dof(i, 1))}};
            const double                pc_old = state[i][1] - state[i][0];
            const double                lim    = capillary_chop_limit(i);
            const double                dpc = limit_capillary_change(i, pc_old, dp[1] - dp[0], lim);
            // Keep the update of the phase that fills most of the node's pores (the one whose
            // pressure the fluxes determine best); the other follows from p_c.
            const SaturationLaw &law         = *rocks[grid.nodes[i].rock].saturation;
            const bool           nw_dominant = law.saturation(pc_old) > 0.5;
            const double         dpw         = nw_dominant ? dp[1] - dpc : dp[0];
            state[i][0] += dpw;
            state[i][1] += dpw + dpc;
            for (unsigned int phase = 0; phase < 2; ++phase)
              p_max = std::max(p_max, std::abs(state[i][phase] + reference_pressure));
            const double du = std::max(std::abs(dpw), std::abs(dpw + dpc));
            if (du > du_max)
              {
                du_max = du;
                argmax = i;
              }
            const double p_e = law.entry_pressure();
            if ((pc_old > p_e) != (pc_old + dpc > p_e))
              ++n_kink_crossings;
            if (std::abs(dpc - (dp[1] - dp[0])) > 1e-12 * std::abs(dp[1] - dp[0]))
              ++n_chopped;
            if (lim > 0 && std::abs(dp[1] - dp[0]) > lim)
              ++n_capillary_chopped;
          }
      static const char *kinds[] = {
        "matrix", "fracture", "interface", "intersection", "dirichlet", "dirichlet"};
      verbose << "        largest update at " << kinds[static_cast<int>(grid.nodes[argmax].kind)]
              << " node " << argmax << " (p_c = " << state[argmax][1] - state[argmax][0]
              << ", S = " << saturation(state, argmax, grid.nodes[argmax].rock) << "), "
              << n_kink_crossings << " nodes crossed p_c = p_e, " << n_chopped << " chopped"
              << std::endl;
      return du_max / std::max(p_max, 1e-300);
    }



    template <int dim>
    bool
    TwoPhaseSolver<dim>::line_search(const State        &previous,
                                     const double        r,
                                     const double        dt,
                                     ConditionalOStream &verbose)
    {
      // Backtracking: halve the (chopped) update while it increases |R|. This breaks the
      // two-cycles that the unbounded slope of the van Genuchten-Mualem k_r^w at S^nw = 0
      // causes at drying fronts; the projections of apply_update() commute with the damping
      // (p_c >= 0 and |Delta S| bounds hold on the segment).
      std::unique_ptr<TimerOutput::Scope> t;
      if (timer)
        t = std::make_unique<TimerOutput::Scope>(*timer, "Flow: assembly");
      const State    full      = state;
      double         theta     = 1.;
      bool           decreased = false;
      Vector<double> trial;
      for (unsigned int k = 0; k < parameters.line_search_steps; ++k)
        {
          assemble(state, old_state, dt, trial, nullptr);
          if (trial.l2_norm() <= r)
            {
              decreased = true;
              break;
            }
          theta *= 0.5;
          for (unsigned int i = 0; i < grid.n_nodes(); ++i)
            for (unsigned int phase = 0; phase < 2; ++phase)
              state[i][phase] = previous[i][phase] + theta * (full[i][phase] - previous[i][phase]);
        }
      // The relative update stays the undamped Newton update: a damped step is no sign of
      // convergence.
      if (theta < 1.)
        verbose << "        line search: step " << theta << std::endl;
      return decreased;
    }



    template <int dim>
    StepResult
    TwoPhaseSolver<dim>::solve_time_step(const double dt, ConditionalOStream &verbose)
    {
      StepResult     result;
      Vector<double> residual, update(2 * n_free);
      double         r0          = 0;
      double         last_update = std::numeric_limits<double>::infinity();
      double best_residual = std::numeric_limits<double>::infinity(), best_mass = best_residual;
      unsigned int last_progress = 0, n_capillary_chopped = 0;
      apply_dirichlet(state);
      if (parameters.capillary_bound)
        for (unsigned int i = 0; i < grid.n_nodes(); ++i)
          if (!grid.is_dirichlet(i))
            state[i][1] =
              std::max(state[i][1],
                       state[i][0] + rocks[grid.nodes[i].rock].saturation->entry_pressure());
      for (unsigned int it = 0; it <= parameters.max_iterations; ++it)
        {
          // Every process stops at the same iteration (a signal may reach one first).
          if (distribution && !distribution->all_processes(interrupt_signal() == 0))
            throw Interrupted("SIGINT or SIGTERM received; stopped in a flow Newton iteration");
          throw_if_interrupted("in a flow Newton iteration");
          // A non-finite state (initial guess or diverged update) is a failed step.
          for (const auto &p : state)
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
              {
                result.failure = "non-finite pressures";
                return result;
              }
          // Entry slope for the first iterations only, exact Jacobian afterwards.
          entry_slope_active = it < parameters.entry_slope_iterations;
          {
            std::unique_ptr<TimerOutput::Scope> t;
            if (timer)
              t = std::make_unique<TimerOutput::Scope>(*timer, "Flow: assembly");
            Assert(sparsity.n_rows() == 2 * n_free,
                   ExcMessage("no Newton matrix: a solver built without its serial pattern "
                              "needs distribute()"));
            assemble(state, old_state, dt, residual, &jacobian);
          }
          entry_slope_active = false;
          const double r     = residual.l2_norm();
          if (!std::isfinite(r))
            {
              result.failure = "non-finite residual";
              return result;
            }
          if (it == 0)
            r0 = std::max(r, residual_scale);
          result.mass_defect = mass_defect(state, old_state, dt);
          const bool mass_ok = result.mass_defect[0] < parameters.mass_tolerance &&
                               result.mass_defect[1] < parameters.mass_tolerance;
          if (verbose.is_active())
            report_largest_residual(residual, verbose);
          verbose << "      Newton " << it << ": |R| = " << std::scientific << std::setprecision(3)
                  << r << ", update " << last_update << ", mass defect "
                  << std::max(result.mass_defect[0], result.mass_defect[1]) << std::defaultfloat
                  << std::endl;
          if (mass_ok && (r == 0 || r < parameters.residual_tolerance * r0 ||
                          last_update < parameters.update_tolerance))
            {
              result.converged  = true;
              result.iterations = it;
              return result;
            }
          const double mass = std::max(result.mass_defect[0], result.mass_defect[1]);
          // An iteration whose update the capillary chop limited advances by design: a node whose
          // p_c must cross many multiples of its Corey R (a gas-filled fracture cell next to a
          // water inlet) needs that many iterations with |R| hardly changed. Not stagnation.
          if (r < 0.5 * best_residual || mass < 0.5 * best_mass || n_capillary_chopped > 0)
            last_progress = it;
          best_residual = std::min(best_residual, r);
          best_mass     = std::min(best_mass, mass);
          if (it == parameters.max_iterations)
            {
              result.failure = "no convergence in " + std::to_string(it) + " iterations";
              break;
            }
          if (parameters.stagnation_iterations > 0 &&
              it >= last_progress + parameters.stagnation_iterations)
            {
              if (stagnation_fallback_holds(mass, last_update))
                {
                  verbose
                    << "      Newton: stagnated within the fallback update tolerance, accepted"
                    << std::endl;
                  result.converged  = true;
                  result.iterations = it;
                  return result;
                }
              std::ostringstream msg;
              msg << "stagnation: neither |R| (" << r << ") nor the mass defect (" << mass
                  << ") halved in " << parameters.stagnation_iterations << " iterations";
              result.failure = msg.str();
              break;
            }
          // Inexact Newton: the linear residual shrinks with the nonlinear one.
          const double tolerance =
            std::max(1e-12,
                     std::min(parameters.linear_tolerance, parameters.linear_forcing * r / r0));
          if (!solve_linear_system(residual, update, tolerance, result.failure))
            return result;
          const State  previous        = parameters.line_search ? state : State();
          const double previous_update = last_update;
          last_update                  = apply_update(update, verbose, n_capillary_chopped);
          if (!std::isfinite(last_update))
            {
              result.failure = "non-finite update";
              return result;
            }
          if (parameters.line_search && !line_search(previous, r, dt, verbose) &&
              stagnation_fallback_holds(mass, previous_update))
            {
              // No damping of the Newton direction lowers |R|: the iterate sits on a kink (of
              // S, of k_r or of the upwinding) and further iterations cycle around it. The
              // state before the step meets the stagnation fallback (mass defect and the update
              // that led to it): it is the answer. Otherwise iterate on, and the stagnation
              // counter decides.
              state = previous;
              verbose << "      Newton: no descent along the Newton direction within the "
                         "fallback update tolerance, accepted"
                      << std::endl;
              result.converged  = true;
              result.iterations = it + 1;
              return result;
            }
          result.iterations = it + 1;
        }
      return result;
    }

    template class TwoPhaseSolver<2>;
    template class TwoPhaseSolver<3>;
  } // namespace flow
} // namespace porofrac
