// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/numerics/vector_tools.h>

#include <porofrac/base/exceptions.h>
#include <porofrac/io/expression.h>
#include <porofrac/io/text.h>
#include <porofrac/mechanics/elasticity_assembly.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace porofrac
{
  namespace mechanics
  {
    namespace
    {
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

      /// Point constraints (e.g. the symmetry of 5.2.1): every vertex at the point. Returns
      /// the number of cell vertices found at each point.
      template <int dim>
      std::vector<unsigned int>
      add_point_constraints(const ContactParameters   &prm,
                            const DoFHandler<dim>     &dof_handler,
                            const double               tol,
                            const bool                 homogeneous,
                            AffineConstraints<double> &target)
      {
        std::vector<unsigned int>         hits;
        std::set<types::global_dof_index> point_constrained;
        for (const PointConstraint &pc : prm.point_constraints)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = pc.point[d];
            hits.push_back(0);
            std::set<types::global_dof_index> own; // a vertex is seen from each of its cells
            for (const auto &cell : dof_handler.active_cell_iterators())
              if (!cell->is_artificial())
                for (const unsigned int v : cell->vertex_indices())
                  if (cell->vertex(v).distance(p) < tol)
                    {
                      ++hits.back();
                      for (const auto &[c, e] : pc.values)
                        {
                          const auto dof = cell->vertex_dof_index(v, c);
                          if (!own.insert(dof).second)
                            continue;
                          check_input(!point_constrained.count(dof),
                                      "Mechanics/Point constraints",
                                      "component " + std::string(1, "xyz"[c]) + " at " +
                                        io::to_text(p) + " is constrained twice");
                          if (target.is_constrained(dof))
                            continue;
                          target.add_line(dof);
                          if (!homogeneous)
                            target.set_inhomogeneity(
                              dof,
                              io::parse_expressions<dim>({e}, "Mechanics/Point constraints")
                                ->value(p));
                        }
                    }
            point_constrained.insert(own.begin(), own.end());
          }
        return hits;
      }

      /// The hoop strain phi_i,r / r of shape function @p i at quadrature point @p q in the
      /// axisymmetric case (r = x[1], radial component 1), else 0.
      template <int dim>
      double
      shape_hoop_strain(const FESystem<dim> &fe,
                        const FEValues<dim> &fe_values,
                        const bool           axisymmetric,
                        const unsigned int   i,
                        const unsigned int   q)
      {
        if (!axisymmetric || fe.system_to_component_index(i).first != 1)
          return 0.;
        return fe_values.shape_value(i, q) / fe_values.quadrature_point(q)[1];
      }
    } // namespace



    std::pair<double, double>
    lame_coefficients(const double E, const double nu)
    {
      return {E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))};
    }



    template <int dim>
    DeckLoads<dim>::DeckLoads(const ContactParameters &prm, const geometry::CutMesh<dim> &mesh)
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
        check_input(std::find(mesh.outer_boundary_ids.begin(), mesh.outer_boundary_ids.end(), id) !=
                      mesh.outer_boundary_ids.end(),
                    parameter,
                    "boundary id " + std::to_string(id) + " is not an outer boundary of the mesh");
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



    template <int dim>
    CellScratch<dim>::CellScratch(const Mapping<dim> &mapping, const FESystem<dim> &fe)
        : quadrature(3)
        , face_quadrature(3)
        , fe_values(mapping,
                    fe,
                    quadrature,
                    update_values | update_gradients | update_quadrature_points | update_JxW_values)
        , fe_face(mapping,
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



    template <int dim>
    void
    CellScratch<dim>::clear()
    {
      matrix       = 0;
      rhs          = 0;
      div_integral = 0;
      cell_measure = 0;
    }



    template <int dim>
    void
    assemble_cell_volume(const ContactParameters                              &prm,
                         const FESystem<dim>                                  &fe,
                         const typename DoFHandler<dim>::active_cell_iterator &cell,
                         const DeckLoads<dim>                                 &loads,
                         CellScratch<dim>                                     &scratch)
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
          scratch.cell_measure += JxW;
          for (unsigned int i = 0; i < n; ++i)
            {
              eps[i]      = fe_values[disp].symmetric_gradient(i, q);
              eps_hoop[i] = shape_hoop_strain(fe, fe_values, axi, i, q);
              div[i]      = trace(eps[i]) + eps_hoop[i];
            }
          if (loads.body)
            loads.body->vector_value(x, scratch.value);
          for (unsigned int i = 0; i < n; ++i)
            {
              const SymmetricTensor<2, dim> s_i =
                2 * mu * eps[i] + lam * div[i] * unit_symmetric_tensor<dim>();
              const double s_i_hoop = 2 * mu * eps_hoop[i] + lam * div[i];
              if (scratch.with_matrix)
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
    double
    cell_elastic_energy(const ContactParameters                              &prm,
                        const FESystem<dim>                                  &fe,
                        const typename DoFHandler<dim>::active_cell_iterator &cell,
                        const Vector<double>                                 &u_local,
                        CellScratch<dim>                                     &scratch)
    {
      // The quadratic form of assemble_cell_volume: 2 mu (eps_i:eps_j + hoop_i hoop_j) +
      // lambda div_i div_j.
      const auto [mu, lam] = lame_coefficients(prm.young_modulus, prm.poisson_ratio);
      const FEValuesExtractors::Vector disp(0);
      const bool                       axi       = prm.axisymmetric;
      auto                            &fe_values = scratch.fe_values;
      fe_values.reinit(cell);
      double energy = 0;
      for (unsigned int q = 0; q < scratch.quadrature.size(); ++q)
        {
          const Point<dim>       &x = fe_values.quadrature_point(q);
          SymmetricTensor<2, dim> eps;
          double                  hoop = 0;
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              eps += u_local(i) * fe_values[disp].symmetric_gradient(i, q);
              hoop += u_local(i) * shape_hoop_strain(fe, fe_values, axi, i, q);
            }
          const double div = trace(eps) + hoop;
          energy += (mu * (eps * eps + hoop * hoop) + 0.5 * lam * div * div) *
                    measure_weight(axi, x) * fe_values.JxW(q);
        }
      return energy;
    }



    template <int dim>
    void
    assemble_cell_boundary(const ContactParameters                              &prm,
                           const FESystem<dim>                                  &fe,
                           const typename DoFHandler<dim>::active_cell_iterator &cell,
                           const DeckLoads<dim>                                 &loads,
                           CellScratch<dim>                                     &scratch)
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
    double
    add_side_coupling(const bool                                            axisymmetric,
                      const FESystem<dim>                                  &fe,
                      FEFaceValues<dim>                                    &fe_face,
                      const typename DoFHandler<dim>::active_cell_iterator &cell,
                      const unsigned int                                    face_no,
                      const double                                          sign,
                      std::map<std::pair<types::global_dof_index, unsigned int>, double> &entries)
    {
      std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
      fe_face.reinit(cell, face_no);
      cell->get_dof_indices(local);
      const unsigned int n_q     = fe_face.get_quadrature().size();
      double             measure = 0;
      for (unsigned int q = 0; q < n_q; ++q)
        measure += measure_weight(axisymmetric, fe_face.quadrature_point(q)) * fe_face.JxW(q);
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          if (!fe.has_support_on_face(i, face_no))
            continue;
          const unsigned int comp = fe.system_to_component_index(i).first;
          double             v    = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            v += fe_face.shape_value_component(i, q, comp) *
                 measure_weight(axisymmetric, fe_face.quadrature_point(q)) * fe_face.JxW(q);
          entries[{local[i], comp}] += sign * v;
        }
      return measure;
    }



    template <int dim>
    std::vector<unsigned int>
    add_displacement_constraints(const ContactParameters      &prm,
                                 const geometry::CutMesh<dim> &mesh,
                                 const DoFHandler<dim>        &dof_handler,
                                 const double                  point_tolerance,
                                 const bool                    homogeneous,
                                 AffineConstraints<double>    &target)
    {
      const std::string pname = "Mechanics/Dirichlet";
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
                                                   target,
                                                   ComponentMask(mask));
        }
      return add_point_constraints(prm, dof_handler, point_tolerance, homogeneous, target);
    }



    void
    check_displacement_constraints(const ContactParameters         &prm,
                                   const std::vector<unsigned int> &point_hits,
                                   const bool                       any_constraint)
    {
      for (unsigned int i = 0; i < point_hits.size(); ++i)
        if (point_hits[i] == 0)
          {
            const auto        &p = prm.point_constraints[i].point;
            std::ostringstream s;
            for (unsigned int d = 0; d < p.size(); ++d)
              s << (d > 0 ? " " : "") << p[d];
            throw InputError("Mechanics/Point constraints",
                             "the point (" + s.str() + ") is not a mesh vertex");
          }
      check_input(any_constraint,
                  "Mechanics/Dirichlet",
                  "no Dirichlet condition or point constraint: the elasticity system is singular");
    }

