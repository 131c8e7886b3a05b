// sat::traversal in exact arithmetic: the same feature AND the same separation
// (compare == 0) as sat::brute_force and sat::gauss_map on every input, and the
// temporal-coherence cache replayed along exact rigid paths.
#include <catch2/catch.hpp>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <sepax/robust/number_types.hpp>
#include <sepax/robust/robust_kernel.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_cache.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

#include "traversal_shapes.hpp"

using namespace sepax;

namespace {

template <class T>
void check_exact(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, const char* what,
                 sat::TraversalStats* total = nullptr, bool with_brute_force = true) {
  const GaussMapWalk wa(a), wb(b);
  PlainKernel<T> k(a, b);
  sat::TraversalStats ts;
  const auto t = sat::traversal_with(k, wa, wb, {}, &ts);
  const auto g = sat::gauss_map(a, b);
  INFO(what << ": traversal " << to_string(t.feature) << " " << t.separation_as_double() << ", gauss map "
            << to_string(g.feature) << " " << g.separation_as_double());
  CHECK(t.feature == g.feature);
  CHECK(compare(t.separation, g.separation) == 0);
  CHECK(t.overlap == g.overlap);
  CHECK(ts.support_scans == 0);  // exact climbs never cycle: no fallback scan
  if (with_brute_force) {
    const auto r = sat::brute_force(a, b);
    INFO("brute force " << to_string(r.feature) << " " << r.separation_as_double());
    CHECK(t.feature == r.feature);
    CHECK(compare(t.separation, r.separation) == 0);
    CHECK(t.overlap == r.overlap);
  }
  if (total) {
    total->fallback_arcs += ts.fallback_arcs;
    total->corner_passes += ts.corner_passes;
    total->lex_starts += ts.lex_starts;
  }
}

template <class T>
Vec3<T> vq(int x, int y, int z, int den = 1) {
  return Vec3<T>(T(x) / T(den), T(y) / T(den), T(z) / T(den));
}

// integer quaternions: identity, 90 degrees about each axis, 180, the
// 120-degree body diagonal, rational angles about z and about skew axes
const int kQuats[][4] = {{1, 0, 0, 0}, {1, 0, 0, 1}, {1, 1, 0, 0}, {1, 0, 1, 0}, {0, 0, 0, 1}, {1, 1, 1, 1},
                         {2, 0, 0, 1}, {3, 0, 0, 1}, {2, 1, 0, 0}, {3, 1, 2, 1}, {5, 1, 1, 2}, {1, 1, 0, 1}};

}  // namespace

TEMPLATE_TEST_CASE("exact traversal == brute force on random hull pairs", "[traversal][exact]", mpq_class,
                   CGAL::Epeck::FT) {
  using T = TestType;
  std::mt19937_64 rng(31337);
  std::uniform_int_distribution<int> nd(4, 14);
  std::uniform_real_distribution<double> off(-1.8, 1.8);
  const int pairs = std::is_same_v<T, mpq_class> ? 40 : 15;
  sat::TraversalStats total;
  for (int it = 0; it < pairs; ++it) {
    const auto a0 = test::sphere_hull(rng, nd(rng));
    const auto b0 = test::moved(test::sphere_hull(rng, nd(rng), 0.8), test::random_rotation(rng),
                                test::V3(off(rng), off(rng), off(rng)));
    const auto a = ConvexPolyhedron<T>::convert_from(a0);
    const auto b = ConvexPolyhedron<T>::convert_from(b0);
    check_exact(a, b, "random pair", &total);
  }
  CHECK(total.fallback_arcs == 0);
}

