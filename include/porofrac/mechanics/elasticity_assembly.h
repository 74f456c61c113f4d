// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_MECHANICS_ELASTICITY_ASSEMBLY_H
#define POROFRAC_MECHANICS_ELASTICITY_ASSEMBLY_H

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <porofrac/geometry/cut_mesh.h>
#include <porofrac/mechanics/parameters.h>

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace porofrac
{
  namespace mechanics
  {
    using namespace dealii;

    /**
     * The cell and face kernels of the elasticity system, shared by the serial
     * (ElasticitySystem) and the distributed (DistributedElasticitySystem) assembly: each works
     * on one cell or one side of a fracture face and knows nothing of the global numbering.
     */

    /// Weight of the integrals: 2 pi r in axisymmetric mode (r = second coordinate), else 1.
    template <int dim>
    double
    measure_weight(const bool axisymmetric, const Point<dim> &p)
    {
      return axisymmetric ? 2 * numbers::PI * p[1] : 1.;
    }

    /// Local frame of a fracture face, rows n+ then the tangent(s) t (and n+ x t in 3D).
    template <int dim>
    Tensor<2, dim>
    face_frame(const geometry::FractureFace<dim> &face)
    {
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

    /// Lame coefficients (mu, lambda) of E and nu; in 2D they give plane strain.
    std::pair<double, double>
    lame_coefficients(const double E, const double nu);

    /// The fixed loads of the deck as functions (body force, tractions, pressures, pre-stress,
    /// fracture pressure). Checks the ids against @p mesh (InputError naming the entry).
    template <int dim>
    struct DeckLoads
    {
      DeckLoads(const ContactParameters &prm, const geometry::CutMesh<dim> &mesh);

      std::unique_ptr<FunctionParser<dim>>                               body;
      SymmetricTensor<2, dim>                                            sigma0;
      std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>> traction, pressure;
      /// Fluid pressure in the fractures by fracture id (none: no pressure).
      std::map<unsigned int, std::unique_ptr<FunctionParser<dim>>> fracture_pressure;
    };

    /// Per-cell work arrays and the cell's contributions (matrix, loads, int_K div phi_i, |K|).
    template <int dim>
    struct CellScratch
    {
      CellScratch(const Mapping<dim> &mapping, const FESystem<dim> &fe);

      /// Zeroes the contributions before the next cell.
      void
      clear();

      const QGaussSimplex<dim>     quadrature;
      const QGaussSimplex<dim - 1> face_quadrature;
      FEValues<dim>                fe_values;
      FEFaceValues<dim>            fe_face;
      /// Whether assemble_cell_volume forms the cell matrix (not needed for loads only).
      bool                                 with_matrix = true;
      FullMatrix<double>                   matrix;
      Vector<double>                       rhs, div_integral;
      double                               cell_measure = 0;
      std::vector<types::global_dof_index> local;
      std::vector<SymmetricTensor<2, dim>> eps;
      std::vector<double>                  eps_hoop, div;
      Vector<double>                       value;
    };

    /// 1/2 u_K^T A_K u_K of one cell without forming A_K: the integral of
    /// mu (eps:eps + eps_hoop^2) + lambda/2 div^2 of the cell's displacement @p u_local.
    template <int dim>
    double
    cell_elastic_energy(const ContactParameters                              &prm,
                        const FESystem<dim>                                  &fe,
                        const typename DoFHandler<dim>::active_cell_iterator &cell,
                        const Vector<double>                                 &u_local,
                        CellScratch<dim>                                     &scratch);

    /// 1/2 a(u, u) over this process's locally owned cells (every cell of a serial mesh), cell
    /// by cell without K; @p u holds the values of those cells' dofs (ghosted in parallel).
    template <int dim, typename VectorType>
    double
    elastic_energy_of_owned_cells(const ContactParameters &prm,
                                  const Mapping<dim>      &mapping,
                                  const FESystem<dim>     &fe,
                                  const DoFHandler<dim>   &dof_handler,
                                  const VectorType        &u)
    {
      CellScratch<dim> scratch(mapping, fe);
      Vector<double>   u_local(fe.n_dofs_per_cell());
      double           energy = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(scratch.local);
            for (unsigned int i = 0; i < scratch.local.size(); ++i)
              u_local(i) = u(scratch.local[i]);
            energy += cell_elastic_energy(prm, fe, cell, u_local, scratch);
          }
      return energy;
    }

    /// Elasticity matrix, body force, pre-stress, int_K div phi_i and the weighted |K| of one
    /// cell, added to @p scratch.
    template <int dim>
    void
    assemble_cell_volume(const ContactParameters                              &prm,
                         const FESystem<dim>                                  &fe,
                         const typename DoFHandler<dim>::active_cell_iterator &cell,
                         const DeckLoads<dim>                                 &loads,
                         CellScratch<dim>                                     &scratch);

    /// Tractions and pressures on the outer boundary faces of one cell, added to @p scratch.
    template <int dim>
    void
    assemble_cell_boundary(const ContactParameters                              &prm,
                           const FESystem<dim>                                  &fe,
                           const typename DoFHandler<dim>::active_cell_iterator &cell,
                           const DeckLoads<dim>                                 &loads,
                           CellScratch<dim>                                     &scratch);

    /**
     * One side of the coupling int_sigma lambda . [v] of a fracture face (paper eq. (10)),
     * [v] = v+ - v-: adds sign * int_sigma phi_i (weighted) to @p entries[(dof, component)] for
     * every shape function of @p cell with support on face @p face_no (sign +1 on the plus side),
     * and returns the weighted measure of the face.
     */
    template <int dim>
    double
    add_side_coupling(const bool                                            axisymmetric,
                      const FESystem<dim>                                  &fe,
                      FEFaceValues<dim>                                    &fe_face,
                      const typename DoFHandler<dim>::active_cell_iterator &cell,
                      const unsigned int                                    face_no,
                      const double                                          sign,
                      std::map<std::pair<types::global_dof_index, unsigned int>, double> &entries);

    /**
     * Constraints of the Dirichlet conditions and point constraints on the cells of
     * @p dof_handler that this process holds (all of them in serial), homogeneous or with the
     * deck's values. @p point_tolerance is the distance below which a vertex is at a point.
     * Returns, per point constraint, the number of cell vertices found at the point (0: the
     * point is not a vertex of these cells); whether a component is constrained twice is an
     * InputError. The caller closes @p constraints.
     */
    template <int dim>
    std::vector<unsigned int>
    add_displacement_constraints(const ContactParameters      &prm,
                                 const geometry::CutMesh<dim> &mesh,
                                 const DoFHandler<dim>        &dof_handler,
                                 const double                  point_tolerance,
                                 const bool                    homogeneous,
                                 AffineConstraints<double>    &constraints);

    /// The InputError of a point constraint that is not at a mesh vertex (hits[i] == 0), and of
    /// constraints without any Dirichlet condition.
    void
    check_displacement_constraints(const ContactParameters         &prm,
                                   const std::vector<unsigned int> &point_hits,
                                   const bool                       any_constraint);
  } // namespace mechanics
} // namespace porofrac

#endif
