// The engine loop of docs/engine.md, compiled and run (keep the two in sync).
#include <catch2/catch.hpp>

#include <sepax/prepared_shape.hpp>
#include <sepax/shapes.hpp>

TEST_CASE("docs/engine.md: the engine loop", "[posed][docs]") {
  using namespace sepax;
  // once per hull, in its local frame
  const PreparedShape<double> crate(shapes::box<double>(0.5, 0.5, 0.5));
  const PreparedShape<double> floor(shapes::box<double>(10.0, 10.0, 0.5));
  // once per pair
  SatCache<double> cache;
  SatOptions opt;
  opt.early_out = true;  // stop at a separation beyond the margin
  opt.margin = 0.02;     // speculative margin, in the shapes' length unit
  int contacts = 0;
  for (int step = 0; step < 10; ++step) {
    const auto pose_floor = RigidTransform<double>::identity();
    const auto pose_crate = RigidTransform<double>::translation_by(Vec3<double>(0.0, 0.0, 1.2 - 0.03 * step));
    const SatResult<double> r = sat::traversal(floor, pose_floor, crate, pose_crate, opt, &cache);
    if (r.early_out) continue;  // farther apart than the margin
    const ContactManifold<double> m = contact_manifold(floor, pose_floor, crate, pose_crate, r, opt);
    contacts += m.size();  // points and normal in world coordinates
  }
  CHECK(contacts > 0);
}
