// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_FLOW_TPFA_GRID_H
#define POROFRAC_FLOW_TPFA_GRID_H

#include <deal.II/base/point.h>

#include <porofrac/flow/fracture_junctions.h>
#include <porofrac/flow/rock_type.h>
#include <porofrac/geometry/cut_mesh.h>

#include <set>
#include <vector>

namespace porofrac
{
  namespace flow
  {
    using namespace dealii;

    /**
     * Two-point flux connectivity of the hybrid-dimensional model (paper Section 4.1, Fig. 5),
     * as a graph of flow nodes joined by two-point connections:
     *
     * - matrix cells (centre = circumcentre, or centroid with Centres::centroid), numbered like
     *   active_cell_index();
     * - fracture cells, one per fracture face sigma (measure |sigma| d_f), numbered after them;
     * - matrix-fracture interface nodes K sigma, one per side of every fracture face (massless:
     *   no damaged layer);
     * - intersection nodes s where >= 3 fracture faces meet (massless, flux balance per phase);
     * - Dirichlet nodes at the centres of matrix boundary faces and at fracture nodes on the outer
     *   boundary whose boundary id has a Dirichlet condition.
     *
     * A connection joins two nodes a, b with a transmissibility T and, for each end, the rock type
     * whose laws give the upwind mobility at that end. Transmissibilities
     * (update_transmissibilities) depend on the per-cell inputs `permeability`, `aperture` and the
     * normal transmissibility Lambda_f, that another module may change between solves:
     * - matrix-matrix: |e| / (d_K,e/K_K + d_L,e/K_L) (signed circumcentre distances);
     * - matrix-boundary and matrix-interface: |e| K_K / d_K,e;
     * - interface-fracture: |sigma| Lambda_f (eq. (3));
     * - fracture-fracture through a junction s (FractureJunction: a fracture node in 2D, an edge
     *   of the fracture triangles in 3D) with two faces: harmonic mean of the half
     *   transmissibilities (d_f^3/12) |s| / d(x_sigma, s) (|s| = 1 in 2D, the edge length in
     *   3D; d from distance_to_junction, in 3D from the triangle's circumcentre normal to the
     *   edge); three or more faces (an intersection point in 2D, an intersection line segment in
     *   3D), or a Dirichlet junction: one half transmissibility per face to a junction node.
     * Matrix-matrix connections whose signed resistance d_K/K_K + d_L/K_L is below 1e-2 of the
     * unsigned one (a centre beyond the face and a permeability jump across it) use unsigned
     * distances. With `axisymmetric`, measures carry the weight 2 pi r with r = the second
     * coordinate.
     */
    template <int dim>
    class TpfaGrid
    {
    public:
      enum class NodeKind
      {
        matrix,
        fracture,
        interface,
        intersection,
        dirichlet_matrix,
        dirichlet_fracture
      };

      struct Node
      {
        NodeKind kind;
        Rock     rock;
        /// Weighted cell measure (matrix), weighted face measure (fracture), 0 otherwise.
        double             measure;
        Point<dim>         centre;
        types::boundary_id boundary_id = numbers::invalid_boundary_id;
      };

      enum class ConnectionKind
      {
        matrix_matrix,
        matrix_boundary,
        matrix_interface,
        interface_fracture,
        fracture_fracture,
        fracture_node
      };

      struct Connection
      {
        ConnectionKind kind;
        unsigned int   a, b;
        Rock           rock_a, rock_b;
        /// Weighted face measure (|e|, |sigma|, or |s| for fracture connections).
        double area;
        /// Distances from the centres of a and b to the face (d_b unused for one-sided ones).
        double d_a, d_b;
        double transmissibility = 0;
      };

      /// Where a cell's pressure lives (CellCentres): the paper's circumcentres (exact two-point
      /// fluxes on Delaunay meshes), or centroids with the projected half transmissibilities.
      enum class Centres
      {
        circumcentre,
        centroid
      };

      TpfaGrid(const geometry::CutMesh<dim>       &mesh,
               const bool                          axisymmetric,
               const std::set<types::boundary_id> &matrix_dirichlet_ids,
               const std::set<types::boundary_id> &fracture_dirichlet_ids,
               const Centres                       centres = Centres::circumcentre);

      /**
       * The distance of a half transmissibility |e| K / d from the cell centre @p x to the face
       * through @p face_centre with unit normal @p normal pointing away from @p x: circumcentres
       * (n . (x_e - x)), signed; centroids |x_e - x|^2 / (n . (x_e - x)), the projection of the
       * two-point gradient on n used by the TPFA of PorePy and MRST (positive for convex cells).
       */
      double
      half_distance(const Point<dim>     &x,
                    const Point<dim>     &face_centre,
                    const Tensor<1, dim> &normal) const
      {
        const Tensor<1, dim> d = face_centre - x;
        return centres == Centres::circumcentre ? d * normal : d.norm_square() / (d * normal);
      }

