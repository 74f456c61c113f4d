// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/base/mpi_tools.h>
#include <porofrac/mechanics/coupling_entry.h>
#include <porofrac/mechanics/distributed_elasticity_system.h>
#include <porofrac/mechanics/elasticity_assembly.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      /// One side of the coupling of a fracture face, computed by the owner of the side's cell.
      struct SideCoupling
      {
        unsigned int                                                       face;
        bool                                                               plus;
        double                                                             measure;
        std::map<std::pair<types::global_dof_index, unsigned int>, double> entries;
      };

      /// The sides of the fracture faces whose cells this process owns.
      template <int dim>
      std::vector<SideCoupling>
      owned_sides(const geometry::DistributedCutMesh<dim> &mesh,
                  const DoFHandler<dim>                   &dof_handler,
                  const FESystem<dim>                     &fe,
                  const bool                               axisymmetric)
      {
        const QGaussSimplex<dim - 1> quadrature(3);
        FEFaceValues<dim>            fe_face(mesh.mapping(),
                                  fe,
                                  quadrature,
                                  update_values | update_quadrature_points | update_JxW_values);
        std::vector<SideCoupling>    sides;
        for (const auto &face : mesh.serial.fracture_faces)
          for (const geometry::Side side : {geometry::plus, geometry::minus})
            if (mesh.owns_side(face.index, side))
              {
                const auto local = mesh.local_cell(face.cell[side]);
                const typename DoFHandler<dim>::active_cell_iterator cell(&mesh.triangulation,
                                                                          local->level(),
                                                                          local->index(),
                                                                          &dof_handler);
                SideCoupling s{face.index, side == geometry::plus, 0., {}};
                s.measure = add_side_coupling(axisymmetric,
                                              fe,
                                              fe_face,
                                              cell,
                                              face.face_no[side],
                                              side == geometry::plus ? 1. : -1.,
                                              s.entries);
                sides.push_back(std::move(s));
              }
        return sides;
      }

      /// A Trilinos matrix with rows @p rows (this process writes @p writable_rows) and columns
      /// @p columns, with the entries @p add puts into a DynamicSparsityPattern.
      template <typename Fill>
      void
      make_matrix(TrilinosWrappers::SparseMatrix &matrix,
                  const IndexSet                 &rows,
                  const IndexSet                 &columns,
                  const IndexSet                 &writable_rows,
                  const MPI_Comm                  communicator,
                  const Fill                     &add)
      {
        DynamicSparsityPattern dsp(rows.size(), columns.size(), writable_rows);
        add(dsp);
        // No rows (a mesh without fracture faces has no multipliers): nothing to send, and
        // deal.II's index-owner dictionary divides by the index space's size.
        if (rows.size() > 0)
          SparsityTools::distribute_sparsity_pattern(dsp, rows, communicator, writable_rows);
        matrix.reinit(rows, columns, dsp, communicator);
      }
    } // namespace



    template <int dim>
    DistributedElasticitySystem<dim>::DistributedElasticitySystem(
      const geometry::DistributedCutMesh<dim> &mesh,
      const ContactParameters                 &parameters,
      TimerOutput                             &timer)
        : mesh(mesh)
        , prm(parameters)
        , timer(timer)
        , fe(FE_SimplexP<dim>(2), dim)
        , dof_handler(mesh.triangulation)
    {
      prm.validate(dim);
      if (prm.axisymmetric)
        for (const auto &v : mesh.serial.triangulation.get_vertices())
          check_input(v[1] >= 0,
                      "Mechanics/Axisymmetric",
                      "the radial section must lie in r = y >= 0");
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::setup()
    {
      TimerOutput::Scope t(timer, "Mechanics: setup");
      const MPI_Comm     comm = get_communicator();
      dof_handler.distribute_dofs(fe);
      owned_u = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_u);
      owned_lambda = IndexSet(dim * n_faces());
      for (const unsigned int f : mesh.locally_owned_faces())
        owned_lambda.add_range(dim * f, dim * (f + 1));
      owned_lambda.compress();
      stabilization            = make_multiplier_stabilization(mesh.serial, prm);
      IndexSet relevant_lambda = owned_lambda;
      for (const unsigned int f : mesh.locally_owned_faces())
        for (unsigned int n = 0; !stabilization.empty() && n < stabilization[f].size(); ++n)
          relevant_lambda.add_range(dim * stabilization[f][n].first,
                                    dim * (stabilization[f][n].first + 1));
      relevant_lambda.compress();
      neighbour_lambda.reinit(owned_lambda, relevant_lambda, comm);
      owned_all = IndexSet(n_dofs());
      owned_all.add_indices(owned_u);
      owned_all.add_indices(owned_lambda, dof_handler.n_dofs());
      owned_all.compress();
      make_constraints();
      make_matrix(
        K_constrained, owned_u, owned_u, relevant_u, comm, [&](DynamicSparsityPattern &dsp) {
          DoFTools::make_sparsity_pattern(dof_handler, dsp);
        });
      make_matrix(K_boundary, owned_u, owned_u, relevant_u, comm, [&](auto &dsp) {
        std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && has_constrained_dofs(cell, local))
            for (const auto i : local)
              for (const auto j : local)
                dsp.add(i, j);
      });
      make_coupling();
      assemble();
    }



    template <int dim>
    bool
    DistributedElasticitySystem<dim>::has_constrained_dofs(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      std::vector<types::global_dof_index>                 &local) const
    {
      cell->get_dof_indices(local);
      return std::any_of(local.begin(), local.end(), [&](const auto i) {
        return constraints_hom.is_constrained(i);
      });
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::make_constraints()
    {
      // The tolerance of the serial system: from the bounding box of the whole mesh.
      const auto   box = GridTools::compute_bounding_box(mesh.serial.triangulation);
      const double tol =
        1e-8 * box.get_boundary_points().first.distance(box.get_boundary_points().second);
      const MPI_Comm comm = get_communicator();
      for (AffineConstraints<double> *target : {&constraints, &constraints_hom})
        {
          target->clear();
          target->reinit(relevant_u);
          std::vector<unsigned int> hits;
          collectively(comm, [&]() {
            hits = add_displacement_constraints(
              prm, mesh.serial, dof_handler, tol, target == &constraints_hom, *target);
          });
          Utilities::MPI::sum(hits, comm, hits);
          const bool any = Utilities::MPI::sum(target->n_constraints(), comm) > 0;
          check_displacement_constraints(prm, hits, any);
          target->close();
        }
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::make_coupling()
    {
      const MPI_Comm                  comm  = get_communicator();
      const std::vector<SideCoupling> sides = owned_sides(mesh, dof_handler, fe, prm.axisymmetric);
      IndexSet                        writable_lambda(dim * n_faces());
      face_measures.assign(n_faces(), 0.);
      for (const SideCoupling &s : sides)
        {
          writable_lambda.add_range(dim * s.face, dim * (s.face + 1));
          if (s.plus)
            face_measures[s.face] = s.measure;
        }
      writable_lambda.compress();
      const auto free = [&](const types::global_dof_index dof) {
        return !constraints_hom.is_constrained(dof);
      };
      const auto fill = [&](DynamicSparsityPattern &dsp, const bool transpose) {
        for (const SideCoupling &s : sides)
          for (const auto &[key, value] : s.entries)
            if (transpose)
              dsp.add(key.first, dim * s.face + key.second);
            else
              dsp.add(dim * s.face + key.second, key.first);
      };
      make_matrix(coupling, owned_lambda, owned_u, writable_lambda, comm, [&](auto &dsp) {
        fill(dsp, false);
      });
      coupling_free.reinit(coupling);
      make_matrix(coupling_free_T, owned_u, owned_lambda, relevant_u, comm, [&](auto &dsp) {
        fill(dsp, true);
      });
      for (const SideCoupling &s : sides)
        for (const auto &[key, value] : s.entries)
          {
            const types::global_dof_index row = dim * s.face + key.second;
            coupling.add(row, key.first, value);
            if (free(key.first))
              {
                coupling_free.add(row, key.first, value);
                coupling_free_T.add(key.first, row, value);
              }
          }
      coupling.compress(VectorOperation::add);
      coupling_free.compress(VectorOperation::add);
      coupling_free_T.compress(VectorOperation::add);
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::assemble()
    {
      TimerOutput::Scope   t(timer, "Mechanics: assembly");
      const MPI_Comm       comm = get_communicator();
      const DeckLoads<dim> loads(prm, mesh.serial);
      CellScratch<dim>     scratch(mesh.mapping(), fe);
      f.reinit(owned_u, comm);
      divergence.clear();
      // A load that cannot be evaluated (an expression not finite on a process's boundary
      // faces) stops every process, not only the one that owns the face.
      collectively(comm, [&]() {
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              scratch.clear();
              assemble_cell_volume(prm, fe, cell, loads, scratch);
              assemble_cell_boundary(prm, fe, cell, loads, scratch);
              cell->get_dof_indices(scratch.local);
              if (has_constrained_dofs(cell, scratch.local))
                {
                  // K_boundary = K - K_constrained on the cells with constrained dofs (on the
                  // others the two agree).
                  K_boundary.add(scratch.local, scratch.matrix);
                  scratch.matrix *= -1.;
                  constraints_hom.distribute_local_to_global(scratch.matrix,
                                                             scratch.local,
                                                             K_boundary);
                  scratch.matrix *= -1.;
                }
              f.add(scratch.local, scratch.rhs);
              CellDivergence d{mesh.serial_cell(cell)->active_cell_index(), {}};
              for (unsigned int i = 0; i < scratch.local.size(); ++i)
                if (scratch.div_integral(i) != 0)
                  d.entries.emplace_back(scratch.local[i], scratch.div_integral(i));
              divergence.push_back(std::move(d));
              constraints_hom.distribute_local_to_global(scratch.matrix,
                                                         scratch.local,
                                                         K_constrained);
            }
        // A fluid pressure p in the fracture pushes both sides apart, -p n on each (see
        // ElasticitySystem::add_fracture_pressure), added by the owner of each side.
        if (!loads.fracture_pressure.empty())
          for (const SideCoupling &s : owned_sides(mesh, dof_handler, fe, prm.axisymmetric))
            {
              const auto &face = mesh.serial.fracture_faces[s.face];
              const auto  it   = loads.fracture_pressure.find(face.fracture_id);
              if (it == loads.fracture_pressure.end())
                continue;
              const double p = it->second->value(face.centre);
              for (const auto &[key, value] : s.entries)
                f(key.first) += -p * face.normal[key.second] * value;
            }
      });
      K_boundary.compress(VectorOperation::add);
      K_constrained.compress(VectorOperation::add);
      f.compress(VectorOperation::add);
      check_input(std::isfinite(f.l2_norm()),
                  "Mechanics",
                  "the loads (body force, tractions, pressures, pre-stress) are not finite");
      f_fixed = f;
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::set_equivalent_pressures(
      const std::vector<double> &p_E_matrix,
      const std::vector<double> &p_E_fracture,
      const double               biot)
    {
      AssertDimension(p_E_matrix.size(), mesh.serial.triangulation.n_active_cells());
      AssertDimension(p_E_fracture.size(), n_faces());
      // Eq. (11b) moved to the right-hand side: + int b p_E,m div v - int p_E,f [v]_n, the
      // second as B^T of the multiplier-row vector p_E,f n+ (B rows: int [v]_i).
      const MPI_Comm comm = get_communicator();
      f                   = f_fixed;
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  values;
      for (const CellDivergence &d : divergence)
        {
          dofs.clear();
          values.clear();
          for (const auto &[dof, value] : d.entries)
            {
              dofs.push_back(dof);
              values.push_back(biot * p_E_matrix[d.cell] * value);
            }
          f.add(dofs, values);
        }
      f.compress(VectorOperation::add);
      VectorType face_load(owned_lambda, comm), load(owned_u, comm);
      for (const unsigned int fi : mesh.locally_owned_faces())
        for (unsigned int c = 0; c < dim; ++c)
          face_load(dim * fi + c) = p_E_fracture[fi] * mesh.serial.fracture_faces[fi].normal[c];
      face_load.compress(VectorOperation::insert);
      coupling.Tvmult(load, face_load);
      f -= load;
    }



    template <int dim>
    Tensor<2, dim>
    DistributedElasticitySystem<dim>::frame(const unsigned int f) const
    {
      return face_frame(mesh.serial.fracture_faces[f]);
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::initial_displacement(VectorType &u) const
    {
      u.reinit(owned_u, get_communicator());
      constraints.distribute(u);
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::contact_jumps(const VectorType            &u,
                                                    const VectorType            &lambda,
                                                    std::vector<Tensor<1, dim>> &jumps) const
    {
      face_jumps(u, jumps);
      if (stabilization.empty())
        return;
      neighbour_lambda      = lambda;
      const auto multiplier = [&](const unsigned int g) {
        return face_multiplier<dim>(neighbour_lambda, g);
      };
      for (const unsigned int f : mesh.locally_owned_faces())
        jumps[f] -= stabilization_term<dim>(stabilization, f, multiplier);
    }



    template <int dim>
    double
    DistributedElasticitySystem<dim>::elastic_energy(const VectorType &u) const
    {
      TimerOutput::Scope t(timer, "Mechanics: elastic energy by cells");
      VectorType         ghosted(owned_u, relevant_u, get_communicator());
      ghosted = u;
      return Utilities::MPI::sum(
        elastic_energy_of_owned_cells(prm, mesh.mapping(), fe, dof_handler, ghosted),
        get_communicator());
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::face_jumps(const VectorType            &u,
                                                 std::vector<Tensor<1, dim>> &jumps) const
    {
      VectorType Bu(owned_lambda, get_communicator());
      coupling.vmult(Bu, u);
      jumps.resize(n_faces());
      for (const unsigned int f : mesh.locally_owned_faces())
        for (unsigned int c = 0; c < dim; ++c)
          jumps[f][c] = Bu(dim * f + c) / face_measures[f];
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::residual(const VectorType &u,
                                               const VectorType &lambda,
                                               VectorType       &r) const
    {
      // On unconstrained rows B_0^T lambda = B^T lambda.
      r.reinit(owned_u, get_communicator());
      VectorType Bt_lambda(r);
      K_constrained.vmult(r, u);
      K_boundary.vmult_add(r, u);
      r.sadd(-1., f);
      coupling_free_T.vmult(Bt_lambda, lambda);
      r -= Bt_lambda;
    }



    template <int dim>
    std::pair<double, double>
    DistributedElasticitySystem<dim>::mechanical_residual_norms(const VectorType &u,
                                                                const VectorType &lambda) const
    {
      VectorType r;
      residual(u, lambda, r);
      double mechanical = 0, load = 0;
      for (const auto i : owned_u)
        if (!constraints.is_constrained(i))
          {
            mechanical += r(i) * r(i);
            load += f(i) * f(i);
          }
      return {mechanical, load};
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::mechanical_rhs(const VectorType &u,
                                                     const VectorType &lambda,
                                                     VectorType       &rhs) const
    {
      VectorType r;
      residual(u, lambda, r);
      for (const auto i : owned_u)
        rhs(i) = constraints_hom.is_constrained(i) ? 0. : double(r(i));
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::set_step(const VectorType &u_old,
                                               const VectorType &lambda_old,
                                               const VectorType &delta,
                                               const double      alpha,
                                               VectorType       &u,
                                               VectorType       &lambda) const
    {
      const types::global_dof_index n_u = dof_handler.n_dofs();
      for (const auto i : owned_u)
        u(i) = u_old(i) + alpha * delta(i);
      for (const auto i : owned_lambda)
        lambda(i) = lambda_old(i) + alpha * delta(n_u + i);
      u.compress(VectorOperation::insert);
      lambda.compress(VectorOperation::insert);
    }



    template <int dim>
    void
    DistributedElasticitySystem<dim>::sum_over_processes(std::vector<double> &values) const
    {
      Utilities::MPI::sum(values, get_communicator(), values);
    }



    template <int dim>
    bool
    DistributedElasticitySystem<dim>::all_processes(const bool value) const
    {
      return Utilities::MPI::min(value ? 1 : 0, get_communicator()) == 1;
    }

    template class DistributedElasticitySystem<2>;
    template class DistributedElasticitySystem<3>;
  } // namespace mechanics
} // namespace porofrac
