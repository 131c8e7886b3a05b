// src/commands/render_command.cpp -- see render_command.hpp.
#include "commands/render_command.hpp"

#include <stdexcept>

#include <sepax/contact_manifold.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/robust/robust_kernel.hpp>

#include "commands/shape_builder.hpp"
#include "render/svg_render.hpp"

namespace sepax::cli {

namespace {

template <class Policy>
SatResult<double> run(const ConvexPolyhedron<double>& a, const ConvexPolyhedron<double>& b, AlgorithmKind alg) {
  switch (alg) {
    case AlgorithmKind::Brute: return sat::brute_force<Policy>(a, b);
    case AlgorithmKind::Gauss: return sat::gauss_map<Policy>(a, b);
    case AlgorithmKind::Traversal: return sat::traversal<Policy>(a, b);
  }
  throw std::invalid_argument("unknown algorithm");
}

}  // namespace

std::string render_case_svg(const io::ShapeData& sa, const io::ShapeData& sb, const Pose* pose_b,
                            const RunConfig& cfg, const std::string& title) {
  const ConvexPolyhedron<double> a = build_shape<double>(sa);
  const ConvexPolyhedron<double> b = build_shape<double>(sb, pose_b);
  const SatResult<double> r = cfg.robust ? run<policy::Robust>(a, b, cfg.algorithm)
                                         : run<policy::Plain>(a, b, cfg.algorithm);
  render::SvgScene scene{&a, &b, r, {}, title};
  for (const auto& p : contact_manifold(a, b, r).points) {
    scene.contacts.push_back(render::SvgContact{p.position, sepax::to_double(p.separation)});
  }
  return render::render_svg(scene);
}

}  // namespace sepax::cli
