// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/numerics/vector_tools.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/mechanics/contact_problem.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
      template <int dim>
      std::string
      coordinate_names(const bool with_d)
      {
        std::string v = (dim == 2 ? "x,y" : "x,y,z");
        return with_d ? v + ",d" : v;
      }

      /// A vector FunctionParser with the given component expressions ("0" elsewhere).
      template <int dim>
      std::unique_ptr<FunctionParser<dim>>
      make_vector_function(const std::map<unsigned int, std::string> &expressions,
                           const std::string                         &parameter)
      {
        std::vector<std::string> e(dim, "0");
        for (const auto &[c, ex] : expressions)
          e[c] = ex;
        auto fp = std::make_unique<FunctionParser<dim>>(dim);
        try
          {
            fp->initialize(coordinate_names<dim>(false), e, {{"pi", numbers::PI}});
          }
        catch (...)
          {
            throw InputError(parameter, "cannot parse the expressions");
          }
        return fp;
      }
    } // namespace

    template <int dim>
    ContactProblem<dim>::ContactProblem(const geometry::CutMesh<dim> &mesh,
                                        const ContactParameters      &parameters,
                                        ConditionalOStream           &progress,
                                        TimerOutput                  &timer)
        : mesh(mesh)
        , prm(parameters)
        , progress(progress)
        , timer(timer)
        , fe(FE_SimplexP<dim>(2), dim)
        , dof_handler(mesh.triangulation)
    {
      check_input(prm.c > 0, "Mechanics/Complementarity parameter c", "must be positive");
      check_input(prm.young_modulus > 0, "Mechanics/Young modulus", "must be positive");
      check_input(prm.poisson_ratio < 0.5 && prm.poisson_ratio > -1,
                  "Mechanics/Poisson ratio",
                  "must be below 0.5 and above -1");
      check_input(prm.tolerance > 0, "Mechanics/Tolerance", "must be positive");
      check_input(prm.max_iterations > 0, "Mechanics/Max iterations", "must be positive");
      check_input(!prm.axisymmetric || dim == 2,
                  "Mechanics/Axisymmetric",
                  "the axisymmetric mode needs a 2D radial section (Dimension = 2)");
      check_input(prm.axisymmetric || prm.pre_stress_hoop == 0,
                  "Mechanics/Pre-stress hoop",
                  "a hoop pre-stress needs Axisymmetric = true");
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

    namespace
    {
      /// Weight of the integrals: 2 pi r in axisymmetric mode (r = second coordinate), else 1.
      template <int dim>
      double
      measure_weight(const bool axisymmetric, const Point<dim> &p)
      {
        return axisymmetric ? 2 * numbers::PI * p[1] : 1.;
      }
    } // namespace

    template <int dim>
    unsigned int
    ContactProblem<dim>::n_dofs() const
    {
      return dof_handler.n_dofs() + dim * mesh.fracture_faces.size();
    }

    template <int dim>
    void
    ContactProblem<dim>::make_constraints()
    {
      const std::string pname = "Mechanics/Dirichlet";
      // Vertex-matching tolerance of the point constraints, from the bounding-box diagonal:
      // GridTools::diameter compares all pairs of boundary vertices (95 s on the 770,176-cell
      // 5.2.1 mesh).
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
          // Point constraints (5.2.1 symmetry): every vertex at the point.
          for (const PointConstraint &pc : prm.point_constraints)
            {
              Point<dim> p;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = pc.point[d];
              unsigned int hits = 0;
              for (const auto &cell : dof_handler.active_cell_iterators())
                for (const unsigned int v : cell->vertex_indices())
                  if (cell->vertex(v).distance(p) < tol)
                    {
                      ++hits;
                      for (const auto &[c, e] : pc.values)
                        {
                          const auto dof = cell->vertex_dof_index(v, c);
                          if (target->is_constrained(dof))
                            continue;
                          target->add_line(dof);
                          if (!homogeneous)
                            {
                              FunctionParser<dim> fp(1);
                              fp.initialize(coordinate_names<dim>(false), e, {{"pi", numbers::PI}});
                              target->set_inhomogeneity(dof, fp.value(p));
                            }
                        }
                    }
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
    ContactProblem<dim>::setup()
    {
      TimerOutput::Scope t(timer, "Mechanics: setup");
      dof_handler.distribute_dofs(fe);
      make_constraints();
      schur.reset();
      schur_unavailable = false;

      const unsigned int                   n_u = dof_handler.n_dofs();
      const unsigned int                   N   = n_dofs();
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

      // Coupling int_sigma lambda . [v] (paper eq. (10)), [v] = v+ - v-.
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
      sparsity.copy_from(dsp);
      K_full.reinit(sparsity);
      base_matrix.reinit(sparsity);
      // system_matrix (full Jacobian) is allocated on first use: the Schur complement path never
      // needs it (0.9 GB at 3 M dofs).
      system_matrix.clear();
      f.reinit(n_u);
      f_fixed.reinit(n_u);
      u.reinit(n_u);
      lambda.reinit(dim * mesh.fracture_faces.size());

      // Friction coefficient per face: muparser of x, y (, z) and d (distance to the tips).
      friction_values.resize(mesh.fracture_faces.size());
      for (const auto &face : mesh.fracture_faces)
        {
          const auto          it   = prm.friction.find(face.fracture_id);
          std::string         expr = (it != prm.friction.end() ? it->second : prm.friction_all);
          FunctionParser<dim> fp(1);
          try
            {
              fp.initialize(coordinate_names<dim>(true), expr, {{"pi", numbers::PI}}, true);
            }
          catch (...)
            {
              throw InputError("Mechanics/Friction coefficient", "cannot parse '" + expr + "'");
            }
          fp.set_time(std::isfinite(face.distance_to_tip) ? face.distance_to_tip : 1e100);
          const double F = fp.value(face.centre);
          if (!(F >= 0))
            {
              std::ostringstream s;
              s << "negative or invalid value " << F << " on fracture " << face.fracture_id;
              throw InputError("Mechanics/Friction coefficient", s.str());
            }
          friction_values[face.index] = F;
        }
      assemble_elasticity();
    }

    template <int dim>
    void
    ContactProblem<dim>::assemble_elasticity()
    {
      TimerOutput::Scope t(timer, "Mechanics: assembly");
      const double       E = prm.young_modulus, nu = prm.poisson_ratio;
      // Hooke's law; in 2D these Lame coefficients give plane strain.
      const double mu = E / (2 * (1 + nu)), lam = E * nu / ((1 + nu) * (1 - 2 * nu));

      const QGaussSimplex<dim>         quadrature(3);
      const QGaussSimplex<dim - 1>     face_quadrature(3);
      FEValues<dim>                    fe_values(mesh.mapping(),
                              fe,
                              quadrature,
                              update_values | update_gradients | update_quadrature_points |
                                update_JxW_values);
      FEFaceValues<dim>                fe_face(mesh.mapping(),
                                fe,
                                face_quadrature,
                                update_values | update_quadrature_points | update_normal_vectors |
                                  update_JxW_values);
      const FEValuesExtractors::Vector disp(0);

      std::unique_ptr<FunctionParser<dim>> body;
      if (!prm.body_force.empty())
        {
          std::map<unsigned int, std::string> m;
          for (unsigned int d = 0; d < dim; ++d)
            m[d] = prm.body_force[d];
          body = make_vector_function<dim>(m, "Mechanics/Body force");
        }
      SymmetricTensor<2, dim> sigma0;
      if (!prm.pre_stress.empty())
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            sigma0[i][j] = prm.pre_stress[i * dim + j];
      std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>> traction, pressure;
      for (const auto &[id, m] : prm.traction)
        traction[id] = make_vector_function<dim>(m, "Mechanics/Traction");
      for (const auto &[id, e] : prm.pressure)
        {
          pressure[id] = std::make_unique<FunctionParser<dim>>(1);
          pressure[id]->initialize(coordinate_names<dim>(false), e, {{"pi", numbers::PI}});
        }

      const unsigned int                   n = fe.n_dofs_per_cell();
      FullMatrix<double>                   cell_matrix(n, n);
      Vector<double>                       cell_rhs(n);
      std::vector<types::global_dof_index> local(n);
      std::vector<SymmetricTensor<2, dim>> eps(n);
      std::vector<double>                  eps_hoop(n), div(n);
      Vector<double>                       value(dim);
      Vector<double>                       cell_div(n);
      const bool                           axi = prm.axisymmetric;
      K_full                                   = 0;
      base_matrix                              = 0;
      f                                        = 0;
      divergence.assign(mesh.triangulation.n_active_cells(), {});
      cell_measures.assign(mesh.triangulation.n_active_cells(), 0.);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          cell_matrix = 0;
          cell_rhs    = 0;
          cell_div    = 0;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Point<dim> &x = fe_values.quadrature_point(q);
              // Axisymmetric: integrals over the ring, weight 2 pi r; strain gains the hoop
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
              if (body)
                body->vector_value(x, value);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const SymmetricTensor<2, dim> s_i =
                    2 * mu * eps[i] + lam * div[i] * unit_symmetric_tensor<dim>();
                  const double s_i_hoop = 2 * mu * eps_hoop[i] + lam * div[i];
                  for (unsigned int j = 0; j < n; ++j)
                    cell_matrix(i, j) += (s_i * eps[j] + s_i_hoop * eps_hoop[j]) * JxW;
                  double r = -(sigma0 * eps[i]) - prm.pre_stress_hoop * eps_hoop[i];
                  if (body)
                    {
                      const unsigned int c = fe.system_to_component_index(i).first;
                      r += value[c] * fe_values.shape_value(i, q);
                    }
                  cell_rhs(i) += r * JxW;
                  cell_div(i) += div[i] * JxW;
                }
            }
          for (const unsigned int fn : cell->face_indices())
            if (cell->face(fn)->at_boundary())
              {
                const auto id = cell->face(fn)->boundary_id();
                const bool tr = traction.count(id) > 0, pr = pressure.count(id) > 0;
                if (!tr && !pr)
                  continue;
                fe_face.reinit(cell, fn);
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  {
                    const double JxW =
                      measure_weight(axi, fe_face.quadrature_point(q)) * fe_face.JxW(q);
                    Tensor<1, dim> t;
                    if (tr)
                      {
                        traction[id]->vector_value(fe_face.quadrature_point(q), value);
                        for (unsigned int d = 0; d < dim; ++d)
                          t[d] += value[d];
                      }
                    if (pr)
                      t -=
                        pressure[id]->value(fe_face.quadrature_point(q)) * fe_face.normal_vector(q);
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        const unsigned int c = fe.system_to_component_index(i).first;
                        cell_rhs(i) += t[c] * fe_face.shape_value(i, q) * JxW;
                      }
                  }
              }
          cell->get_dof_indices(local);
          K_full.add(local, cell_matrix);
          for (unsigned int i = 0; i < n; ++i)
            {
              f(local[i]) += cell_rhs(i);
              if (cell_div(i) != 0)
                divergence[cell->active_cell_index()].emplace_back(local[i], cell_div(i));
            }
          constraints_hom.distribute_local_to_global(cell_matrix, local, base_matrix);
        }
      f_fixed = f;
      assemble_coupling();
    }

    template <int dim>
    void
    ContactProblem<dim>::assemble_coupling()
    {
      const unsigned int n_u = dof_handler.n_dofs();
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        for (const auto &e : coupling[fi])
          if (!constraints_hom.is_constrained(e.dof))
            base_matrix.add(e.dof, n_u + dim * fi + e.component, e.value);
      // A typical multiplier magnitude for the stopping criterion: the load.
      lambda_scale = 0;
    }

    template <int dim>
    Tensor<2, dim>
    ContactProblem<dim>::frame(const unsigned int fi) const
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
    Tensor<1, dim>
    ContactProblem<dim>::jump(const unsigned int fi) const
    {
      Tensor<1, dim> j;
      for (const auto &e : coupling[fi])
        j[e.component] += e.value * u(e.dof);
      return j / face_measures[fi];
    }

    template <int dim>
    Tensor<1, dim>
    ContactProblem<dim>::multiplier(const unsigned int fi) const
    {
      Tensor<1, dim> l;
      for (unsigned int d = 0; d < dim; ++d)
        l[d] = lambda(dim * fi + d);
      return l;
    }

    template <int dim>
    FaceState
    ContactProblem<dim>::state(const unsigned int fi) const
    {
      const Tensor<2, dim>       R = frame(fi);
      const LocalContactLaw<dim> law{friction_values[fi], prm.c};
      return law.state(R * multiplier(fi), R * jump(fi));
    }

    template <int dim>
    void
    ContactProblem<dim>::apply_elasticity(Vector<double> &r) const
    {
      // K_full is square of size n_dofs() but only has entries in the displacement block.
      Vector<double> x(n_dofs()), y(n_dofs());
      for (unsigned int i = 0; i < u.size(); ++i)
        x(i) = u(i);
      K_full.vmult(y, x);
      for (unsigned int i = 0; i < u.size(); ++i)
        r(i) = y(i);
    }

    template <int dim>
    typename ContactProblem<dim>::ResidualParts
    ContactProblem<dim>::residual_parts(const double c) const
    {
      ResidualParts parts;
      // Mechanical rows: f - K u - B^T lambda on unconstrained dofs.
      Vector<double> r(dof_handler.n_dofs());
      apply_elasticity(r);
      r.sadd(-1., f);
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        for (const auto &e : coupling[fi])
          r(e.dof) -= e.value * lambda(dim * fi + e.component);
      for (unsigned int i = 0; i < r.size(); ++i)
        if (!constraints.is_constrained(i))
          {
            parts.mechanical += r(i) * r(i);
            parts.load += f(i) * f(i);
          }
      // Contact rows, (25)-(26) scaled to stress units, weighted by |sigma|.
      for (unsigned int fi = 0; fi < coupling.size(); ++fi)
        {
          const Tensor<2, dim>       R = frame(fi);
          const LocalContactLaw<dim> law{friction_values[fi], c};
          const Tensor<1, dim>       l = R * multiplier(fi), j = R * jump(fi);
          const double               w = face_measures[fi];
          parts.contact += w * law.residual(l, j, true).norm_square();
          parts.contact_unscaled += w * law.residual(l, j, false).norm_square();
          parts.lambda += w * l.norm_square();
          parts.c_jump += w * (c * j).norm_square();
        }
      return parts;
    }

    template <int dim>
    double
    ContactProblem<dim>::merit(const ResidualParts &r, const double scale2)
    {
      const double rel_c = (scale2 > 0 ? std::sqrt(r.contact / scale2) : std::sqrt(r.contact));
      const double rel_m = (r.load > 0 ? std::sqrt(r.mechanical / r.load) : 0.);
      return std::max(rel_c, rel_m);
    }

    template <int dim>
    double
    ContactProblem<dim>::relative_residual() const
    {
      // max(|C| / |lambda|, |f - K u - B^T lambda| / |f|); |c [u]| scales C when lambda = 0.
      const ResidualParts r = residual_parts(prm.c);
      return merit(r, r.lambda > 0 ? r.lambda : r.c_jump);
    }

    template <int dim>
    double
    ContactProblem<dim>::time_linear_solve() const
    {
      // Linear elasticity with every fracture open: the multiplier rows read lambda = 0.
      Timer                clock;
      SparseMatrix<double> A(sparsity);
      A.copy_from(base_matrix);
      const unsigned int n_u = dof_handler.n_dofs();
      for (unsigned int i = n_u; i < n_dofs(); ++i)
        A.set(i, i, 1.);
      Vector<double> rhs(n_dofs()), x(n_dofs());
      for (unsigned int i = 0; i < n_u; ++i)
        rhs(i) = constraints_hom.is_constrained(i) ? 0. : f(i);
      clock.restart();
      // The LU of the contact iterations (symbolic analysis + numeric factorization + solve).
      SparseLU direct;
      direct.factorize(A);
      direct.vmult(x, rhs);
      return clock.wall_time();
    }

    template <int dim>
    double
    ContactProblem<dim>::time_linear_solve_cholesky() const
    {
      // Linear elasticity with every fracture open: K u = f, Cholesky factorization of the
      // constrained elasticity block + one solve.
      Timer              clock;
      const unsigned int n_u = dof_handler.n_dofs();
      Vector<double>     x(n_u);
      for (unsigned int i = 0; i < n_u; ++i)
        x(i) = constraints_hom.is_constrained(i) ? 0. : f(i);
      clock.restart();
      SparseCholesky cholesky;
      cholesky.factorize(base_matrix, n_u);
      cholesky.solve(x);
      return clock.wall_time();
    }

    template <int dim>
    void
    ContactProblem<dim>::apply_linearization(const std::vector<Tensor<2, dim>> &AlR,
                                             const std::vector<Tensor<2, dim>> &AjR,
                                             const Vector<double>              &x,
                                             Vector<double>                    &y) const
    {
      // Rows [0, n_u): K x_u + B^T x_lambda (base_matrix, constrained rows as in the full
      // system); face rows: A_l R x_lambda + A_j R [x_u] (as assembled in solve()).
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
          const Tensor<1, dim> row = AlR[fi] * l + AjR[fi] * j;
          for (unsigned int i = 0; i < dim; ++i)
            y(n_u + dim * fi + i) = row[i];
        }
    }

    template <int dim>
    void
    ContactProblem<dim>::solve(const bool warm_start)
    {
      const unsigned int n_u = dof_handler.n_dofs();
      const unsigned int N   = n_dofs();
      const unsigned int n_f = coupling.size();
      check_input(prm.cycle_damping >= 0 && prm.cycle_damping < 1,
                  "Mechanics/Cycle damping",
                  "must be in [0, 1)");
      check_input(prm.c_start >= 0, "Mechanics/Continuation c start", "must be >= 0");
      check_input(prm.continuation_factor > 1, "Mechanics/Continuation factor", "must be > 1");
      residual_history.clear();
      initial_relative_history.clear();
      step_history.clear();
      backtracks = cycles_detected = 0;
      time_contact_rows = time_factorization = time_solves = time_residuals = 0;
      time_cholesky = time_form_W = 0;
      converged                   = false;
      if (prm.schur_complement && !schur && !schur_unavailable)
        {
          TimerOutput::Scope t(timer, "Mechanics: Schur complement setup");
          std::vector<bool>  constrained(n_u);
          for (unsigned int i = 0; i < n_u; ++i)
            constrained[i] = constraints_hom.is_constrained(i);
          try
            {
              schur = std::make_unique<MultiplierSchurComplement<dim>>(
                base_matrix, n_u, coupling, face_measures, constrained);
              time_cholesky = schur->time_cholesky;
              time_form_W   = schur->time_form_W;
              progress << "    Schur complement: Cholesky of K (" << n_u << " dofs, "
                       << schur->cholesky().factor_nonzeros() << " nonzeros in L) " << time_cholesky
                       << " s, W (" << dim * n_f << "^2, " << schur->reach_entries
                       << " nonzeros in L^{-1} P J^T) " << time_form_W << " s" << std::endl;
            }
          catch (const SolverFailure &e)
            {
              // A body held in place by the contact rows only (no Dirichlet condition on one
              // side of a through-going fracture) has a singular elasticity block: the full
              // system is still regular, so solve it instead.
              schur_unavailable = true;
              progress << "    Schur complement unavailable (" << e.what()
                       << "); solving the full system" << std::endl;
            }
        }
      if (!(warm_start && solved_once))
        {
          // Initial guess: u = 0 (plus Dirichlet values); open lambda = 0, or stick
          // lambda_n = given.
          u = 0;
          constraints.distribute(u);
          lambda = 0;
          if (prm.stick_guess)
            for (const auto &face : mesh.fracture_faces)
              for (unsigned int d = 0; d < dim; ++d)
                lambda(dim * face.index + d) = prm.initial_lambda_n * face.normal[d];
        }
      solved_once                  = true;
      const ResidualParts g0       = residual_parts(prm.c);
      const double        g0_norm2 = g0.mechanical + g0.contact_unscaled;
      // Continuation in c: the complementarity functions (25)-(26) have the same zeros for every
      // c > 0, so c may move from c_start to the target during the iterations.
      double c_now = (prm.c_start > 0 ? prm.c_start : prm.c);
      // Face states of every iterate, for the cycling safeguard.
      std::vector<std::vector<FaceState>> seen_states;
      Vector<double>                      rhs(N), delta(N), u_old(n_u), lambda_old(lambda.size());
      Timer                               clock;
      std::vector<Tensor<2, dim>>         AlR(n_f), AjR(n_f);
      factorizations = reused_factorizations = 0;
      bool line_search_on                    = false;
      for (iterations = 1; iterations <= prm.max_iterations; ++iterations)
        {
          std::vector<FaceState> states(n_f);
          bool                   same_matrix = factorization != nullptr;
          {
            TimerOutput::Scope t(timer, "Mechanics: contact update");
            clock.restart();
            rhs = 0;
            // Mechanical residual f - K u - B^T lambda.
            Vector<double> r(n_u);
            apply_elasticity(r);
            for (unsigned int i = 0; i < n_u; ++i)
              rhs(i) = constraints_hom.is_constrained(i) ? 0. : f(i) - r(i);
            for (unsigned int fi = 0; fi < n_f; ++fi)
              for (const auto &e : coupling[fi])
                if (!constraints_hom.is_constrained(e.dof))
                  rhs(e.dof) -= e.value * lambda(dim * fi + e.component);
            // Contact rows A_l R lambda + A_j R [u] = r (Section 5.1 / specs.md 3a), for the
            // increment.
            for (unsigned int fi = 0; fi < n_f; ++fi)
              {
                const Tensor<2, dim>       R = frame(fi);
                const LocalContactLaw<dim> law{friction_values[fi], c_now};
                const Tensor<1, dim>       l = R * multiplier(fi), j = R * jump(fi);
                Tensor<2, dim>             Al, Aj;
                Tensor<1, dim>             r_loc;
                states[fi]               = law.rows(prm.method, l, j, Al, Aj, r_loc);
                const Tensor<1, dim> res = r_loc - Al * l - Aj * j;
                AlR[fi]                  = Al * R;
                AjR[fi]                  = Aj * R;
                same_matrix =
                  same_matrix && AlR[fi] == factorized_AlR[fi] && AjR[fi] == factorized_AjR[fi];
                for (unsigned int i = 0; i < dim; ++i)
                  rhs(n_u + dim * fi + i) = res[i];
              }
            // The Jacobian only depends on the face rows: when none changed (the active set
            // method with an unchanged active set, e.g. in warm-started coupled solves), the
            // factorization is reused.
            if (!same_matrix && !schur)
              {
                if (system_matrix.empty())
                  system_matrix.reinit(sparsity);
                system_matrix.copy_from(base_matrix);
                for (unsigned int fi = 0; fi < coupling.size(); ++fi)
                  {
                    const double m = face_measures[fi];
                    for (unsigned int i = 0; i < dim; ++i)
                      {
                        const unsigned int row = n_u + dim * fi + i;
                        for (unsigned int k = 0; k < dim; ++k)
                          system_matrix.add(row, n_u + dim * fi + k, AlR[fi][i][k]);
                        for (const auto &e : coupling[fi])
                          if (!constraints_hom.is_constrained(e.dof))
                            system_matrix.add(row, e.dof, AjR[fi][i][e.component] * e.value / m);
                      }
                  }
              }
            time_contact_rows += clock.wall_time();
          }
          {
            TimerOutput::Scope t(timer, "Mechanics: factorization and solve");
            // The factorization is exact while no face row changed (the active set method with
            // an unchanged active set, e.g. warm-started coupled solves). Otherwise only face rows
            // changed (often few of them): optionally try GMRES preconditioned by the last LU
            // factors, which needs about (changed rows + 1) steps, so only when few face states
            // changed; else refactorize.
            unsigned int changed = 0;
            if (!seen_states.empty())
              for (unsigned int fi = 0; fi < n_f; ++fi)
                changed += (seen_states.back()[fi] != states[fi]);
            bool solved = false;
            if (schur)
              {
                // Schur complement on the multipliers (multiplier_schur_complement.h).
                const double lu0 = schur->time_dense_lu, s0 = schur->time_solves;
                if (!schur->set_rows(AlR, AjR))
                  ++factorizations;
                schur->solve(rhs, delta);
                // Iterative refinement on the full system: the dense multiplier system is
                // worse conditioned than the full one (stick rows against W ~ h/E), and a
                // solve error of ~1e-7 stalls warm-started coupled solves and spoils the
                // finite-difference products of Newton-Krylov.
                Vector<double> defect(N), correction(N);
                for (unsigned int k = 0; k < 3; ++k)
                  {
                    apply_linearization(AlR, AjR, delta, defect);
                    defect.sadd(-1., 1., rhs);
                    if (defect.l2_norm() <= 1e-14 * rhs.l2_norm())
                      break;
                    schur->solve(defect, correction);
                    delta += correction;
                  }
                time_factorization += schur->time_dense_lu - lu0;
                time_solves += schur->time_solves - s0;
                solved = true;
              }
            if (!solved && same_matrix)
              {
                clock.restart();
                factorization->vmult(delta, rhs);
                time_solves += clock.wall_time();
                solved = true;
              }
            if (!solved && factorization && prm.reuse_iterations > 0 &&
                dim * changed < prm.reuse_iterations)
              {
                clock.restart();
                SolverControl control(prm.reuse_iterations, 1e-12 * rhs.l2_norm(), false, false);
                SolverGMRES<Vector<double>> gmres(
                  control,
                  SolverGMRES<Vector<double>>::AdditionalData(prm.reuse_iterations + 2, true));
                delta = 0;
                try
                  {
                    gmres.solve(system_matrix, delta, rhs, *factorization);
                    solved = true;
                    ++reused_factorizations;
                  }
                catch (const SolverControl::NoConvergence &)
                  {
                  }
                time_solves += clock.wall_time();
              }
            if (!solved)
              {
                clock.restart();
                // One LU object for every solve: the symbolic analysis of the (fixed) pattern
                // is reused. No iterative refinement: the contact iteration corrects the solve
                // error itself (on the 5.3 paper mesh refinement tripled the solve time).
                if (!factorization)
                  factorization = std::make_unique<SparseLU>(/*refinement_steps=*/0);
                try
                  {
                    factorization->factorize(system_matrix);
                  }
                catch (const std::exception &e)
                  {
                    factorization.reset();
                    throw SolverFailure(std::string("contact mechanics: ") + e.what());
                  }
                factorized_AlR = AlR;
                factorized_AjR = AjR;
                ++factorizations;
                ++n_factorizations;
                time_factorization += clock.wall_time();
                clock.restart();
                factorization->vmult(delta, rhs);
                time_solves += clock.wall_time();
              }
          }

          // Safeguard against active-set cycling: states equal to those of an earlier iterate
          // other than the previous one mean the iteration revisits a set; damp the step.
          double alpha_max = 1;
          if (prm.cycle_damping > 0)
            {
              for (unsigned int k = 0; k + 1 < seen_states.size(); ++k)
                if (seen_states[k] == states && seen_states.back() != states)
                  {
                    alpha_max = prm.cycle_damping;
                    ++cycles_detected;
                    progress << "    contact iteration " << iterations
                             << ": face states repeat those of iteration " << k + 1
                             << "; step damped by " << prm.cycle_damping << std::endl;
                    break;
                  }
            }
          seen_states.push_back(states);

          TimerOutput::Scope t(timer, "Mechanics: contact update");
          clock.restart();
          u_old         = u;
          lambda_old    = lambda;
          auto set_step = [&](const double alpha) {
            for (unsigned int i = 0; i < n_u; ++i)
              u(i) = u_old(i) + alpha * delta(i);
            for (unsigned int i = 0; i < lambda.size(); ++i)
              lambda(i) = lambda_old(i) + alpha * delta(n_u + i);
          };
          double alpha = alpha_max;
          set_step(alpha);
          // The line search runs from the start, or (trigger on stagnation) from the first
          // iterate whose relative residual did not decrease.
          const unsigned int nr = residual_history.size();
          if (prm.line_search && !line_search_on &&
              (!prm.line_search_on_stagnation ||
               (nr > 1 && residual_history[nr - 1] >= residual_history[nr - 2])))
            line_search_on = true;
          if (line_search_on)
            {
              // Backtracking (Armijo) on the merit max(|C|/S, |r_mech|/|f|) of eqs. (25)-(26)
              // with one multiplier scale S for all trial steps (the larger of the current and
              // the full-step multipliers).
              const ResidualParts trial = residual_parts(c_now);
              std::swap(u, u_old);
              std::swap(lambda, lambda_old);
              const ResidualParts current = residual_parts(c_now);
              std::swap(u, u_old);
              std::swap(lambda, lambda_old);
              double scale2 = std::max(trial.lambda, current.lambda);
              if (scale2 <= 0)
                scale2 = std::max(trial.c_jump, current.c_jump);
              // Non-monotone reference (Grippo-Lampariello-Lucidi): the largest of the current
              // merit and the relative residuals of the last `memory - 1` iterates.
              double phi0 = merit(current, scale2);
              for (unsigned int k = 1; k < prm.line_search_memory && k < residual_history.size();
                   ++k)
                phi0 = std::max(phi0, residual_history[residual_history.size() - 1 - k]);
              double       phi  = merit(trial, scale2);
              double       best = phi, best_alpha = alpha;
              unsigned int halvings = 0;
              while (phi > (1 - 1e-4 * alpha) * phi0 && halvings < prm.line_search_halvings)
                {
                  alpha /= 2;
                  ++halvings;
                  ++backtracks;
                  set_step(alpha);
                  phi = merit(residual_parts(c_now), scale2);
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
            }
          step_history.push_back(alpha);
          const double res = relative_residual();
          time_residuals += clock.wall_time();
          residual_history.push_back(res);
          {
            const ResidualParts g = residual_parts(prm.c);
            initial_relative_history.push_back(
              g0_norm2 > 0 ? std::sqrt((g.mechanical + g.contact_unscaled) / g0_norm2) : 0.);
          }
          progress << "    contact iteration " << iterations << ": relative residual "
                   << std::scientific << std::setprecision(3) << res << std::defaultfloat;
          if (alpha != 1)
            progress << ", step " << alpha;
          if (c_now != prm.c)
            progress << ", c = " << c_now;
          progress << std::endl;
          if (res <= prm.tolerance && c_now == prm.c)
            {
              converged = true;
              return;
            }
          // Continuation: move c towards the target once the face states are those of the
          // previous iterate (the active set has settled for this c).
          if (c_now != prm.c && seen_states.size() > 1 &&
              seen_states[seen_states.size() - 2] == states)
            c_now = (c_now < prm.c ? std::min(prm.c, c_now * prm.continuation_factor) :
                                     std::max(prm.c, c_now / prm.continuation_factor));
        }
      iterations = prm.max_iterations;
      std::ostringstream s;
      s << "contact solver ("
        << (prm.method == ContactMethod::active_set ? "active set" : "semismooth newton")
        << ") did not converge in " << prm.max_iterations << " iterations; last relative residual "
        << std::scientific << std::setprecision(3) << residual_history.back();
      throw SolverFailure(s.str());
    }

    template <int dim>
    void
    ContactProblem<dim>::reset()
    {
      solved_once = false;
      factorization.reset();
      factorized_AlR.clear();
      factorized_AjR.clear();
      if (schur)
        schur->clear_rows();
    }

    template <int dim>
    void
    ContactProblem<dim>::set_contact_solver(const ContactMethod method,
                                            const double        c,
                                            const bool          stick_guess)
    {
      check_input(c > 0, "Mechanics/Complementarity parameter c", "must be positive");
      prm.method      = method;
      prm.c           = c;
      prm.stick_guess = stick_guess;
      reset();
    }

    template <int dim>
    void
    ContactProblem<dim>::set_equivalent_pressures(const std::vector<double> &p_E_matrix,
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
    std::vector<double>
    ContactProblem<dim>::cell_divergence() const
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
    ContactProblem<dim>::normal_jump(const unsigned int fi) const
    {
      return mesh.fracture_faces[fi].normal * jump(fi);
    }

    template <int dim>
    double
    ContactProblem<dim>::elastic_energy() const
    {
      Vector<double> Ku(u.size());
      apply_elasticity(Ku);
      return 0.5 * (u * Ku);
    }

    template <int dim>
    double
    ContactProblem<dim>::external_work(const Vector<double> &u_old) const
    {
      double w = 0;
      for (unsigned int i = 0; i < u.size(); ++i)
        w += f_fixed(i) * (u(i) - u_old(i));
      return w;
    }

    template <int dim>
    SymmetricTensor<2, dim>
    ContactProblem<dim>::stress(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                const Point<dim> &unit_point) const
    {
      const Quadrature<dim> q(unit_point);
      FEValues<dim>         fv(mesh.mapping(), fe, q, update_gradients);
      fv.reinit(cell);
      std::vector<SymmetricTensor<2, dim>> eps(1);
      fv[FEValuesExtractors::Vector(0)].get_function_symmetric_gradients(u, eps);
      const double            E = prm.young_modulus, nu = prm.poisson_ratio;
      const double            mu = E / (2 * (1 + nu)), lam = E * nu / ((1 + nu) * (1 - 2 * nu));
      SymmetricTensor<2, dim> s =
        2 * mu * eps[0] + lam * trace(eps[0]) * unit_symmetric_tensor<dim>();
      if (!prm.pre_stress.empty())
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            s[i][j] += prm.pre_stress[i * dim + j];
      return s;
    }

    template class ContactProblem<2>;
    template class ContactProblem<3>;
  } // namespace mechanics
} // namespace porofrac