      const Centres centres;

      /// Recomputes every transmissibility from permeability, aperture and Lambda_f; validates
      /// them (InputError naming Flow/...).
      void
      update_transmissibilities();

      /// Pore measure of node i: |K| phi_K, |sigma| d_f, |sigma| d_a phi_a for an interface node
      /// (damaged layer), or 0.
      double
      pore_volume(const unsigned int i) const;

      unsigned int
      n_nodes() const
      {
        return nodes.size();
      }
      bool
      is_dirichlet(const unsigned int i) const
      {
        return nodes[i].kind == NodeKind::dirichlet_matrix ||
               nodes[i].kind == NodeKind::dirichlet_fracture;
      }

      /// The process of every node for a distributed Newton system: matrix cell K that of
      /// @p cell_owner[K]; a fracture cell that of the matrix cell on side 0 of its face, and
      /// both its interface nodes the fracture cell's; every other node that of the first node
      /// found connected to it (through a connection, in order).
      std::vector<unsigned int>
      node_owners(const std::vector<unsigned int> &cell_owner) const;

      /// Damaged layer on each side of a fracture: thickness d_a (m) and porosity
      /// phi_a; its saturation law is the fracture's (rock a = f, as in 5.3). 0 = massless
      /// interface nodes.
      double damaged_layer_thickness = 0, damaged_layer_porosity = 0;

      std::vector<Node>       nodes;
      std::vector<Connection> connections;
      unsigned int            n_matrix_cells;
      unsigned int            n_fracture_cells;
      unsigned int            n_interfaces;
      unsigned int            n_intersections;
      /// Number of matrix connections whose centre lies on the wrong side of the face.
      unsigned int n_non_admissible;
      /// Matrix-matrix connections with d_K,e + d_L,e < 1e-2 |sigma| (3D: 1e-2 sqrt|sigma|):
      /// cocircular pairs (centres merged, see merge_or_refuse) and, in 3D only, pairs with their
      /// centres in the wrong order (unsigned distances, inexact). Boundary and interface faces
      /// with d_K,e <= 0 use max(d_K,e, 1e-3 diameter).
      unsigned int n_fallback;
      /// 3D fracture connections whose pair of circumcentre distances to the edge sums to less
      /// than 1e-2 |edge| (cocircular pairs: at least 1e-5 |edge| in all; centres in the wrong
      /// order: unsigned distances) or whose one-sided distance is not positive (1e-3
      /// sqrt|sigma|).
      unsigned int n_non_admissible_fracture;

      /// Per-cell inputs: porosity and isotropic permeability (m^2) of matrix cells, aperture d_f
      /// (m) of fracture cells, normal transmissibility Lambda_f (m).
      std::vector<double> porosity;
      std::vector<double> permeability;
      std::vector<double> aperture;
      double              normal_transmissibility = 1.;

    private:
      /// Matrix cells (circumcentres), fracture cells and the two interface nodes per face.
      void
      make_nodes(const geometry::CutMesh<dim> &mesh, const bool axisymmetric);
      /// Matrix-matrix, matrix-interface and matrix-Dirichlet connections.
      void
      add_matrix_connections(const geometry::CutMesh<dim>       &mesh,
                             const bool                          axisymmetric,
                             const std::set<types::boundary_id> &matrix_dirichlet_ids);
      /// Distances of a matrix-matrix pair with d_a + d_b < 1e-2 |sigma| (@p measure): merged
      /// centres for cocircular pairs; an InputError in 2D, unsigned distances in 3D, for
      /// centres in the wrong order.
      void
      merge_or_refuse(double           &d_a,
                      double           &d_b,
                      const double      measure,
                      const Point<dim> &centre) const;
      /// Interface-fracture connections (eq. (3)).
      void
      add_interface_connections(const geometry::CutMesh<dim> &mesh, const bool axisymmetric);
      /// Half-transmissibility distance of fracture face @p face to @p junction, made positive.
      double
      one_sided_distance(const geometry::CutMesh<dim> &mesh,
                         const unsigned int            face,
                         const FractureJunction<dim>  &junction);
      /// Fracture-fracture connections through the fracture junctions, intersection and
      /// Dirichlet nodes.
      void
      add_fracture_node_connections(const geometry::CutMesh<dim>       &mesh,
                                    const bool                          axisymmetric,
                                    const std::set<types::boundary_id> &fracture_dirichlet_ids);
    };
  } // namespace flow
} // namespace porofrac

#endif