#define POROFRAC_INSTANTIATE(dim)                                                                 \
  template struct DeckLoads<dim>;                                                                 \
  template struct CellScratch<dim>;                                                               \
  template double cell_elastic_energy(const ContactParameters &,                                  \
                                      const FESystem<dim> &,                                      \
                                      const typename DoFHandler<dim>::active_cell_iterator &,     \
                                      const Vector<double> &,                                     \
                                      CellScratch<dim> &);                                        \
  template void   assemble_cell_volume(const ContactParameters &,                                 \
                                       const FESystem<dim> &,                                     \
                                       const typename DoFHandler<dim>::active_cell_iterator &,    \
                                       const DeckLoads<dim> &,                                    \
                                       CellScratch<dim> &);                                       \
  template void   assemble_cell_boundary(const ContactParameters &,                               \
                                         const FESystem<dim> &,                                   \
                                         const typename DoFHandler<dim>::active_cell_iterator &,  \
                                         const DeckLoads<dim> &,                                  \
                                         CellScratch<dim> &);                                     \
  template double add_side_coupling(                                                              \
    const bool,                                                                                   \
    const FESystem<dim> &,                                                                        \
    FEFaceValues<dim> &,                                                                          \
    const typename DoFHandler<dim>::active_cell_iterator &,                                       \
    const unsigned int,                                                                           \
    const double,                                                                                 \
    std::map<std::pair<types::global_dof_index, unsigned int>, double> &);                        \
  template std::vector<unsigned int> add_displacement_constraints(const ContactParameters &,      \
                                                                  const geometry::CutMesh<dim> &, \
                                                                  const DoFHandler<dim> &,        \
                                                                  const double,                   \
                                                                  const bool,                     \
                                                                  AffineConstraints<double> &);
    POROFRAC_INSTANTIATE(2)
    POROFRAC_INSTANTIATE(3)
#undef POROFRAC_INSTANTIATE
  } // namespace mechanics
} // namespace porofrac
