// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <porofrac/base/cpr_preconditioner.h>
#include <porofrac/base/distributed_linear_solver.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/base/mumps_factorization.h>
#include <porofrac/base/registry.h>

#include <exception>
#include <memory>
#include <new>

namespace porofrac
{
  namespace
  {
    using namespace dealii;
    using VectorType = TrilinosWrappers::MPI::Vector;

    /// The preconditioner of a KrylovLinearSolver, set up per matrix.
    class Preconditioner
    {
    public:
      virtual ~Preconditioner() = default;

      virtual void
      initialize(const TrilinosWrappers::SparseMatrix &matrix) = 0;

      virtual void
      vmult(VectorType &dst, const VectorType &src) const = 0;
    };

    /// CprPreconditioner behind the Preconditioner interface.
    class CprStage : public Preconditioner
    {
    public:
      explicit CprStage(const DistributedLinearSolverOptions &options)
          : cpr(options.block_size, options.amg)
      {
      }

      void
      initialize(const TrilinosWrappers::SparseMatrix &matrix) override
      {
        cpr.initialize(matrix);
      }

      void
      vmult(VectorType &dst, const VectorType &src) const override
      {
        cpr.vmult(dst, src);
      }

    private:
      CprPreconditioner cpr;
    };

    /// Smoothed-aggregation AMG (Trilinos ML) on the whole system, one constant near-null
    /// mode per unknown of a node (point blocks of block_size unknowns).
    class AmgStage : public Preconditioner
    {
    public:
      explicit AmgStage(const DistributedLinearSolverOptions &options)
          : block_size(options.block_size)
          , settings(options.amg)
      {
      }

      void
      initialize(const TrilinosWrappers::SparseMatrix &matrix) override
      {
        const IndexSet &owned = matrix.locally_owned_range_indices();
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic      = true;
        data.smoother_type = "symmetric Gauss-Seidel";
        data.constant_modes.assign(block_size, std::vector<bool>(owned.n_elements(), false));
        unsigned int j = 0;
        for (const auto row : owned)
          data.constant_modes[row % block_size][j++] = true;
        initialize_amg(amg, matrix, data, settings);
      }

      void
      vmult(VectorType &dst, const VectorType &src) const override
      {
        amg.vmult(dst, src);
      }

    private:
      const unsigned int                block_size;
      const AmgSettings                 settings;
      TrilinosWrappers::PreconditionAMG amg;
    };

    /**
     * Right-preconditioned restarted GMRES (residuals are those of the unpreconditioned
     * system) to the relative tolerance the caller asks for (an inexact Newton step). A
     * system GMRES does not solve in Max linear iterations is solved by MUMPS instead and
     * counted (LinearSolverStatistics::direct_fallbacks): a hard system costs time, never a
     * failed step.
     */
    class KrylovLinearSolver : public DistributedLinearSolver
    {
    public:
      KrylovLinearSolver(const std::string                    &name,
                         std::unique_ptr<Preconditioner>       preconditioner,
                         const DistributedLinearSolverOptions &options)
          : registered_name(name)
          , preconditioner(std::move(preconditioner))
          , max_iterations(options.max_iterations)
          , what(options.what)
          , fallback(options.what + " (direct fallback)")
      {
      }

      void
      initialize(const TrilinosWrappers::SparseMatrix &m) override
      {
        matrix            = &m;
        factors_of_matrix = false;
        try
          {
            preconditioner->initialize(m);
          }
        catch (const SolverFailure &)
          {
            throw;
          }
        catch (const std::bad_alloc &)
          {
            throw;
          }
        catch (const std::exception &e)
          {
            throw SolverFailure(what + ": preconditioner set-up failed (" + e.what() + ")");
          }
      }

      void
      solve(const VectorType &b, VectorType &x, const double relative_tolerance) override
      {
        ++stats.solves;
        x                 = 0;
        const double norm = b.l2_norm();
        if (norm == 0)
          return;
        // A matrix GMRES already failed on (the caller reuses a set-up): its factors solve it.
        if (factors_of_matrix)
          {
            ++stats.direct_fallbacks;
            fallback.solve(x, b);
            return;
          }
        SolverControl           control(max_iterations, relative_tolerance * norm, false, false);
        SolverGMRES<VectorType> gmres(control, SolverGMRES<VectorType>::AdditionalData(50, true));
        try
          {
            gmres.solve(*matrix, x, b, *preconditioner);
          }
        catch (const SolverControl::NoConvergence &)
          {
            // Counted before MUMPS runs: a singular system fails there too.
            stats.iterations += control.last_step();
            ++stats.direct_fallbacks;
            fallback.factorize(*matrix);
            stats.direct_workspace_retries = fallback.workspace_retries();
            factors_of_matrix              = true;
            fallback.solve(x, b);
            return;
          }
        catch (const std::bad_alloc &)
          {
            throw;
          }
        catch (const std::exception &e)
          {
            throw SolverFailure(what + ": GMRES failed (" + e.what() + ")");
          }
        stats.iterations += control.last_step();
      }

      std::string
      name() const override
      {
        return registered_name;
      }

    private:
      const std::string                     registered_name;
      std::unique_ptr<Preconditioner>       preconditioner;
      const unsigned int                    max_iterations;
      const std::string                     what;
      const TrilinosWrappers::SparseMatrix *matrix = nullptr;
      MumpsFactorization                    fallback;
      /// Whether fallback holds the factors of the matrix of the last initialize().
      bool factors_of_matrix = false;
    };
  } // namespace

  POROFRAC_REGISTER(DistributedLinearSolverRegistry,
                    "cpr-gmres",
                    "GMRES preconditioned by the two-stage CPR preconditioner (AMG on the "
                    "total-mobility pressure matrix, then ILU(0) of the whole Jacobian; "
                    "doc/parallel.md), to the forcing tolerance of the Newton step; a system "
                    "not solved in Max linear iterations is solved by MUMPS.",
                    [](const DistributedLinearSolverOptions &options) {
                      return std::make_unique<KrylovLinearSolver>(
                        "cpr-gmres", std::make_unique<CprStage>(options), options);
                    })

  POROFRAC_REGISTER(DistributedLinearSolverRegistry,
                    "amg-gmres",
                    "GMRES preconditioned by smoothed-aggregation AMG (Trilinos ML) of the whole "
                    "Jacobian with the unknowns of a node as point blocks, to the forcing "
                    "tolerance of the Newton step; a system not solved in Max linear iterations "
                    "is solved by MUMPS.",
                    [](const DistributedLinearSolverOptions &options) {
                      return std::make_unique<KrylovLinearSolver>(
                        "amg-gmres", std::make_unique<AmgStage>(options), options);
                    })
} // namespace porofrac
