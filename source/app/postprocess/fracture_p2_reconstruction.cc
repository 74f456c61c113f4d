// SPDX-License-Identifier: LGPL-2.1-or-later
#include <porofrac/app/postprocess/postprocessor.h>
#include <porofrac/io/output_file.h>
#include <porofrac/mechanics/fracture_reconstruction.h>

#include <iomanip>

namespace porofrac
{
  namespace app
  {
    using namespace dealii;

    namespace
    {
      /// fracture_p2.csv: the paper's P2 reconstructions of the jump and the multiplier at 3
      /// Gauss points per fracture face, local frame (deck entry Mechanics/Write P2
      /// reconstruction; 2D).
      template <int dim>
      class FractureP2Reconstruction : public Postprocessor<dim>
      {
      public:
        void
        execute(SceneView<dim> &scene, io::RunContext &context) override
        {
          const auto    &problem = *scene.mechanics;
          io::OutputFile file(context.path("fracture_p2.csv"));
          std::ostream  &csv = file.stream();
          csv << "fracture_id,face_id,s_begin,s_end,s,JxW,jump_n,jump_t,lambda_n,lambda_t\n"
              << std::setprecision(12);
          for (const auto &v : mechanics::reconstruct_fracture_fields(problem, 3))
            {
              const auto          &face = scene.mesh.fracture_faces[v.face];
              const Tensor<2, dim> R    = problem.frame(v.face);
              const Tensor<1, dim> j = R * v.jump, l = R * v.lambda;
              csv << face.fracture_id << ',' << v.face << ',' << face.abscissa_begin << ','
                  << face.abscissa_end << ',' << v.abscissa << ',' << v.JxW << ',' << j[0] << ','
                  << j[dim - 1] << ',' << l[0] << ',' << l[dim - 1] << '\n';
            }
          file.close();
        }
      };

      template <int dim>
      std::unique_ptr<Postprocessor<dim>>
      make(const PhysicsParameters &p)
      {
        if (dim != 2 || !p.mechanics.reports.p2_reconstruction)
          return nullptr;
        return std::make_unique<FractureP2Reconstruction<dim>>();
      }

      const std::string description = "fracture_p2.csv, the P2 reconstructions on the fractures";
    } // namespace

    POROFRAC_REGISTER(PostprocessorRegistry<2>, "fracture p2 reconstruction", description, make<2>)
    POROFRAC_REGISTER(PostprocessorRegistry<3>, "fracture p2 reconstruction", description, make<3>)
  } // namespace app
} // namespace porofrac
