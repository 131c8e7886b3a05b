// Posed contact manifolds (posed_queries.hpp) and the allocation guarantee of
// the engine path: a batch of posed queries and manifolds allocates nothing
// in float and double (after a warm-up pass has sized the per-thread posing
// scratch), and a manifold is bit for bit the pre-posed manifold mapped to
// world by pose_a.
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include <sepax/prepared_shape.hpp>

#include "core/alloc_counter.hpp"
#include "core/posed_cases.hpp"

using namespace sepax;
using namespace sepax::test;

TEMPLATE_TEST_CASE("a posed manifold is the pre-posed manifold mapped to world", "[posed][contact]", float,
                   double) {
  using T = TestType;
  std::mt19937_64 rng(1811);
  const auto shapes = local_shapes<T>(rng);
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  int with_points = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      for (int p = 0; p < 8; ++p) {
        const auto pa = random_pose<T>(rng, 1.2), pb = random_pose<T>(rng, 1.2);
        SatOptions opt;
        opt.margin = 0.05;
        const auto r = sat::traversal(prepared[i], pa, prepared[j], pb, opt);
        const auto m = contact_manifold(prepared[i], pa, prepared[j], pb, r, opt);
        const auto bp = posed(shapes[j], relative_pose(pa, pb));
        const auto rl = sat::traversal(shapes[i], bp, opt);
        ManifoldOptions mo;
        mo.margin = opt.margin;
        const auto ml = contact_manifold(shapes[i], bp, rl, mo);
        INFO("shapes " << i << ", " << j << " pose " << p);
        REQUIRE(m.kind == ml.kind);
        REQUIRE(m.feature == ml.feature);
        REQUIRE(m.size() == ml.size());
        for (int c = 0; c < 3; ++c) REQUIRE(m.normal[c] == r.axis[c]);
        for (int k = 0; k < m.size(); ++k) {
          const auto& x = m.points[static_cast<std::size_t>(k)];
          const auto& y = ml.points[static_cast<std::size_t>(k)];
          REQUIRE(x.id == y.id);
          REQUIRE(x.separation.num == y.separation.num);
          const auto wa = pa.apply(y.point_a), wb = pa.apply(y.point_b), wp = pa.apply(y.position);
          for (int c = 0; c < 3; ++c) {
            REQUIRE(x.point_a[c] == wa[c]);
            REQUIRE(x.point_b[c] == wb[c]);
            REQUIRE(x.position[c] == wp[c]);
          }
        }
        with_points += m.size() > 0;
      }
    }
  }
  CHECK(with_points > 50);
}

// A posed manifold reuses its query's B' only at bit-identical poses: after
// a query of the same shapes at other poses (the scratch holds B at another
// pose), and at poses one ulp apart, it is still the pre-posed manifold of
// its own poses, mapped to world.
TEMPLATE_TEST_CASE("a posed manifold after a query at other poses", "[posed][contact]", float, double) {
  using T = TestType;
  std::mt19937_64 rng(1813);
  const auto shapes = local_shapes<T>(rng);
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  auto require_mapped = [&](std::size_t i, std::size_t j, const RigidTransform<T>& pa,
                            const RigidTransform<T>& pb, const SatResult<T>& r, const ContactManifold<T>& m) {
    const auto bp = posed(shapes[j], relative_pose(pa, pb));
    SatResult<T> rl = sat::traversal(shapes[i], bp);
    ManifoldOptions mo;
    const auto ml = contact_manifold(shapes[i], bp, rl, mo);
    REQUIRE(r.feature == rl.feature);
    REQUIRE(m.kind == ml.kind);
    REQUIRE(m.size() == ml.size());
    for (int k = 0; k < m.size(); ++k) {
      const auto& x = m.points[static_cast<std::size_t>(k)];
      const auto& y = ml.points[static_cast<std::size_t>(k)];
      REQUIRE(x.id == y.id);
      REQUIRE(x.separation.num == y.separation.num);
      const auto wp = pa.apply(y.position);
      for (int c = 0; c < 3; ++c) REQUIRE(x.position[c] == wp[c]);
    }
  };
  int with_points = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      for (int p = 0; p < 4; ++p) {
        const auto pa = random_pose<T>(rng, 1.2), pb = random_pose<T>(rng, 1.2);
        auto pb2 = pb;  // one ulp away in the translation
        pb2.translation[0] = std::nextafter(pb.translation[0], T(2));
        const auto r = sat::traversal(prepared[i], pa, prepared[j], pb);
        const auto r2 = sat::traversal(prepared[i], pa, prepared[j], pb2);
        // the scratch holds B at (pa, pb2): the manifold at (pa, pb) poses B again
        const auto m = contact_manifold(prepared[i], pa, prepared[j], pb, r);
        INFO("shapes " << i << ", " << j << " pose " << p);
        require_mapped(i, j, pa, pb, r, m);
        // and now holds B at (pa, pb): the manifold at (pa, pb2) poses it again too
        const auto m2 = contact_manifold(prepared[i], pa, prepared[j], pb2, r2);
        require_mapped(i, j, pa, pb2, r2, m2);
        with_points += m.size() > 0;
      }
    }
  }
  CHECK(with_points > 20);
}

TEMPLATE_TEST_CASE("posed queries and manifolds allocate nothing", "[posed][alloc]", float, double) {
  using T = TestType;
  std::mt19937_64 rng(1812);
  auto shapes = local_shapes<T>(rng);
  shapes.push_back(shapes::prism<T>(32, 1.0, 0.5));  // 32-gon caps: 64-vertex clipped polygons
  std::vector<PreparedShape<T>> prepared;
  for (const auto& s : shapes) prepared.emplace_back(s);
  struct Query {
    std::size_t i, j;
    RigidTransform<T> pa, pb;
  };
  std::vector<Query> batch;
  for (std::size_t i = 0; i < shapes.size(); ++i)
    for (std::size_t j = 0; j < shapes.size(); ++j)
      for (int p = 0; p < 6; ++p) batch.push_back({i, j, random_pose<T>(rng, 1.2), random_pose<T>(rng, 1.2)});
  // resting caps of two cylinders, turned: the largest clipped polygons
  for (long z : {1L, 3L, 7L}) {
    batch.push_back({shapes.size() - 1, shapes.size() - 1, RigidTransform<T>{},
                     from_integer_quaternion<T>(9, 0, 0, z, Vec3<T>(T(0.1f), T(0), T(0.45f)))});
  }
  std::vector<SatCache<T>> caches(batch.size());
  long points = 0, early = 0;
  auto run = [&] {
    for (std::size_t q = 0; q < batch.size(); ++q) {
      const Query& c = batch[q];
      SatOptions opt;
      opt.early_out = q % 2 == 0;
      opt.margin = 0.02;
      for (SatAlgorithm alg : kSatAlgorithms) {
        const auto r = sat::run(alg, prepared[c.i], c.pa, prepared[c.j], c.pb, opt, &caches[q]);
        early += r.early_out;
        if (r.early_out) continue;
        const auto m = contact_manifold(prepared[c.i], c.pa, prepared[c.j], c.pb, r, opt);
        points += m.size();
      }
    }
  };
  run();  // warm-up: sizes this thread's posing scratch
  const long n = count_allocations(run);
  CHECK(n == 0);
  CHECK(points > 100);
  CHECK(early > 50);
}
