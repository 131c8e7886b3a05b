// python/src/tools.cpp -- see tools.hpp.
#include "tools.hpp"

#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include <sepax/fuzz/cli.hpp>
#include <sepax/fuzz/generators.hpp>
#include <sepax/posing.hpp>

#include "render/svg_render.hpp"  // sepax_cli_lib's include directory (src/)

namespace sepax::python {

std::string render_query_svg(const ConvexPolyhedron<double>& a, const PoseD& pose_a,
                             const ConvexPolyhedron<double>& b, const PoseD& pose_b, const QueryOut& q,
                             const std::string& title) {
  const ConvexPolyhedron<double> wa = posed(a, to_transform<double>(pose_a));
  const ConvexPolyhedron<double> wb = posed(b, to_transform<double>(pose_b));
  render::SvgScene scene;
  scene.a = &wa;
  scene.b = &wb;
  scene.sat.overlap = q.overlap;
  scene.sat.early_out = q.early_out;
  scene.sat.feature = q.feature;
  scene.sat.separation = Separation<double>{q.separation, 1.0};
  scene.sat.axis = Vec3<double>(q.axis[0], q.axis[1], q.axis[2]);
  scene.sat.stats = q.stats;
  scene.title = title;
  for (const PointOut& p : q.points) {
    scene.contacts.push_back(
        render::SvgContact{Vec3<double>(p.position[0], p.position[1], p.position[2]), p.separation});
  }
  return render::render_svg(scene);
}

namespace {

fuzz::ShapeSpec spec_of(const ConvexPolyhedron<double>& p, int& rounded) {
  fuzz::ShapeSpec s;
  s.vertices = p.vertices();
  for (int f = 0; f < p.face_count(); ++f) s.faces.push_back(p.face_vertices(f));
  const std::vector<Vec3<double>> before = s.vertices;
  fuzz::round_to_float(s);
  for (std::size_t i = 0; i < before.size(); ++i) {
    for (int j = 0; j < 3; ++j) rounded += before[i][j] != s.vertices[i][j] ? 1 : 0;
  }
  return s;
}

}  // namespace

AuditReport audit_report(const ConvexPolyhedron<double>& a, const PoseD& pose_a,
                         const ConvexPolyhedron<double>& b, const PoseD& pose_b, bool use_double, bool json) {
  const RigidTransform<double> rel =
      relative_pose(to_transform<double>(pose_a), to_transform<double>(pose_b));
  AuditReport out;
  fuzz::FuzzCase c;
  c.family = "python";
  c.a = spec_of(a, out.rounded);
  c.b = spec_of(posed(b, rel), out.rounded);  // B' as a posed query computes it
  fuzz::AuditOptions opt;
  opt.use_double = use_double;
  opt.json = json;
  std::ostringstream s;
  out.status = fuzz::run_audit(c, opt, s);
  out.text = s.str();
  return out;
}

Replayed replay_case(const std::string& path, bool bytes) {
  Replayed out;
  if (bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InvalidInput(ErrorCode::Parse, "cannot open libFuzzer input '" + path + "'");
    const std::vector<char> raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    out.c = fuzz::decode_bytes(reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size());
  } else {
    out.c = fuzz::read_case_file(path);
  }
  out.r = fuzz::check_case_guarded(out.c);
  return out;
}

}  // namespace sepax::python