TEMPLATE_TEST_CASE("exact traversal on boxes, prisms and tetrahedra at exact rotations (massive ties)",
                   "[traversal][exact]", mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  const std::vector<ConvexPolyhedron<T>> as{shapes::cube<T>(1.0), shapes::box<T>(1.0, 0.5, 0.75)};
  const std::vector<ConvexPolyhedron<T>> bs{shapes::cube<T>(0.5), shapes::box<T>(0.5, 0.25, 1.0),
                                            shapes::tetrahedron<T>(0.5), shapes::prism<T>(6, 0.5, 0.5)};
  // touching (faces, edges, vertices exactly in contact), overlapping, separated
  const std::vector<Vec3<T>> ts{vq<T>(0, 0, 0), vq<T>(3, 0, 0, 2), vq<T>(3, 2, 0, 2), vq<T>(3, 2, 5, 2),
                                vq<T>(2, 0, 0), vq<T>(1, 1, 1),    vq<T>(5, 3, 1, 4), vq<T>(0, 0, 7, 4)};
  sat::TraversalStats total;
  const int nq = std::is_same_v<T, mpq_class> ? 12 : 6;
  for (const auto& a : as)
    for (const auto& b0 : bs)
      for (int q = 0; q < nq; ++q)
        for (const auto& t : ts) {
          const auto b = test::rotated_exact(b0, kQuats[q][0], kQuats[q][1], kQuats[q][2], kQuats[q][3], t);
          check_exact(a, b, "box family", &total);
          check_exact(b, a, "box family swapped", &total);
        }
  // these placements do exercise the degenerate paths
  CHECK(total.corner_passes + total.lex_starts + total.fallback_arcs > 0);
}

TEMPLATE_TEST_CASE("exact traversal with double-sided polygons against everything", "[traversal][exact]",
                   mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  const std::vector<ConvexPolyhedron<T>> polys{shapes::regular_polygon<T>(3, 1.0),
                                               shapes::regular_polygon<T>(4, 1.0),
                                               shapes::regular_polygon<T>(9, 0.75)};
  std::mt19937_64 rng(5);
  const std::vector<ConvexPolyhedron<T>> others{
      shapes::cube<T>(0.5),
      shapes::tetrahedron<T>(0.6),
      shapes::prism<T>(8, 0.5, 0.4),
      shapes::regular_polygon<T>(4, 0.5),
      shapes::regular_polygon<T>(5, 0.6),
      ConvexPolyhedron<T>::convert_from(test::sphere_hull(rng, 10, 0.7))};
  const std::vector<Vec3<T>> ts{vq<T>(0, 0, 0), vq<T>(0, 0, 1, 2), vq<T>(1, 0, 0), vq<T>(1, 1, 1, 2),
                                vq<T>(0, 0, 3, 2)};
  const int nq = std::is_same_v<T, mpq_class> ? 8 : 3;
  for (const auto& p : polys)
    for (const auto& o : others)
      for (int q = 0; q < nq; ++q)
        for (const auto& t : ts) {
          const auto b = test::rotated_exact(o, kQuats[q][0], kQuats[q][1], kQuats[q][2], kQuats[q][3], t);
          check_exact(p, b, "polygon as A");
          check_exact(b, p, "polygon as B");
        }
}

