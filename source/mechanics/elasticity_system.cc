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
    namespace
    {
      /// Weight of the integrals: 2 pi r in axisymmetric mode (r = second coordinate), else 1.
      template <int dim>
      double
      measure_weight(const bool axisymmetric, const Point<dim> &p)
      {
        return axisymmetric ? 2 * numbers::PI * p[1] : 1.;
      }

      /// A vector function of x, y (, z) with the given component expressions ("0" elsewhere).
      template <int dim>
      std::unique_ptr<FunctionParser<dim>>
      make_vector_function(const std::map<unsigned int, std::string> &expressions,
                           const std::string                         &parameter)
      {
        std::vector<std::string> e(dim, "0");
        for (const auto &[c, ex] : expressions)
          e[c] = ex;
        return io::parse_expressions<dim>(e, parameter);
      }

      /// Lame coefficients (mu, lambda) of E and nu; in 2D they give plane strain.
      std::pair<double, double>
      lame_coefficients(const double E, const double nu)
      {
        return {E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))};
      }
    } // namespace



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
    ElasticitySystem<dim>::setup()
    {
      TimerOutput::Scope t(timer, "Mechanics: setup");
      dof_handler.distribute_dofs(fe);
      make_constraints();
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
      make_coupling(dsp);
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
      const std::string pname = "Mechanics/Dirichlet";
      // Vertex-matching tolerance of the point constraints, from the bounding-box diagonal
      // (GridTools::diameter compares all pairs of boundary vertices: quadratic).
      const auto   box = GridTools::compute_bounding_box(mesh.triangulation);
      const double tol =
        1e-8 * box.get_boundary_points().first.distance(box.get_boundary_points().second);
      for (AffineConstraints<double> *target : {&constraints, &constraints_hom})
        {
          const bool homogeneous = (target == &constraints_hom);
          target->clear();
          for (const auto &[id, comps] : prm.dirichlet)
            {
              if (std::find(mesh.outer_boundary_ids.begin(), mesh.outer_boundary_ids.end(), id) ==
                  mesh.outer_boundary_ids.end())
                throw InputError(pname,
                                 "boundary id " + std::to_string(id) +
                                   " is not an outer boundary of the mesh");
              std::vector<bool> mask(dim, false);
              for (const auto &[c, e] : comps)
                mask[c] = true;
              auto                         fp = make_vector_function<dim>(comps, pname);
              Functions::ZeroFunction<dim> zero(dim);
              VectorTools::interpolate_boundary_values(mesh.mapping(),
                                                       dof_handler,
                                                       id,
                                                       homogeneous ?
                                                         static_cast<const Function<dim> &>(zero) :
                                                         *fp,
                                                       *target,
                                                       ComponentMask(mask));
            }
          // Point constraints (e.g. the symmetry of 5.2.1): every vertex at the point.
          std::set<types::global_dof_index> point_constrained;
          for (const PointConstraint &pc : prm.point_constraints)
            {
              Point<dim> p;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = pc.point[d];
              unsigned int                      hits = 0;
              std::set<types::global_dof_index> own; // a vertex is seen from each of its cells
              for (const auto &cell : dof_handler.active_cell_iterators())
                for (const unsigned int v : cell->vertex_indices())
                  if (cell->vertex(v).distance(p) < tol)
                    {
                      ++hits;
                      for (const auto &[c, e] : pc.values)
                        {
                          const auto dof = cell->vertex_dof_index(v, c);
                          if (!own.insert(dof).second)
                            continue;
                          check_input(!point_constrained.count(dof),
                                      "Mechanics/Point constraints",
                                      "component " + std::string(1, "xyz"[c]) + " at " +
                                        io::to_text(p) + " is constrained twice");
                          if (target->is_constrained(dof))
                            continue;
                          target->add_line(dof);
                          if (!homogeneous)
                            target->set_inhomogeneity(
                              dof,
                              io::parse_expressions<dim>({e}, "Mechanics/Point constraints")
                                ->value(p));
                        }
                    }
              point_constrained.insert(own.begin(), own.end());
              if (hits == 0)
                {
                  std::ostringstream s;
                  s << "the point (" << p << ") is not a mesh vertex";
                  throw InputError("Mechanics/Point constraints", s.str());
                }
            }
          target->close();
        }
      check_input(constraints.n_constraints() > 0,
                  "Mechanics/Dirichlet",
                  "no Dirichlet condition or point constraint: the elasticity system is singular");
    }



    template <int dim>
    void
    ElasticitySystem<dim>::make_coupling(DynamicSparsityPattern &dsp)
    {
      // Coupling int_sigma lambda . [v] (paper eq. (10)), [v] = v+ - v-.
      const unsigned int                   n_u = dof_handler.n_dofs();
      std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
      const QGaussSimplex<dim - 1>         face_quadrature(3);
      FEFaceValues<dim>                    fe_face(mesh.mapping(),
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
              fe_face.reinit(cell, face.face_no[side]);
              cell->get_dof_indices(local);
              const double sign = (side == geometry::plus ? 1. : -1.);
              if (side == geometry::plus)
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  face_measures[face.index] +=
                    measure_weight(prm.axisymmetric, fe_face.quadrature_point(q)) * fe_face.JxW(q);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                {
                  if (!fe.has_support_on_face(i, face.face_no[side]))
                    continue;
                  const unsigned int comp = fe.system_to_component_index(i).first;
                  double             v    = 0;
                  for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                    v += fe_face.shape_value_component(i, q, comp) *
                         measure_weight(prm.axisymmetric, fe_face.quadrature_point(q)) *
                         fe_face.JxW(q);
                  entries[{local[i], comp}] += sign * v;
                }
            }
          for (const auto &[key, v] : entries)
            if (std::abs(v) > 1e-14 * face_measures[face.index])
              coupling[face.index].push_back({key.first, key.second, v});
          for (unsigned int i = 0; i < dim; ++i)
            {
              const unsigned int row = n_u + dim * face.index + i;
              for (unsigned int j = 0; j < dim; ++j)
                dsp.add(row, n_u + dim * face.index + j);
              for (const auto &e : coupling[face.index])
                {
                  dsp.add(row, e.dof);
                  dsp.add(e.dof, row);
                }
            }
        }
    }



    /// The fixed loads of the deck as functions (body force, tractions, pressures, pre-stress).
    template <int dim>
    struct DeckLoads
    {
      DeckLoads(const ContactParameters &prm, const geometry::CutMesh<dim> &mesh)
      {
        if (!prm.body_force.empty())
          {
            std::map<unsigned int, std::string> m;
            for (unsigned int d = 0; d < dim; ++d)
              m[d] = prm.body_force[d];
            body = make_vector_function<dim>(m, "Mechanics/Body force");
          }
        if (!prm.pre_stress.empty())
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              sigma0[i][j] = prm.pre_stress[i * dim + j];
        const auto check_id = [&](const types::boundary_id id, const std::string &parameter) {
          check_input(std::find(mesh.outer_boundary_ids.begin(),
                                mesh.outer_boundary_ids.end(),
                                id) != mesh.outer_boundary_ids.end(),
                      parameter,
                      "boundary id " + std::to_string(id) +
                        " is not an outer boundary of the mesh");
        };
        for (const auto &[id, m] : prm.traction)
          {
            check_id(id, "Mechanics/Traction");
            traction[id] = make_vector_function<dim>(m, "Mechanics/Traction");
          }
        for (const auto &[id, e] : prm.pressure)
          {
            check_id(id, "Mechanics/Normal pressure");
            pressure[id] = io::parse_expressions<dim>({e}, "Mechanics/Normal pressure");
          }
        const std::string fp = "Mechanics/Fracture pressure";
        for (const auto &[id, e] : prm.fracture_pressure)
          check_input(id == numbers::invalid_unsigned_int ||
                        std::count(mesh.fracture_ids.begin(), mesh.fracture_ids.end(), id) > 0,
                      fp,
                      "fracture id " + std::to_string(id) + " is not a fracture of the mesh");
        for (const unsigned int id : mesh.fracture_ids)
          {
            auto it = prm.fracture_pressure.find(id);
            if (it == prm.fracture_pressure.end())
              it = prm.fracture_pressure.find(numbers::invalid_unsigned_int);
            if (it != prm.fracture_pressure.end())
              fracture_pressure[id] = io::parse_expressions<dim>({it->second}, fp);
          }
      }

      std::unique_ptr<FunctionParser<dim>>                               body;
      SymmetricTensor<2, dim>                                            sigma0;
      std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>> traction, pressure;
      /// Fluid pressure in the fractures by fracture id (none: no pressure).
      std::map<unsigned int, std::unique_ptr<FunctionParser<dim>>> fracture_pressure;
    };



    /// Per-cell work arrays and the cell's contributions (matrix, loads, int_K div phi_i).
    template <int dim>
    struct ElasticitySystem<dim>::CellScratch
    {
      CellScratch(const geometry::CutMesh<dim> &mesh, const FESystem<dim> &fe)
          : quadrature(3)
          , face_quadrature(3)
          , fe_values(mesh.mapping(),
                      fe,
                      quadrature,
                      update_values | update_gradients | update_quadrature_points |
                        update_JxW_values)
          , fe_face(mesh.mapping(),
                    fe,
                    face_quadrature,
                    update_values | update_quadrature_points | update_normal_vectors |
                      update_JxW_values)
          , matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
          , rhs(fe.n_dofs_per_cell())
          , div_integral(fe.n_dofs_per_cell())
          , local(fe.n_dofs_per_cell())
          , eps(fe.n_dofs_per_cell())
          , eps_hoop(fe.n_dofs_per_cell())
          , div(fe.n_dofs_per_cell())
          , value(dim)
      {
      }

      const QGaussSimplex<dim>             quadrature;
      const QGaussSimplex<dim - 1>         face_quadrature;
      FEValues<dim>                        fe_values;
      FEFaceValues<dim>                    fe_face;
      FullMatrix<double>                   matrix;
      Vector<double>                       rhs, div_integral;
      std::vector<types::global_dof_index> local;
      std::vector<SymmetricTensor<2, dim>> eps;
      std::vector<double>                  eps_hoop, div;
      Vector<double>                       value;
    };



    template <int dim>
    void
    ElasticitySystem<dim>::assemble_cell_volume(const active_cell_iterator &cell,
                                                const DeckLoads<dim>       &loads,
                                                CellScratch                &scratch)
    {
      // Hooke's law (plane strain in 2D).
      const auto [mu, lam] = lame_coefficients(prm.young_modulus, prm.poisson_ratio);
      const FEValuesExtractors::Vector disp(0);
      const bool                       axi       = prm.axisymmetric;
      const unsigned int               n         = fe.n_dofs_per_cell();
      auto                            &fe_values = scratch.fe_values;
      auto &eps = scratch.eps, &eps_hoop = scratch.eps_hoop, &div = scratch.div;
      fe_values.reinit(cell);
      for (unsigned int q = 0; q < scratch.quadrature.size(); ++q)
        {
          const Point<dim> &x = fe_values.quadrature_point(q);
          // Axisymmetric: integrals over the ring, weight 2 pi r; the strain gains the hoop
          // component u_r / r (r = x[1], radial component 1).
          const double JxW = measure_weight(axi, x) * fe_values.JxW(q);
          cell_measures[cell->active_cell_index()] += JxW;
          for (unsigned int i = 0; i < n; ++i)
            {
              eps[i]      = fe_values[disp].symmetric_gradient(i, q);
              eps_hoop[i] = (axi && fe.system_to_component_index(i).first == 1) ?
                              fe_values.shape_value(i, q) / x[1] :
                              0.;
              div[i]      = trace(eps[i]) + eps_hoop[i];
            }
          if (loads.body)
            loads.body->vector_value(x, scratch.value);
          for (unsigned int i = 0; i < n; ++i)
            {
              const SymmetricTensor<2, dim> s_i =
                2 * mu * eps[i] + lam * div[i] * unit_symmetric_tensor<dim>();
              const double s_i_hoop = 2 * mu * eps_hoop[i] + lam * div[i];
              for (unsigned int j = 0; j < n; ++j)
                scratch.matrix(i, j) += (s_i * eps[j] + s_i_hoop * eps_hoop[j]) * JxW;
              double r = -(loads.sigma0 * eps[i]) - prm.pre_stress_hoop * eps_hoop[i];
              if (loads.body)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  r += scratch.value[c] * fe_values.shape_value(i, q);
                }
              scratch.rhs(i) += r * JxW;
              scratch.div_integral(i) += div[i] * JxW;
            }
        }
    }



    template <int dim>
    void
    ElasticitySystem<dim>::assemble_cell_boundary(const active_cell_iterator &cell,
                                                  const DeckLoads<dim>       &loads,
                                                  CellScratch                &scratch)
    {
      for (const unsigned int fn : cell->face_indices())
        {
          if (!cell->face(fn)->at_boundary())
            continue;
          const auto id = cell->face(fn)->boundary_id();
          const auto tr = loads.traction.find(id);
          const auto pr = loads.pressure.find(id);
          if (tr == loads.traction.end() && pr == loads.pressure.end())
            continue;
          auto &fe_face = scratch.fe_face;
          fe_face.reinit(cell, fn);
          for (unsigned int q = 0; q < scratch.face_quadrature.size(); ++q)
            {
              const Point<dim> &x   = fe_face.quadrature_point(q);
              const double      JxW = measure_weight(prm.axisymmetric, x) * fe_face.JxW(q);
              Tensor<1, dim>    t;
              if (tr != loads.traction.end())
                {
                  tr->second->vector_value(x, scratch.value);
                  for (unsigned int d = 0; d < dim; ++d)
                    t[d] += scratch.value[d];
                }
              if (pr != loads.pressure.end())
                t -= pr->second->value(x) * fe_face.normal_vector(q);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  scratch.rhs(i) += t[c] * fe_face.shape_value(i, q) * JxW;
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
      CellScratch          scratch(mesh, fe);
      K_full      = 0;
      base_matrix = 0;
      f           = 0;
      divergence.assign(mesh.triangulation.n_active_cells(), {});
      cell_measures.assign(mesh.triangulation.n_active_cells(), 0.);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          scratch.matrix       = 0;
          scratch.rhs          = 0;
          scratch.div_integral = 0;
          assemble_cell_volume(cell, loads, scratch);
          assemble_cell_boundary(cell, loads, scratch);
          cell->get_dof_indices(scratch.local);
          K_full.add(scratch.local, scratch.matrix);
          for (unsigned int i = 0; i < scratch.local.size(); ++i)
            {
              f(scratch.local[i]) += scratch.rhs(i);
              if (scratch.div_integral(i) != 0)
                divergence[cell->active_cell_index()].emplace_back(scratch.local[i],
                                                                   scratch.div_integral(i));
            }
          constraints_hom.distribute_local_to_global(scratch.matrix, scratch.local, base_matrix);
        }
      add_fracture_pressure(loads);
      check_input(std::isfinite(f.l2_norm()),
                  "Mechanics",
                  "the loads (body force, tractions, pressures, pre-stress) are not finite");
      f_fixed = f;
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
      const auto    &face = mesh.fracture_faces[fi];
      Tensor<2, dim> R;
      for (unsigned int d = 0; d < dim; ++d)
        {
          R[0][d] = face.normal[d];
          R[1][d] = face.tangent[d];
        }
      if constexpr (dim == 3)
        {
          const Tensor<1, 3> t2 = cross_product_3d(face.normal, face.tangent);
          for (unsigned int d = 0; d < 3; ++d)
            R[2][d] = t2[d];
        }
      return R;
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

    template class ElasticitySystem<2>;
    template class ElasticitySystem<3>;
  } // namespace mechanics
} // namespace porofrac
