// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/io/expression.h>
#include <porofrac/io/text.h>
#include <porofrac/mechanics/coupling_entry.h>
#include <porofrac/mechanics/elasticity_assembly.h>
#include <porofrac/mechanics/elasticity_system.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace porofrac
{
  namespace mechanics
  {



    template <int dim>
    ElasticitySystem<dim>::ElasticitySystem(const geometry::CutMesh<dim> &mesh,
                                            const ContactParameters      &parameters,
                                            TimerOutput                  &timer)
        : mesh(mesh)
        , prm(parameters)
        , timer(timer)
        , fe(FE_SimplexP<dim>(2), dim)
        , dof_handler(mesh.triangulation)
    {
      prm.validate(dim);
      if (prm.axisymmetric)
        for (const auto &v : mesh.triangulation.get_vertices())
          if (v[1] < 0)
            {
              std::ostringstream m;
              m << "the radial section must lie in r = y >= 0, but the mesh has the vertex (" << v
                << ")";
              throw InputError("Mechanics/Axisymmetric", m.str());
            }
    }



    template <int dim>
    unsigned int
    ElasticitySystem<dim>::n_dofs() const
    {
      return dof_handler.n_dofs() + dim * mesh.fracture_faces.size();
    }



    template <int dim>
    void
    ElasticitySystem<dim>::setup(const SystemAssembly what)
    {
      TimerOutput::Scope t(timer, "Mechanics: setup");
      dof_handler.distribute_dofs(fe);
      make_constraints();
      stabilization      = make_multiplier_stabilization(mesh, prm);
      matrices_assembled = what == SystemAssembly::matrices;
      if (!matrices_assembled)
        {
          make_coupling(nullptr);
          if (what == SystemAssembly::loads)
            {
              f.reinit(dof_handler.n_dofs());
              f_fixed.reinit(dof_handler.n_dofs());
              assemble();
            }
          return;
        }
      const unsigned int                   N = n_dofs();
      DynamicSparsityPattern               dsp(N, N);
      std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(local);
          constraints_hom.add_entries_local_to_global(local, dsp, true);
          for (const auto i : local)
            for (const auto j : local)
              dsp.add(i, j);
        }
      make_coupling(&dsp);
      sparsity.copy_from(dsp);
      K_full.reinit(sparsity);
      base_matrix.reinit(sparsity);
      f.reinit(dof_handler.n_dofs());
      f_fixed.reinit(dof_handler.n_dofs());
      assemble();
    }



    template <int dim>
    void
    ElasticitySystem<dim>::make_constraints()
    {
      // Vertex-matching tolerance of the point constraints, from the bounding-box diagonal
      // (GridTools::diameter compares all pairs of boundary vertices: quadratic).
      const auto   box = GridTools::compute_bounding_box(mesh.triangulation);
      const double tol =
        1e-8 * box.get_boundary_points().first.distance(box.get_boundary_points().second);
      for (AffineConstraints<double> *target : {&constraints, &constraints_hom})
        {
          target->clear();
          const std::vector<unsigned int> hits = add_displacement_constraints(
            prm, mesh, dof_handler, tol, target == &constraints_hom, *target);
          check_displacement_constraints(prm, hits, true);
          target->close();
        }
      check_displacement_constraints(prm, {}, constraints.n_constraints() > 0);
    }



    template <int dim>
    void
    ElasticitySystem<dim>::make_coupling(DynamicSparsityPattern *dsp)
    {
      // Coupling int_sigma lambda . [v] (paper eq. (10)), [v] = v+ - v-.
      const unsigned int           n_u = dof_handler.n_dofs();
      const QGaussSimplex<dim - 1> face_quadrature(3);
      FEFaceValues<dim>            fe_face(mesh.mapping(),
                                fe,
                                face_quadrature,
                                update_values | update_quadrature_points | update_JxW_values);
      coupling.assign(mesh.fracture_faces.size(), {});
      face_measures.assign(mesh.fracture_faces.size(), 0.);
      for (const auto &face : mesh.fracture_faces)
        {
          std::map<std::pair<types::global_dof_index, unsigned int>, double> entries;
          for (unsigned int side = 0; side < 2; ++side)
            {
              const typename DoFHandler<dim>::active_cell_iterator cell(&mesh.triangulation,
                                                                        face.cell[side]->level(),
                                                                        face.cell[side]->index(),
                                                                        &dof_handler);
              const double sign    = (side == geometry::plus ? 1. : -1.);
              const double measure = add_side_coupling(
                prm.axisymmetric, fe, fe_face, cell, face.face_no[side], sign, entries);
              if (side == geometry::plus)
                face_measures[face.index] = measure;
            }
          for (const auto &[key, v] : entries)
            if (std::abs(v) > 1e-14 * face_measures[face.index])
              coupling[face.index].push_back({key.first, key.second, v});
          for (unsigned int i = 0; dsp != nullptr && i < dim; ++i)
            {
              const unsigned int row = n_u + dim * face.index + i;
              for (unsigned int j = 0; j < dim; ++j)
                dsp->add(row, n_u + dim * face.index + j);
              for (const auto &e : coupling[face.index])
                {
                  dsp->add(row, e.dof);
                  dsp->add(e.dof, row);
                }
            }
        }
    }



    template <int dim>
    void
    ElasticitySystem<dim>::assemble()
    {
      TimerOutput::Scope   t(timer, "Mechanics: assembly");
      const DeckLoads<dim> loads(prm, mesh);
      CellScratch<dim>     scratch(mesh.mapping(), fe);
      scratch.with_matrix = matrices_assembled;
      if (matrices_assembled)
        {
          K_full      = 0;
          base_matrix = 0;
        }
      f = 0;
      divergence.assign(mesh.triangulation.n_active_cells(), {});
      cell_measures.assign(mesh.triangulation.n_active_cells(), 0.);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          scratch.clear();
          assemble_cell_volume(prm, fe, cell, loads, scratch);
          assemble_cell_boundary(prm, fe, cell, loads, scratch);
          cell_measures[cell->active_cell_index()] = scratch.cell_measure;
          cell->get_dof_indices(scratch.local);
          if (matrices_assembled)
            {
              K_full.add(scratch.local, scratch.matrix);
              constraints_hom.distribute_local_to_global(scratch.matrix,
                                                         scratch.local,
                                                         base_matrix);
            }
          for (unsigned int i = 0; i < scratch.local.size(); ++i)
            {
              f(scratch.local[i]) += scratch.rhs(i);
              if (scratch.div_integral(i) != 0)
                divergence[cell->active_cell_index()].emplace_back(scratch.local[i],
                                                                   scratch.div_integral(i));
            }
        }
      add_fracture_pressure(loads);
      check_input(std::isfinite(f.l2_norm()),
                  "Mechanics",
                  "the loads (body force, tractions, pressures, pre-stress) are not finite");
      f_fixed = f;
      if (matrices_assembled)
        add_coupling_to_matrix();
    }



    template <int dim>
    void
    ElasticitySystem<dim>::add_fracture_pressure(const DeckLoads<dim> &loads)
    {
      // A fluid pressure p in the fracture pushes both sides apart, -p n on each: the work
      // -int p [v]_n, a load like p_E,f in (11b), constant per face (its value at the centre).
      for (const auto &face : mesh.fracture_faces)
        {
          const auto it = loads.fracture_pressure.find(face.fracture_id);
          if (it == loads.fracture_pressure.end())
            continue;
          const double p = it->second->value(face.centre);
          for (const auto &e : coupling[face.index])
            f(e.dof) -= p * face.normal[e.component] * e.value;
        }
    }



    template <int dim>
    void
    ElasticitySystem<dim>::add_coupling_to_matrix()
    {
      const unsigned int n_u = dof_handler.n_dofs();
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        for (const auto &e : coupling[fi])
          if (!constraints_hom.is_constrained(e.dof))
            base_matrix.add(e.dof, n_u + dim * fi + e.component, e.value);
    }



    template <int dim>
    Tensor<2, dim>
    ElasticitySystem<dim>::frame(const unsigned int fi) const
    {
      return face_frame(mesh.fracture_faces[fi]);
    }



    template <int dim>
    void
    ElasticitySystem<dim>::set_equivalent_pressures(const std::vector<double> &p_E_matrix,
                                                    const std::vector<double> &p_E_fracture,
                                                    const double               biot)
    {
      AssertDimension(p_E_matrix.size(), divergence.size());
      AssertDimension(p_E_fracture.size(), coupling.size());
      // Eq. (11b) moved to the right-hand side: + int b p_E,m div v - int p_E,f [v]_n.
      f = f_fixed;
      for (unsigned int K = 0; K < divergence.size(); ++K)
        for (const auto &[dof, value] : divergence[K])
          f(dof) += biot * p_E_matrix[K] * value;
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        {
          const Tensor<1, dim> &n = mesh.fracture_faces[fi].normal;
          for (const auto &e : coupling[fi])
            f(e.dof) -= p_E_fracture[fi] * n[e.component] * e.value;
        }
    }



    template <int dim>
    void
    ElasticitySystem<dim>::initial_displacement(Vector<double> &u) const
    {
      u.reinit(dof_handler.n_dofs());
      constraints.distribute(u);
    }



    template <int dim>
    void
    ElasticitySystem<dim>::apply_elasticity(const Vector<double> &u, Vector<double> &Ku) const
    {
      AssertThrow(matrices_assembled,
                  ExcMessage("ElasticitySystem: K u needs setup() with the matrices"));
      // K_full lives on the saddle-point pattern but has entries in the displacement block only.
      Vector<double> x(n_dofs()), y(n_dofs());
      for (unsigned int i = 0; i < u.size(); ++i)
        x(i) = u(i);
      K_full.vmult(y, x);
      Ku.reinit(u.size());
      for (unsigned int i = 0; i < u.size(); ++i)
        Ku(i) = y(i);
    }



    template <int dim>
    double
    ElasticitySystem<dim>::elastic_energy_by_cells(const Vector<double> &u) const
    {
      TimerOutput::Scope t(timer, "Mechanics: elastic energy by cells");
      return elastic_energy_of_owned_cells(prm, mesh.mapping(), fe, dof_handler, u);
    }



    template <int dim>
    void
    ElasticitySystem<dim>::apply_jacobian(const FaceRows<dim>  &rows,
                                          const Vector<double> &x,
                                          Vector<double>       &y) const
    {
      const unsigned int n_u = dof_handler.n_dofs();
      base_matrix.vmult(y, x);
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        {
          const double   m = face_measures[fi];
          Tensor<1, dim> l, j;
          for (unsigned int k = 0; k < dim; ++k)
            l[k] = x(n_u + dim * fi + k);
          for (const auto &e : coupling[fi])
            if (!constraints_hom.is_constrained(e.dof))
              j[e.component] += e.value * x(e.dof) / m;
          j -= stabilization_term<dim>(stabilization, fi, [&](const unsigned int g) {
            Tensor<1, dim> lg;
            for (unsigned int k = 0; k < dim; ++k)
              lg[k] = x(n_u + dim * g + k);
            return lg;
          });
          const Tensor<1, dim> row = rows.lambda[fi] * l + rows.jump[fi] * j;
          for (unsigned int i = 0; i < dim; ++i)
            y(n_u + dim * fi + i) = row[i];
        }
    }



    template <int dim>
    Tensor<1, dim>
    ElasticitySystem<dim>::jump(const Vector<double> &u, const unsigned int fi) const
    {
      Tensor<1, dim> j;
      for (const auto &e : coupling[fi])
        j[e.component] += e.value * u(e.dof);
      return j / face_measures[fi];
    }



    template <int dim>
    std::vector<double>
    ElasticitySystem<dim>::cell_divergence(const Vector<double> &u) const
    {
      std::vector<double> result(divergence.size(), 0.);
      for (unsigned int K = 0; K < divergence.size(); ++K)
        {
          for (const auto &[dof, value] : divergence[K])
            result[K] += value * u(dof);
          result[K] /= cell_measures[K];
        }
      return result;
    }



    template <int dim>
    double
    ElasticitySystem<dim>::elastic_energy(const Vector<double> &u) const
    {
      if (!matrices_assembled)
        return elastic_energy_by_cells(u);
      Vector<double> Ku;
      apply_elasticity(u, Ku);
      return 0.5 * (u * Ku);
    }



    template <int dim>
    double
    ElasticitySystem<dim>::external_work(const Vector<double> &u, const Vector<double> &u_old) const
    {
      double w = 0;
      for (unsigned int i = 0; i < u.size(); ++i)
        w += f_fixed(i) * (u(i) - u_old(i));
      return w;
    }



    template <int dim>
    SymmetricTensor<2, dim>
    ElasticitySystem<dim>::stress(const Vector<double>                                 &u,
                                  const typename DoFHandler<dim>::active_cell_iterator &cell,
                                  const Point<dim> &unit_point) const
    {
      const Quadrature<dim> q(unit_point);
      FEValues<dim>         fv(mesh.mapping(), fe, q, update_gradients);
      fv.reinit(cell);
      std::vector<SymmetricTensor<2, dim>> eps(1);
      fv[FEValuesExtractors::Vector(0)].get_function_symmetric_gradients(u, eps);
      const auto [mu, lam] = lame_coefficients(prm.young_modulus, prm.poisson_ratio);
      SymmetricTensor<2, dim> s =
        2 * mu * eps[0] + lam * trace(eps[0]) * unit_symmetric_tensor<dim>();
      if (!prm.pre_stress.empty())
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            s[i][j] += prm.pre_stress[i * dim + j];
      return s;
    }


    template <int dim>
    void
    ElasticitySystem<dim>::face_jumps(const Vector<double>        &u,
                                      std::vector<Tensor<1, dim>> &jumps) const
    {
      jumps.resize(coupling.size());
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        jumps[fi] = jump(u, fi);
    }



    template <int dim>
    void
    ElasticitySystem<dim>::contact_jumps(const Vector<double>        &u,
                                         const Vector<double>        &lambda,
                                         std::vector<Tensor<1, dim>> &jumps) const
    {
      face_jumps(u, jumps);
      if (stabilization.empty())
        return;
      const auto multiplier = [&](const unsigned int g) { return face_multiplier<dim>(lambda, g); };
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        jumps[fi] -= stabilization_term<dim>(stabilization, fi, multiplier);
    }



    template <int dim>
    std::pair<double, double>
    ElasticitySystem<dim>::mechanical_residual_norms(const Vector<double> &u,
                                                     const Vector<double> &lambda) const
    {
      // f - K u - B^T lambda on unconstrained dofs.
      Vector<double> r;
      apply_elasticity(u, r);
      r.sadd(-1., f);
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        for (const auto &e : coupling[fi])
          r(e.dof) -= e.value * lambda(dim * fi + e.component);
      double mechanical = 0, load = 0;
      for (unsigned int i = 0; i < r.size(); ++i)
        if (!constraints.is_constrained(i))
          {
            mechanical += r(i) * r(i);
            load += f(i) * f(i);
          }
      return {mechanical, load};
    }



    template <int dim>
    void
    ElasticitySystem<dim>::mechanical_rhs(const Vector<double> &u,
                                          const Vector<double> &lambda,
                                          Vector<double>       &rhs) const
    {
      const unsigned int n_u = dof_handler.n_dofs();
      Vector<double>     r;
      apply_elasticity(u, r);
      for (unsigned int i = 0; i < n_u; ++i)
        rhs(i) = constraints_hom.is_constrained(i) ? 0. : f(i) - r(i);
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        for (const auto &e : coupling[fi])
          if (!constraints_hom.is_constrained(e.dof))
            rhs(e.dof) -= e.value * lambda(dim * fi + e.component);
    }



    template <int dim>
    void
    ElasticitySystem<dim>::set_step(const Vector<double> &u_old,
                                    const Vector<double> &lambda_old,
                                    const Vector<double> &delta,
                                    const double          alpha,
                                    Vector<double>       &u,
                                    Vector<double>       &lambda) const
    {
      const unsigned int n_u = u.size();
      for (unsigned int i = 0; i < n_u; ++i)
        u(i) = u_old(i) + alpha * delta(i);
      for (unsigned int i = 0; i < lambda.size(); ++i)
        lambda(i) = lambda_old(i) + alpha * delta(n_u + i);
    }

    template class ElasticitySystem<2>;
    template class ElasticitySystem<3>;
  } // namespace mechanics
} // namespace porofrac
