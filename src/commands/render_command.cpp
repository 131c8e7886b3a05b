// src/commands/render_command.cpp -- see render_command.hpp.
#include "commands/render_command.hpp"

#include <stdexcept>

#include <sepax/contact_manifold.hpp>
#include <sepax/robust/robust_kernel.hpp>
#include <sepax/sat.hpp>

#include "commands/shape_builder.hpp"
#include "render/svg_render.hpp"

namespace sepax::cli {

std::string render_case_svg(const io::ShapeData& sa, const io::ShapeData& sb, const Pose* pose_b,
                            const RunConfig& cfg, const std::string& title) {
  const ConvexPolyhedron<double> a = build_shape<double>(sa);
  const ConvexPolyhedron<double> b = build_shape<double>(sb, pose_b);
  const SatAlgorithm alg = sat_algorithm(cfg.algorithm);
  const SatResult<double> r =
      cfg.robust ? sat::run<policy::Robust>(alg, a, b) : sat::run<policy::Plain>(alg, a, b);
  render::SvgScene scene{&a, &b, r, {}, title};
  for (const auto& p : contact_manifold(a, b, r).points) {
    scene.contacts.push_back(render::SvgContact{p.position, sepax::to_double(p.separation)});
  }
  return render::render_svg(scene);
}

}  // namespace sepax::cli
