// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef POROFRAC_GEOMETRY_DISTRIBUTED_CUT_MESH_H
#define POROFRAC_GEOMETRY_DISTRIBUTED_CUT_MESH_H

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/fully_distributed_tria.h>

#include <porofrac/geometry/cut_mesh.h>

#include <vector>

namespace porofrac
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * The owners of the active cells of @p serial_mesh among the ranks of @p communicator: a
     * METIS partition of the cell graph, in which the two cells of each fracture face are
     * neighbours (so that the partition does not follow the fractures), computed on rank 0 and
     * broadcast (no two ranks can disagree). Sets the subdomain ids of the cells. Collective.
     */
    template <int dim>
    std::vector<unsigned int>
    partition_cells(CutMesh<dim> &serial_mesh, const MPI_Comm communicator);

    /**
     * A cut mesh distributed over the ranks of a communicator: the serial CutMesh (built the
     * same on every rank, doc/parallel.md) is partitioned with METIS and handed to a
     * parallel::fullydistributed::Triangulation that holds only the locally owned cells and one
     * layer of ghost cells.
     *
     * Fracture faces keep their serial indices and their serial table (CutMesh::fracture_faces,
     * the same on every rank). A face is owned by the rank that owns its plus-side cell; its
     * minus-side cell may belong to another rank (the cut separates the two cells, so neither
     * is a ghost of the other): what the multiplier coupling needs from the other side travels
     * through distributed matrices, not through ghost cells.
     *
     * METIS sees the two cells of each fracture face as neighbours, so that the partition does
     * not follow the fractures (the cut makes them free boundaries of the cell graph).
     */
    template <int dim>
    class DistributedCutMesh
    {
    public:
      using cell_iterator = typename Triangulation<dim>::active_cell_iterator;

      /// Partitions @p serial (the subdomain ids of its cells are set) over the ranks of
      /// @p communicator and builds the distributed triangulation. Collective.
      DistributedCutMesh(CutMesh<dim> &serial, const MPI_Comm communicator);

      /// The serial mesh and its fracture-face table (the same on every rank).
      const CutMesh<dim>                            &serial;
      parallel::fullydistributed::Triangulation<dim> triangulation;

      MPI_Comm
      get_communicator() const
      {
        return communicator;
      }
      unsigned int
      this_rank() const
      {
        return rank;
      }

      const Mapping<dim> &
      mapping() const
      {
        return serial.mapping();
      }

      /// Rank owning the serial active cell with index @p serial_index.
      types::subdomain_id
      cell_owner(const unsigned int serial_index) const
      {
        return owner[serial_index];
      }
      /// The owning rank of every serial active cell.
      const std::vector<unsigned int> &
      cell_owners() const
      {
        return owner;
      }
      /// Rank owning fracture face @p f (the owner of its plus-side cell).
      types::subdomain_id
      face_owner(const unsigned int f) const
      {
        return owner[serial.fracture_faces[f].cell[plus]->active_cell_index()];
      }
      bool
      owns_face(const unsigned int f) const
      {
        return face_owner(f) == rank;
      }
      /// Fracture faces owned by this rank, in increasing index.
      const std::vector<unsigned int> &
      locally_owned_faces() const
      {
        return owned_faces;
      }
      /// Whether this rank owns the cell of side @p side of fracture face @p f.
      bool
      owns_side(const unsigned int f, const Side side) const
      {
        return owner[serial.fracture_faces[f].cell[side]->active_cell_index()] == rank;
      }

      /// The distributed cell (locally owned or ghost) of serial active cell @p serial_cell;
      /// the end iterator if this rank does not hold it.
      cell_iterator
      local_cell(const cell_iterator &serial_cell) const
      {
        return local_cells[serial_cell->active_cell_index()];
      }
      /// The serial active cell of a distributed cell.
      cell_iterator
      serial_cell(const cell_iterator &local) const;

    private:
      MPI_Comm                   communicator;
      unsigned int               rank;
      std::vector<unsigned int>  owner;
      std::vector<unsigned int>  owned_faces;
      std::vector<cell_iterator> local_cells;
    };
  } // namespace geometry
} // namespace porofrac

#endif
