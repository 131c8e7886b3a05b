#include <catch2/catch.hpp>

#include <sepax/manifold_compare.hpp>
#include <sepax/shapes.hpp>

using namespace sepax;

namespace {
template <Number T>
ConvexPolyhedron<T> shifted(const ConvexPolyhedron<T>& p, double x, double y, double z) {
  std::vector<Vec3<T>> vs;
  for (const auto& v : p.vertices()) vs.push_back(Vec3<T>(v + vec_from_double<T>(Vec3<double>(x, y, z))));
  return p.with_vertices(vs);
}
}  // namespace

TEST_CASE("compare_manifolds: float vs double on the same inputs", "[contact][compare]") {
  const auto ad = shapes::prism<double>(7, 1.0, 1.0);
  const auto bd = shifted(shapes::prism<double>(5, 0.6, 0.5), 0.2, 0.1, 1.3);
  const auto af = shapes::prism<float>(7, 1.0, 1.0);
  const auto bf = ConvexPolyhedron<float>::from_faces(
      [&] {
        std::vector<Vec3<float>> v;
        for (const auto& p : bd.vertices()) v.push_back(p.cast<float>());
        return v;
      }(),
      [&] {
        std::vector<std::vector<int>> f;
        for (int i = 0; i < bd.face_count(); ++i) f.push_back(bd.face_vertices(i));
        return f;
      }());
  const auto md = contact_manifold(ad, bd);
  const auto mf = contact_manifold(af, bf);
  REQUIRE(md.size() == 4);
  const auto d = compare_manifolds(mf, md);
  CHECK(d.identical());
  CHECK(d.same_deepest);
  CHECK(d.max_depth_error < 1e-6);
  CHECK(d.max_position_error < 1e-6);
  // a different configuration is told apart
  const auto other = contact_manifold(ad, shifted(shapes::prism<double>(5, 0.6, 0.5), 0.2, 0.1, 1.2));
  const auto e = compare_manifolds(mf, other);
  CHECK(e.same_ids);                // same features touch ...
  CHECK(e.max_depth_error > 0.09);  // ... 0.1 deeper
  CHECK_FALSE(compare_manifolds(md, contact_manifold(ad, shifted(bd, 0, 0, 5))).same_kind);
}
