// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/base/exceptions.h>
#include <porofrac/io/json.h>
#include <porofrac/mechanics/elasticity_assembly.h>
#include <porofrac/mechanics/fracture_reconstruction.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <utility>
#include <vector>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      const std::string parameter = "Mechanics/Analytical solution";

      /// The exact fields of a penny crack on its plane (global frame; doc/algorithms.md §17).
      struct PennySolution
      {
        Point<3>     centre;
        Tensor<1, 3> normal;        ///< n+
        double       radius   = 1;  ///< a
        double       lambda_n = 0;  ///< sigma sin^2 psi - p if closed, else 0
        Tensor<1, 3> lambda_t;      ///< uniform lambda_tau
        Tensor<1, 3> direction;     ///< unit slip direction (that of the resolved shear)
        double       slip_peak = 0; ///< slip magnitude at the centre
        double       open_peak = 0; ///< opening -[u]_n at the centre
        std::string  regime;        ///< "open", "slip" or "stick"

        double
        r(const Point<3> &x) const
        {
          const Tensor<1, 3> d = x - centre;
          return (d - (d * normal) * normal).norm();
        }

        double
        profile(const Point<3> &x) const
        {
          const double q = r(x) / radius;
          return std::sqrt(std::max(0., 1 - q * q));
        }
      };

      /**
       * Errors against a planar disc of radius a in an infinite isotropic medium under the remote
       * stress -sigma e_x e_x and the fracture pressure p: with n+ the disc normal, sin psi =
       * |n_x| and the resolved shear tau = sigma sin psi cos psi,
       * - closed (sigma sin^2 psi > p): lambda_n = sigma sin^2 psi - p; slip if tau > F lambda_n
       *   with the uniform stress drop dtau = tau - F lambda_n, stick (no slip) otherwise;
       * - open: lambda = 0, opening w(r) = 8 (1 - nu^2) (p - sigma sin^2 psi) a / (pi E)
       *   sqrt(1 - r^2/a^2) (Sneddon 1946), slip with dtau = tau;
       * - the slip is parallel to the resolved shear with magnitude 8 (1 - nu) / (pi (2 - nu))
       *   dtau / mu sqrt(a^2 - r^2) (Eshelby 1957, Segall 2010 eq. (4.74)).
       * Relative L2 errors over r <= 0.9 a of the P2 reconstructions (QGaussSimplex(3), 6 points
       * per face) and of the face means.
       */
      class PennyCrackErrors : public Postprocessor<3>
      {
      public:
        explicit PennyCrackErrors(const mechanics::ContactParameters &p)
            : prm(p)
        {
        }

        void
        execute(SceneView<3> &scene, io::RunContext &context) override
        {
          const auto         &problem = *scene.mechanics;
          const PennySolution exact   = solution(problem);
          context.report << "Mechanics: penny crack (" << exact.regime << "): peak slip "
                         << exact.slip_peak << " m, peak opening " << exact.open_peak
                         << " m, lambda_n " << exact.lambda_n << " Pa, |lambda_t| "
                         << exact.lambda_t.norm() << " Pa" << std::endl;
          io::Json e              = io::Json::object();
          e["regime"]             = exact.regime;
          e["slip_peak_exact"]    = exact.slip_peak;
          e["opening_peak_exact"] = exact.open_peak;
          e["lambda_n_exact"]     = exact.lambda_n;
          e["lambda_t_exact"]     = exact.lambda_t.norm();
          const Errors p2         = reconstruction_errors(problem, exact);
          const Errors means      = face_mean_errors(problem, exact);
          write(p2, "", e);
          write(means, "_face_mean", e);
          report(p2, "P2 reconstructions", context.report);
          report(means, "face means", context.report);
          context.summary["errors"] = e;
        }

      private:
        /// Error norms and their reference norms; an error whose reference is zero is absolute.
        struct Errors
        {
          double slip = 0, slip_ref = 0, angle = 0, angle_weight = 0, lambda_n = 0,
                 lambda_n_ref = 0, lambda_t = 0, lambda_t_ref = 0, opening = 0, opening_ref = 0,
                 area = 0;

          void
          add(const PennySolution &exact,
              const Point<3>      &x,
              const double         JxW,
              const Tensor<1, 3>  &jump,
              const Tensor<1, 3>  &lambda)
          {
            const Tensor<1, 3> n  = exact.normal;
            const double       g  = exact.profile(x);
            const Tensor<1, 3> jt = jump - (jump * n) * n;
            const Tensor<1, 3> lt = lambda - (lambda * n) * n;
            const double       s  = exact.slip_peak * g;
            slip += JxW * std::pow(jt.norm() - s, 2);
            slip_ref += JxW * s * s;
            if (jt.norm() > 0 && s > 0)
              {
                const double c = std::clamp(jt * exact.direction / jt.norm(), -1., 1.);
                angle += JxW * s * s * std::pow(std::acos(c), 2);
                angle_weight += JxW * s * s;
              }
            lambda_n += JxW * std::pow(lambda * n - exact.lambda_n, 2);
            lambda_n_ref += JxW * exact.lambda_n * exact.lambda_n;
            lambda_t += JxW * (lt - exact.lambda_t).norm_square();
            lambda_t_ref += JxW * exact.lambda_t.norm_square();
            opening += JxW * std::pow(-jump * n - exact.open_peak * g, 2);
            opening_ref += JxW * std::pow(exact.open_peak * g, 2);
            area += JxW;
          }

          /// sqrt(e / ref), or the root mean square over the area where ref = 0.
          double
          relative(const double e, const double ref) const
          {
            return ref > 0 ? std::sqrt(e / ref) : std::sqrt(e / area);
          }
        };

        PennySolution
        solution(const mechanics::ContactProblem<3> &problem) const
        {
          const auto &mesh = problem.get_mesh();
          check_input(mesh.fracture_ids.size() == 1 && !mesh.fracture_faces.empty(),
                      parameter,
                      "the penny crack needs exactly one fracture; the mesh has " +
                        std::to_string(mesh.fracture_ids.size()));
          PennySolution exact;
          exact.radius       = prm.reports.fracture_half_length;
          exact.normal       = mesh.fracture_faces.front().normal;
          double       area  = 0;
          double       F_min = std::numeric_limits<double>::max(), F_max = 0;
          Tensor<1, 3> c;
          for (const auto &face : mesh.fracture_faces)
            {
              check_input((face.normal - exact.normal).norm() < 1e-8,
                          parameter,
                          "the penny crack needs a planar fracture (face normals differ)");
              c += face.measure * face.centre;
              area += face.measure;
              F_min = std::min(F_min, problem.friction(face.index));
              F_max = std::max(F_max, problem.friction(face.index));
            }
          check_input(F_max - F_min <= 1e-12 * F_max,
                      parameter,
                      "the penny crack needs a uniform friction coefficient");
          exact.centre = Point<3>(c / area);

          const double E = prm.young_modulus, nu = prm.poisson_ratio, F = F_max;
          const double mu    = E / (2 * (1 + nu));
          const double sigma = prm.reports.remote_stress;
          const double nx    = exact.normal[0];
          Tensor<1, 3> ex;
          ex[0] = 1;
          // lambda = -T+ with T+ = sigma_remote n+ = -sigma n_x e_x.
          const Tensor<1, 3> shear = sigma * nx * (ex - nx * exact.normal);
          const double       tau   = shear.norm();
          exact.direction          = tau > 0 ? shear / tau : Tensor<1, 3>();
          const double lambda_n0   = sigma * nx * nx - pressure(problem, exact.centre);
          double       drop        = tau;
          if (lambda_n0 > 0)
            {
              exact.lambda_n = lambda_n0;
              exact.regime   = (tau > F * lambda_n0) ? "slip" : "stick";
              drop           = std::max(0., tau - F * lambda_n0);
              exact.lambda_t = exact.direction * std::min(tau, F * lambda_n0);
            }
          else
            {
              exact.regime    = "open";
              exact.open_peak = 8 * (1 - nu * nu) * (-lambda_n0) * exact.radius / (numbers::PI * E);
            }
          exact.slip_peak = 8 * (1 - nu) / (numbers::PI * (2 - nu)) * drop / mu * exact.radius;
          return exact;
        }

        /// The deck's fracture pressure at @p x (0 without one).
        double
        pressure(const mechanics::ContactProblem<3> &problem, const Point<3> &x) const
        {
          const mechanics::DeckLoads<3> loads(prm, problem.get_mesh());
          const auto it = loads.fracture_pressure.find(problem.get_mesh().fracture_ids.front());
          return it == loads.fracture_pressure.end() ? 0. : it->second->value(x);
        }

        bool
        inside(const PennySolution &exact, const Point<3> &x) const
        {
          return exact.r(x) <= 0.9 * exact.radius;
        }

        Errors
        reconstruction_errors(const mechanics::ContactProblem<3> &problem,
                              const PennySolution                &exact) const
        {
          Errors e;
          for (const auto &v : mechanics::reconstruct_fracture_fields(problem, 3))
            if (inside(exact, v.x))
              e.add(exact, v.x, v.JxW, v.jump, v.lambda);
          return e;
        }

        Errors
        face_mean_errors(const mechanics::ContactProblem<3> &problem,
                         const PennySolution                &exact) const
        {
          Errors e;
          for (const auto &face : problem.get_mesh().fracture_faces)
            if (inside(exact, face.centre))
              e.add(exact,
                    face.centre,
                    face.measure,
                    problem.jump(face.index),
                    problem.multiplier(face.index));
          return e;
        }

        /// Relative errors as X_rel_l2; where the exact field vanishes, the root mean square
        /// of the computed one as X_rms (Pa or m); the slip-weighted RMS angle between the
        /// computed and the exact slip direction.
        static std::vector<std::pair<std::string, double>>
        entries(const Errors &e)
        {
          std::vector<std::pair<std::string, double>> result;
          const auto put = [&](const std::string &name, const double err, const double ref) {
            result.emplace_back(name + (ref > 0 ? "_rel_l2" : "_rms"), e.relative(err, ref));
          };
          put("slip", e.slip, e.slip_ref);
          put("lambda_n", e.lambda_n, e.lambda_n_ref);
          put("lambda_t", e.lambda_t, e.lambda_t_ref);
          put("opening", e.opening, e.opening_ref);
          result.emplace_back("slip_direction_rad",
                              e.angle_weight > 0 ? std::sqrt(e.angle / e.angle_weight) : 0.);
          return result;
        }

        static void
        write(const Errors &e, const std::string &suffix, io::Json &json)
        {
          for (const auto &[name, value] : entries(e))
            json[name + suffix] = value;
        }

        static void
        report(const Errors &e, const std::string &what, std::ostream &out)
        {
          out << "Mechanics: penny crack errors (r <= 0.9 a, " << what << "):" << std::scientific
              << std::setprecision(3);
          for (const auto &[name, value] : entries(e))
            out << ' ' << name << ' ' << value;
          out << std::defaultfloat << std::endl;
        }

        const mechanics::ContactParameters prm;
      };

      std::unique_ptr<Postprocessor<3>>
      make(const PhysicsParameters &p)
      {
        if (p.mechanics.reports.analytical_solution != "penny crack")
          return nullptr;
        return std::make_unique<PennyCrackErrors>(p.mechanics);
      }

      const std::string description =
        "errors against the analytical solutions of a penny crack (Eshelby, Sneddon)";
    } // namespace

    POROFRAC_REGISTER(PostprocessorRegistry<3>,
                      "analytical solution penny crack",
                      description,
                      make)
  } // namespace app
} // namespace porofrac
