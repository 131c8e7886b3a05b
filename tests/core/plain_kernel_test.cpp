// PlainKernel at extreme scales: edge axes (eA x eB, normalised) and the
// parallel-edge test are scale-safe, so the three SATs give the same features
// and exactly scaled separations for shapes scaled by any power of two in
// range (1e-289 .. 1e301 for double, 1e-30 .. 1e36 for float).  Before, |eA x
// eB|^2 overflowed or underflowed beyond about 1e+-77 (double), 1e+-9 (float)
// and edge axes came out zero or imprecise: wrong features and separations.
#include <catch2/catch.hpp>

#include <sepax/convex_hull.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

#include <cmath>
#include <random>
#include <type_traits>
#include <vector>

using namespace sepax;

namespace {

template <class T>
ConvexPolyhedron<T> times_pow2(const ConvexPolyhedron<T>& p, int k) {
  std::vector<Vec3<T>> v;
  for (const auto& q : p.vertices())
    v.emplace_back(std::ldexp(q[0], k), std::ldexp(q[1], k), std::ldexp(q[2], k));
  std::vector<std::vector<int>> f;
  for (int i = 0; i < p.face_count(); ++i) f.push_back(p.face_vertices(i));
  return ConvexPolyhedron<T>::from_faces(std::move(v), f);
}

template <class T>
void check_same(const SatResult<T>& r0, const SatResult<T>& rk, int k) {
  CHECK(r0.overlap == rk.overlap);
  CHECK(r0.feature == rk.feature);
  CHECK(std::ldexp(r0.separation_as_double(), k) == rk.separation_as_double());
}

}  // namespace

TEMPLATE_TEST_CASE("PlainKernel: SAT results scale exactly with a power-of-two scale", "[kernel][scale]",
                   float, double) {
  using T = TestType;
  const std::vector<int> ks = std::is_same_v<T, double> ? std::vector<int>{-960, -300, 300, 1000}
                                                        : std::vector<int>{-100, -40, 40, 119};
  std::mt19937 rng(5);
  std::normal_distribution<double> nd;
  int edge_features = 0;
  for (int rep = 0; rep < 60; ++rep) {
    std::vector<Vec3<T>> pa, pb;
    for (int i = 0; i < 12; ++i) pa.push_back(vec_cast<T>(Vec3<double>(nd(rng), nd(rng), nd(rng))));
    const double off = 2.5 * std::abs(nd(rng));
    for (int i = 0; i < 12; ++i) pb.push_back(vec_cast<T>(Vec3<double>(nd(rng) + off, nd(rng), nd(rng))));
    const auto a = convex_hull(pa), b = convex_hull(pb);
    const auto r_bf = sat::brute_force(a, b);
    const auto r_gm = sat::gauss_map(a, b);
    const auto r_tr = sat::traversal(a, b);
    if (r_gm.feature.type == FeatureType::EdgePair) ++edge_features;
    for (const int k : ks) {
      INFO("rep " << rep << ", scale 2^" << k);
      const auto as = times_pow2(a, k), bs = times_pow2(b, k);
      check_same(r_bf, sat::brute_force(as, bs), k);
      check_same(r_gm, sat::gauss_map(as, bs), k);
      check_same(r_tr, sat::traversal(as, bs), k);
    }
  }
  CHECK(edge_features > 5);  // the edge axes were exercised
}

TEST_CASE("PlainKernel: shapes of very different scales (double)", "[kernel][scale]") {
  using T = double;
  // a box of half size 2^480 resting on the top face (z = 2^500) of a box of
  // half size 2^500, then lifted by 2^470: exact at these scales
  const auto big = times_pow2(shapes::cube<T>(1.0), 500);
  const auto small_at = [&](double lift) {
    const auto s = times_pow2(shapes::cube<T>(1.0), 480);
    std::vector<Vec3<T>> v;
    for (const auto& q : s.vertices()) v.emplace_back(q[0], q[1], q[2] + 0x1p500 + 0x1p480 + lift);
    return s.with_vertices(v);
  };
  for (const double lift : {0.0, 0x1p470}) {
    INFO("lift " << lift);
    const auto small = small_at(lift);
    for (const auto& r :
         {sat::brute_force(big, small), sat::gauss_map(big, small), sat::traversal(big, small)}) {
      CHECK(r.overlap == (lift == 0.0));
      CHECK(r.separation_as_double() == lift);
      CHECK(r.feature.type != FeatureType::EdgePair);
      CHECK(r.axis == Vec3<T>(0, 0, 1));  // from A towards B
    }
  }
}

TEMPLATE_TEST_CASE("PlainKernel: edge axes of a long edge against a short one", "[kernel][scale]", float,
                   double) {
  using T = TestType;
  // edges of length about 2e20 against edges of about 0.7: |eA x eB|^2 is far below float's normal range
  // when both are scaled by one power of two, so each is scaled by its own (scaled_cross, vec3.hpp)
  const double h = std::is_same_v<T, float> ? 1e20 : 1e160;
  const auto big = shapes::box<T>(h, h, h);
  const auto polygon = shapes::regular_polygon<T>(9);
  for (const int e : {0, 3, 7}) {
    const Vec3<T> u = big.edge_direction(e), w = polygon.edge_direction(e);
    const Vec3<T> n = scaled_cross(u, w);
    // the reference in long double (x87: its range holds |u x w|^2 here; elsewhere it is double, and the
    // float case still checks what it must)
    using L = long double;
    const L c[3] = {L(u[1]) * L(w[2]) - L(u[2]) * L(w[1]), L(u[2]) * L(w[0]) - L(u[0]) * L(w[2]),
                    L(u[0]) * L(w[1]) - L(u[1]) * L(w[0])};
    const L cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    const L nn = L(n[0]) * L(n[0]) + L(n[1]) * L(n[1]) + L(n[2]) * L(n[2]);
    INFO("edge " << e);
    if (!(cc > 0) || !std::isfinite(cc)) continue;
    CHECK(std::abs((L(n[0]) * c[0] + L(n[1]) * c[1] + L(n[2]) * c[2]) / std::sqrt(nn * cc) - 1) < 1e-6L);
  }
  const auto r_bf = sat::brute_force(big, polygon);
  const auto r_gm = sat::gauss_map(big, polygon);
  const auto r_tr = sat::traversal(big, polygon);
  for (const auto* r : {&r_bf, &r_gm, &r_tr}) {
    CHECK(r->overlap);
    CHECK(std::abs(std::sqrt(static_cast<double>(squared_norm(r->axis))) - 1.0) < 1e-6);
  }
  CHECK(r_bf.feature == r_gm.feature);
  CHECK(r_bf.feature == r_tr.feature);
  CHECK(r_bf.separation_as_double() == r_gm.separation_as_double());
}
