// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/io/json.h>
#include <porofrac/mechanics/fracture_reconstruction.h>

#include <cmath>
#include <iomanip>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /**
       * Errors against the analytical solution of paper Section 5.2.1 (a straight fracture of
       * half length l at angle psi under a remote compression sigma along x, Phan et al. 2003):
       * lambda_n = sigma sin^2 psi and the slip
       *   |[u]_tau|(tau) = 4 (1 - nu^2) / E sigma sin psi (cos psi - F sin psi) sqrt(l^2 - (l -
       * tau)^2) (plane strain; doc/algorithms.md explains the prefactor), on the central 90 % of
       * the fracture (tau in [0.1 l, 1.9 l]), both with the face means and with the paper's P2
       * reconstructions (4-point Gauss rule per face).
       */
      template <int dim>
      class SingleFractureErrors : public Postprocessor<dim>
      {
      public:
        explicit SingleFractureErrors(const mechanics::ContactParameters &p)
            : E(p.young_modulus)
            , nu(p.poisson_ratio)
            , sigma(p.reports.remote_stress)
            , psi(p.reports.fracture_angle * numbers::PI / 180.)
            , ell(p.reports.fracture_half_length)
        {
        }

        void
        execute(SceneView<dim> &scene, io::RunContext &context) override
        {
          const auto &problem    = *scene.mechanics;
          const auto  face_means = face_mean_errors(problem);
          context.report << "Mechanics: 5.2.1 errors (central 90 %, face means): jump_t rel L2 "
                         << std::scientific << std::setprecision(3) << face_means.jump_t
                         << ", lambda_n rel L2 " << face_means.lambda_n << std::defaultfloat
                         << std::endl;
          const auto p2 = reconstruction_errors(problem);
          context.report << "Mechanics: 5.2.1 errors (central 90 %, P2 reconstructions): jump_t "
                         << "rel L2 " << std::scientific << std::setprecision(3) << p2.jump_t
                         << ", lambda_n rel L2 " << p2.lambda_n << std::defaultfloat << std::endl;
          io::Json e                     = io::Json::object();
          e["jump_t_rel_l2"]             = p2.jump_t;
          e["lambda_n_rel_l2"]           = p2.lambda_n;
          e["jump_n_abs_l2"]             = p2.jump_n;
          e["jump_t_rel_l2_face_mean"]   = face_means.jump_t;
          e["lambda_n_rel_l2_face_mean"] = face_means.lambda_n;
          e["max_abs_jump_n"]            = face_means.jump_n;
          context.summary["errors"]      = e;
        }

      private:
        struct Errors
        {
          double jump_t, lambda_n, jump_n;
        };

        double
        slip(const double F, const double tau) const
        {
          return 4 * (1 - nu * nu) / E * sigma * std::sin(psi) *
                 (std::cos(psi) - F * std::sin(psi)) *
                 std::sqrt(std::max(0., ell * ell - (ell - tau) * (ell - tau)));
        }

        bool
        central(const double tau) const
        {
          return tau >= 0.1 * ell && tau <= 1.9 * ell;
        }

        /// Relative L2 errors of the face means; jump_n: max |[u]_n|.
        Errors
        face_mean_errors(const mechanics::ContactProblem<dim> &problem) const
        {
          const double lambda_n = sigma * std::sin(psi) * std::sin(psi);
          double       e_t = 0, n_t = 0, e_n = 0, n_n = 0, max_jn = 0;
          for (const auto &face : problem.get_mesh().fracture_faces)
            {
              const double tau = face.abscissa; // from the first point of the fracture
              if (!central(tau))
                continue;
              const double         s = slip(problem.friction(face.index), tau);
              const Tensor<2, dim> R = problem.frame(face.index);
              const Tensor<1, dim> j = R * problem.jump(face.index);
              const Tensor<1, dim> l = R * problem.multiplier(face.index);
              e_t += face.measure * std::pow(std::abs(j[1]) - s, 2);
              n_t += face.measure * s * s;
              e_n += face.measure * std::pow(l[0] - lambda_n, 2);
              n_n += face.measure * lambda_n * lambda_n;
              max_jn = std::max(max_jn, std::abs(j[0]));
            }
          return {std::sqrt(e_t / n_t), std::sqrt(e_n / n_n), max_jn};
        }

        /// Relative L2 errors of the P2 reconstructions; jump_n: absolute L2 norm of [u]_n.
        Errors
        reconstruction_errors(const mechanics::ContactProblem<dim> &problem) const
        {
          const double lambda_n = sigma * std::sin(psi) * std::sin(psi);
          double       e_t = 0, n_t = 0, e_n = 0, n_n = 0, jn = 0;
          for (const auto &v : mechanics::reconstruct_fracture_fields(problem, 4))
            {
              if (!central(v.abscissa))
                continue;
              const double         s = slip(problem.friction(v.face), v.abscissa);
              const Tensor<2, dim> R = problem.frame(v.face);
              const Tensor<1, dim> j = R * v.jump, l = R * v.lambda;
              e_t += v.JxW * std::pow(mechanics::LocalContactLaw<dim>::tangential(j).norm() - s, 2);
              n_t += v.JxW * s * s;
              e_n += v.JxW * std::pow(l[0] - lambda_n, 2);
              n_n += v.JxW * lambda_n * lambda_n;
              jn += v.JxW * j[0] * j[0];
            }
          return {std::sqrt(e_t / n_t), std::sqrt(e_n / n_n), std::sqrt(jn)};
        }

        const double E, nu, sigma, psi, ell;
      };

      template <int dim>
      std::unique_ptr<Postprocessor<dim>>
      make(const PhysicsParameters &p)
      {
        if (p.mechanics.reports.analytical_solution != "single fracture")
          return nullptr;
        return std::make_unique<SingleFractureErrors<dim>>(p.mechanics);
      }

      const std::string description = "errors against the analytical solution of Section 5.2.1";
    } // namespace

    POROFRAC_REGISTER(PostprocessorRegistry<2>, "analytical solution 5.2.1", description, make<2>)
    POROFRAC_REGISTER(PostprocessorRegistry<3>, "analytical solution 5.2.1", description, make<3>)
  } // namespace app
} // namespace porofrac