TEMPLATE_TEST_CASE("exact traversal: arcs through Gauss-map vertices", "[traversal][exact]", mpq_class,
                   CGAL::Epeck::FT) {
  using T = TestType;
  // A cube against a cube turned about z by a rational angle: A's equator arcs
  // run through B's side normals, and +-z normals coincide.  Tilting B about x
  // by 90 degrees puts B's z normals on A's equator too.
  const auto a = shapes::cube<T>(1.0);
  const auto c = shapes::cube<T>(0.5);
  sat::TraversalStats total;
  for (const auto& q : {std::array<int, 4>{2, 0, 0, 1}, std::array<int, 4>{3, 0, 0, 2},
                        std::array<int, 4>{2, 1, 0, 0}, std::array<int, 4>{1, 0, 1, 0}}) {
    for (const auto& t :
         {vq<T>(0, 0, 0), vq<T>(3, 0, 0, 2), vq<T>(1, 1, 0), vq<T>(0, 0, 3, 2), vq<T>(5, 1, 1, 4)}) {
      const auto b = test::rotated_exact(c, q[0], q[1], q[2], q[3], t);
      check_exact(a, b, "rational turn", &total);
      check_exact(b, a, "rational turn swapped", &total);
      // and a tetrahedron whose edges pass through the cube's Gauss vertices
      const auto tet = test::rotated_exact(shapes::tetrahedron<T>(0.5), q[0], q[1], q[2], q[3], t);
      check_exact(a, tet, "tetrahedron");
      check_exact(tet, a, "tetrahedron swapped");
    }
  }
  // Constructed so that the arc of A's edge PQ (from normal +x to normal
  // (0,1,2)) passes exactly through the Gauss-map vertex (1,1,2) of -B (B's
  // base has normal -(1,1,2)), with unique support vertices at both ends: the
  // walk must pass the corner.
  auto tet = [](std::vector<Vec3<T>> v) {
    return ConvexPolyhedron<T>::from_faces(std::move(v), {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
  };
  auto oriented = [&](std::vector<Vec3<T>> v) {
    // orient the tetrahedron 0,1,2,3 so that face (0,1,2) is counter-clockwise from outside
    const Vec3<T> n = cross(Vec3<T>(v[1] - v[0]), Vec3<T>(v[2] - v[0]));
    if (dot(n, Vec3<T>(v[3] - v[0])) > T(0)) std::swap(v[1], v[2]);
    return tet(std::move(v));
  };
  const auto ta = oriented({vq<T>(0, 0, 0), vq<T>(0, -2, 1), vq<T>(0, -1, -2), vq<T>(-2, 0, 0)});
  const auto tb0 = oriented({vq<T>(0, 0, 0), vq<T>(2, 0, -1), vq<T>(-1, 3, -1), vq<T>(1, 1, 3)});
  for (const auto& t :
       {vq<T>(0, 0, 0), vq<T>(1, 0, 0), vq<T>(-1, 1, 0), vq<T>(3, 0, 0), vq<T>(-1, -1, -1, 2)}) {
    const auto tb = test::rotated_exact(tb0, 1, 0, 0, 0, t);
    check_exact(ta, tb, "constructed corner", &total);
    check_exact(tb, ta, "constructed corner swapped", &total);
  }
  CHECK(total.corner_passes > 0);
}

TEMPLATE_TEST_CASE("exact cache replay along rigid paths equals fresh queries", "[traversal][cache][exact]",
                   mpq_class, CGAL::Epeck::FT) {
  using T = TestType;
  std::mt19937_64 rng(8);
  const auto a = ConvexPolyhedron<T>::convert_from(test::sphere_hull(rng, 10));
  const std::vector<ConvexPolyhedron<T>> bs{shapes::cube<T>(0.5),
                                            ConvexPolyhedron<T>::convert_from(test::sphere_hull(rng, 8, 0.6)),
                                            shapes::regular_polygon<T>(5, 0.6)};
  const GaussMapWalk wa(a);
  auto run = [&](const GaussMapWalk& wb) {
    return [&wa, &wb](auto& k, const SatOptions& o) { return sat::traversal_with(k, wa, wb, o); };
  };
  const int steps = std::is_same_v<T, mpq_class> ? 40 : 20;
  for (const auto& b0 : bs) {
    const GaussMapWalk wb(b0);
    SatCache<T> full_cache, eo_cache;
    for (int i = 0; i <= steps; ++i) {
      // B moves from x = -2.5 to x = +2.5 through A while turning about a skew axis
      const auto b =
          test::rotated_exact(b0, 4 * steps, i, 2 * i, steps, vq<T>(5 * i - 5 * steps / 2, 1, 1, steps));
      const auto fresh = sat::traversal(a, wa, b, wb);
      const auto cached = sat::cached(full_cache, a, b, run(wb));
      CHECK(cached.feature == fresh.feature);
      CHECK(compare(cached.separation, fresh.separation) == 0);
      CHECK(cached.overlap == fresh.overlap);
      const auto eo = sat::cached(eo_cache, a, b, run(wb), {.early_out = true});
      CHECK(eo.overlap == fresh.overlap);
      if (fresh.overlap) {
        CHECK(eo.feature == fresh.feature);
        CHECK(compare(eo.separation, fresh.separation) == 0);
      } else {
        CHECK(sign(eo.separation) > 0);
        // the returned separation is the one every SAT computes for that feature
        PlainKernel<T> k(a, b);
        const auto ev = sat::reevaluate(k, eo.feature);
        REQUIRE(ev);
        CHECK(ev->first == eo.feature);
        CHECK(compare(ev->second, eo.separation) == 0);
      }
    }
    CHECK(eo_cache.hits > 0);
  }
}

// policy::Robust decides exactly what PlainKernel<mpq_class> decides on the
// exact images, so the robust float traversal must report the exact feature.
TEST_CASE("robust float traversal reports the exact brute-force feature", "[traversal][robust]") {
  using Q = mpq_class;
  std::mt19937_64 rng(271828);
  std::uniform_int_distribution<int> nd(4, 14);
  std::uniform_real_distribution<double> off(-1.8, 1.8);
  auto check = [](const ConvexPolyhedron<double>& a, const ConvexPolyhedron<double>& b, const char* what) {
    const auto qa = ConvexPolyhedron<Q>::convert_from(a);
    const auto qb = ConvexPolyhedron<Q>::convert_from(b);
    const auto exact = sat::brute_force(qa, qb);
    const auto rt = sat::traversal<policy::Robust>(a, b);
    const auto rg = sat::gauss_map<policy::Robust>(a, b);
    INFO(what << ": robust traversal " << to_string(rt.feature) << ", exact brute force "
              << to_string(exact.feature));
    CHECK(rt.feature == exact.feature);
    CHECK(rt.overlap == exact.overlap);
    CHECK(rt.feature == rg.feature);
    CHECK(compare(rt.separation, rg.separation) == 0);
    const auto ft = sat::traversal<policy::Robust>(ConvexPolyhedron<float>::convert_from(a),
                                                   ConvexPolyhedron<float>::convert_from(b));
    const auto fe =
        sat::traversal(ConvexPolyhedron<Q>::convert_from(ConvexPolyhedron<float>::convert_from(a)),
                       ConvexPolyhedron<Q>::convert_from(ConvexPolyhedron<float>::convert_from(b)));
    CHECK(ft.feature == fe.feature);
  };
  for (int it = 0; it < 40; ++it) {
    const auto a = test::sphere_hull(rng, nd(rng));
    const auto b = test::moved(test::sphere_hull(rng, nd(rng), 0.8), test::random_rotation(rng),
                               test::V3(off(rng), off(rng), off(rng)));
    check(a, b, "random pair");
  }
  // exact ties in double: boxes, polygons and the constructed corner case
  const auto cube = shapes::cube<double>(1.0);
  const auto small = shapes::box<double>(0.5, 0.25, 1.0);
  const auto poly = shapes::regular_polygon<double>(4, 1.0);
  for (const auto& t : {test::V3(0, 0, 0), test::V3(1.5, 0, 0), test::V3(1.5, 1.25, 0),
                        test::V3(1.5, 1.25, 2.0), test::V3(0.25, 0.5, 0.75)}) {
    for (int q = 0; q < 6; ++q) {
      const auto b =
          test::rotated_exact(small, kQuats[q][0], kQuats[q][1], kQuats[q][2], kQuats[q][3], Vec3<double>(t));
      check(cube, b, "boxes");
      check(b, cube, "boxes swapped");
      check(poly, b, "polygon");
      check(b, poly, "polygon swapped");
    }
  }
}
