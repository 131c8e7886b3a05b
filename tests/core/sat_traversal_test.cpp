#include <catch2/catch.hpp>

#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

#include "traversal_shapes.hpp"

#include "alloc_counter.hpp"

using namespace sepax;
using test::V3;

namespace {

// A kernel wrapper that counts the calls the SATs make (the SatKernel concept
// is all the algorithms see).
template <SatKernel K>
struct Counting {
  using FT = typename K::FT;
  K& k;
  mutable std::int64_t face_queries = 0, heights = 0, arcs = 0, edge_seps = 0;
  const ConvexPolyhedron<FT>& a() const { return k.a(); }
  const ConvexPolyhedron<FT>& b() const { return k.b(); }
  FaceQuery<FT> face_query_a(int i) const {
    ++face_queries;
    return k.face_query_a(i);
  }
  FaceQuery<FT> face_query_b(int i) const {
    ++face_queries;
    return k.face_query_b(i);
  }
  FaceQuery<FT> side_query_a(int i) const { return k.side_query_a(i); }
  FaceQuery<FT> side_query_b(int i) const { return k.side_query_b(i); }
  Separation<FT> face_separation_a(int i, int j) const {
    ++heights;
    return k.face_separation_a(i, j);
  }
  Separation<FT> face_separation_b(int i, int j) const {
    ++heights;
    return k.face_separation_b(i, j);
  }
  ArcSigns arc_signs(int i, int j) const {
    ++arcs;
    return k.arc_signs(i, j);
  }
  bool edges_parallel(int i, int j) const { return k.edges_parallel(i, j); }
  Separation<FT> edge_separation(int i, int j) const {
    ++edge_seps;
    return k.edge_separation(i, j);
  }
  std::optional<Separation<FT>> edge_separation_full(int i, int j) const {
    return k.edge_separation_full(i, j);
  }
  int compare(const Separation<FT>& x, const Feature& fx, const Separation<FT>& y, const Feature& fy) const {
    return k.compare(x, fx, y, fy);
  }
  int sign(const Separation<FT>& x, const Feature& f) const { return k.sign(x, f); }
  Vec3<FT> axis(const Feature& f) const { return k.axis(f); }
  std::int64_t exact_fallbacks() const { return k.exact_fallbacks(); }
};
static_assert(SatKernel<Counting<PlainKernel<double>>>);

// Same feature, verdict and separation.  Against sat::gauss_map (the same
// kernel calls per axis) the double separations are identical; the brute force
// measures edge axes by full projection, a different rounding, so there the
// separation is compared to a relative 1e-12 (exact types: exactly, in the
// exact test).
template <class T>
void check_same(const SatResult<T>& t, const SatResult<T>& ref, const char* what, bool same_formula = true) {
  INFO(what << ": traversal " << to_string(t.feature) << " " << t.separation_as_double() << " vs "
            << to_string(ref.feature) << " " << ref.separation_as_double());
  CHECK(t.feature == ref.feature);
  if (same_formula) {
    CHECK(compare(t.separation, ref.separation) == 0);
  } else {
    CHECK(t.separation_as_double() == Approx(ref.separation_as_double()).epsilon(1e-12).margin(1e-12));
  }
  CHECK(t.overlap == ref.overlap);
}

}  // namespace

TEST_CASE("traversal agrees with gauss map and brute force on random hull pairs (double)", "[traversal]") {
  std::mt19937_64 rng(12345);
  std::uniform_int_distribution<int> nd(4, 40);
  std::uniform_real_distribution<double> off(-2.5, 2.5);
  std::int64_t fallbacks = 0, corners = 0;
  for (int it = 0; it < 300; ++it) {
    const auto a0 = test::sphere_hull(rng, nd(rng));
    const auto b0 = test::sphere_hull(rng, nd(rng), 0.7);
    const auto a = test::moved(a0, test::random_rotation(rng), V3(0, 0, 0));
    const auto b = test::moved(b0, test::random_rotation(rng), V3(off(rng), off(rng), off(rng)));
    const GaussMapWalk wa(a), wb(b);
    PlainKernel<double> pk(a, b);
    Counting<PlainKernel<double>> ck{pk};
    sat::TraversalStats ts;
    const auto t = sat::traversal_with(ck, wa, wb, {}, &ts);
    check_same(t, sat::gauss_map(a, b), "gauss_map");
    check_same(t, sat::brute_force(a, b), "brute_force", false);
    // no full support scan: the start face climbs from the deepest probe
    // (a scan is only the climb's fallback when rounding makes it cycle)
    CHECK(ck.face_queries == 0);
    CHECK(ts.support_scans == 0);
    fallbacks += ts.fallback_arcs;
    corners += ts.corner_passes;
    // PlainKernel<double> itself takes the float fast path (climbs on
    // fl(n.v), no Separation per neighbour); Counting<> above the generic one.
    sat::TraversalStats fs;
    const auto f = sat::traversal_with(pk, wa, wb, {}, &fs);
    check_same(f, sat::gauss_map(a, b), "gauss_map (fast path)");
    CHECK(fs.support_scans == 0);
  }
  // Random points are in general position: the walk never needs a fallback.
  CHECK(fallbacks == 0);
  CHECK(corners == 0);
}

TEST_CASE("traversal makes far fewer kernel calls than gauss map on sphere hulls", "[traversal]") {
  std::mt19937_64 rng(777);
  for (int n : {32, 128}) {
    std::int64_t t_arcs = 0, g_arcs = 0, t_heights = 0, t_scans = 0, g_scans = 0;
    const int reps = 5;
    for (int r = 0; r < reps; ++r) {
      const auto a = test::sphere_hull(rng, n);
      const auto b = test::moved(test::sphere_hull(rng, n), test::random_rotation(rng), V3(0.5, 0.3, 0.2));
      const GaussMapWalk wa(a), wb(b);
      PlainKernel<double> pk(a, b);
      Counting<PlainKernel<double>> ct{pk}, cg{pk};
      const auto t = sat::traversal_with(ct, wa, wb);
      const auto g = sat::gauss_map_with(cg);
      check_same(t, g, "gauss_map");
      t_arcs += ct.arcs;
      g_arcs += cg.arcs;
      t_heights += ct.heights;
      t_scans += ct.face_queries;
      g_scans += cg.face_queries;
    }
    WARN("N=" << n << " per query: traversal " << t_scans / reps << " support scans, " << t_arcs / reps
              << " arc tests, " << t_heights / reps << " O(1) heights; gauss map " << g_scans / reps
              << " support scans, " << g_arcs / reps << " arc tests");
    CHECK(t_scans == 0);  // no full support scan: the start face climbs from the deepest probe
    CHECK(t_arcs * 4 < g_arcs);
  }
}

TEST_CASE("traversal prunes faces and arcs below the best, with the same result", "[traversal]") {
  // Overlapping sphere hulls: most faces' climbs stop at their seed (a vertex
  // already below the best), most of the others at the deepest probe vertex
  // without a climb, most arcs are skipped by the arc bound, and the answer
  // is still the Gauss map's.
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> off(-0.6, 0.6);
  for (int n : {16, 64, 96}) {  // (the test hull builder is O(n^4))
    std::int64_t faces = 0, edges = 0;
    sat::TraversalStats sum;
    for (int r = 0; r < 6; ++r) {
      const auto a = test::sphere_hull(rng, n);
      const auto b = test::moved(test::sphere_hull(rng, n), test::random_rotation(rng),
                                 V3(off(rng), off(rng), off(rng)));
      const GaussMapWalk wa(a), wb(b);
      PlainKernel<double> pk(a, b);
      sat::TraversalStats ts;
      const auto t = sat::traversal_with(pk, wa, wb, {}, &ts);
      check_same(t, sat::gauss_map(a, b), "gauss_map");
      faces += a.face_count() + b.face_count();
      edges += a.edge_count();
      sum.pruned_faces += ts.pruned_faces;
      sum.probe_checks += ts.probe_checks;
      sum.probe_pruned += ts.probe_pruned;
      sum.climb_steps += ts.climb_steps;
      sum.pruned_arcs += ts.pruned_arcs;
      sum.height_evals += ts.height_evals;
      sum.late_certified += ts.late_certified;
      CHECK(ts.support_scans == 0);
    }
    WARN("N=" << n << ": pruned faces " << sum.pruned_faces << " of " << faces << " (by a probe "
              << sum.probe_pruned << " of " << sum.probe_checks << " looked at), pruned arcs "
              << sum.pruned_arcs << " of " << edges << ", late climbs " << sum.late_certified
              << ", climb steps " << sum.climb_steps << ", O(1) heights per face "
              << double(sum.height_evals) / double(faces));
    CHECK(sum.pruned_faces * 10 > faces * 7);
    CHECK(sum.pruned_arcs * 2 > edges);
    CHECK(sum.height_evals < 6 * faces);
    // Faces look at the probes only when their seed is not below the best
    // (at most once each), and most of those are pruned there.
    CHECK(sum.probe_checks * 2 < faces);
    CHECK(sum.probe_pruned * 3 > sum.probe_checks * 2);
  }
}

TEST_CASE("traversal on boxes: axis-aligned and 90-degree poses, touching (ties everywhere)", "[traversal]") {
  const auto a = shapes::box<double>(1.0, 0.5, 0.75);
  const auto c = shapes::cube<double>(0.5);
  std::vector<Eigen::Matrix3d> rots;
  // all 24 rotations of the cube group
  Eigen::Matrix3d base[3] = {Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity(),
                             Eigen::Matrix3d::Identity()};
  base[1] << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  base[2] << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  Eigen::Matrix3d rz, rx;
  rz << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  rx << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  for (const auto& bm : base) {
    Eigen::Matrix3d m = bm;
    for (int i = 0; i < 4; ++i) {
      rots.push_back(m);
      rots.push_back(rx * rx * m);
      m = rz * m;
    }
  }
  for (const auto& r : rots) {
    for (const V3& t : {V3(0, 0, 0), V3(1.5, 0, 0), V3(1.5, 1.0, 0), V3(1.5, 1.0, 1.25), V3(0.25, 0.5, 1.0),
                        V3(2.0, 0, 0), V3(0.7, 0.3, 0.1)}) {
      const auto b = test::moved(c, r, t);
      const auto tr = sat::traversal(a, b);
      check_same(tr, sat::brute_force(a, b), "brute_force", false);
      check_same(tr, sat::gauss_map(a, b), "gauss_map");
      const auto tr2 = sat::traversal(b, a);
      check_same(tr2, sat::gauss_map(b, a), "gauss_map swapped");
    }
  }
}

TEST_CASE("traversal with double-sided polygons against everything", "[traversal]") {
  std::mt19937_64 rng(99);
  std::vector<ConvexPolyhedron<double>> shapes_list{shapes::regular_polygon<double>(3),
                                                    shapes::regular_polygon<double>(7, 0.8),
                                                    shapes::regular_polygon<double>(32, 1.2),
                                                    shapes::cube<double>(0.6),
                                                    shapes::tetrahedron<double>(0.7),
                                                    shapes::prism<double>(12, 0.8, 0.4),
                                                    test::sphere_hull(rng, 20)};
  std::uniform_real_distribution<double> off(-1.5, 1.5);
  int n = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    for (const auto& other : shapes_list) {
      for (int rep = 0; rep < 20; ++rep) {
        const auto a = test::moved(shapes_list[i], test::random_rotation(rng), V3(0, 0, 0));
        const auto b = test::moved(other, test::random_rotation(rng), V3(off(rng), off(rng), off(rng)));
        check_same(sat::traversal(a, b), sat::gauss_map(a, b), "polygon as A");
        check_same(sat::traversal(b, a), sat::gauss_map(b, a), "polygon as B");
        ++n;
      }
      // parallel placements: the polygon flat on z = const against the unrotated shape
      for (double z : {0.0, 0.3, 0.6, 1.0}) {
        const auto a = test::moved(shapes_list[i], Eigen::Matrix3d::Identity(), V3(0.1, 0.05, z));
        check_same(sat::traversal(a, other), sat::gauss_map(a, other), "parallel polygon as A");
        check_same(sat::traversal(other, a), sat::gauss_map(other, a), "parallel polygon as B");
      }
    }
  }
  CHECK(n > 0);
}

// Two nearly coplanar flat quads (fuzz/corpus/35-..., shrunk from a 10-minute
// fuzz campaign): every vertex of B has the same float height over A's back
// face, so the float climb reports a tie at the end of each arc of A, while
// the float arc test still accepts a second crossing near the start.  The
// walk used to stop at the first tied vertex and never measured edges(3, 2),
// the float Gauss map's (and exact arithmetic's) answer.  A crossing the arc
// test accepts must be taken: the plain float walk then measures every pair
// its own arc test accepts, like the Gauss map.
TEST_CASE("plain float traversal takes every crossing its arc test accepts, even at a rounded height tie",
          "[traversal][flat]") {
  using V = Vec3<float>;
  const std::vector<std::vector<int>> quad{{0, 1, 2, 3}, {3, 2, 1, 0}};
  const auto a = ConvexPolyhedron<float>::from_faces({V(-0.0011733612f, -0.000349798473f, -0.00129976182f),
                                                      V(-0.000755380257f, -0.000349798473f, -0.0012997617f),
                                                      V(-0.000985715538f, -8.71701632e-05f, -0.00129976182f),
                                                      V(-0.00117749802f, -0.000321693951f, -0.0012997617f)},
                                                     quad);
  const auto b = ConvexPolyhedron<float>::from_faces({V(-0.0009765625f, -0.000610351562f, -0.00134277344f),
                                                      V(-0.0009765625f, -0.000366210938f, -0.00134277344f),
                                                      V(-0.00122070312f, -0.000366210938f, -0.00134277344f),
                                                      V(-0.00122070312f, -0.000610351562f, -0.00134277344f)},
                                                     quad);
  const auto t = sat::traversal(a, b);
  const auto g = sat::gauss_map(a, b);
  CHECK(g.feature == Feature::edges(3, 2));
  check_same(t, g, "nearly coplanar quads");
}

// A quad and a pentagon nearly parallel (fuzz/corpus/37-..., shrunk from a
// 10-minute campaign, seed 22): B's heights over A's faces are rounding ties,
// the float climb's support vertex for A's face 0 was one region off, and the
// walk skipped the crossing edges(0, 0) that the float arc test accepts (and
// exact arithmetic chooses).  Plain kernels now test every arc of a flat pair
// against every arc of -B, as the Gauss map does.
TEST_CASE("plain float traversal with a flat shape measures every pair its arc test accepts",
          "[traversal][flat]") {
  using V = Vec3<float>;
  const auto a = ConvexPolyhedron<float>::from_faces(
      {V(-0.0326072983f, 0.0249402914f, -0.00621825783f), V(-0.032214243f, 0.0249345172f, -0.00624135137f),
       V(-0.0321951434f, 0.0248533338f, -0.00656608958f), V(-0.0325774178f, 0.0247043259f, -0.00716211926f)},
      {{0, 1, 2, 3}, {3, 2, 1, 0}});
  const auto b = ConvexPolyhedron<float>::from_faces(
      {V(-0.0322029516f, 0.024851175f, -0.00657469174f), V(-0.0321554206f, 0.0248513408f, -0.00657402631f),
       V(-0.0319796354f, 0.0247085374f, -0.00714524183f), V(-0.0322105475f, 0.0244366378f, -0.00823284592f),
       V(-0.0323127694f, 0.0244829617f, -0.00804754905f)},
      {{0, 1, 2, 3, 4}, {4, 3, 2, 1, 0}});
  const GaussMapWalk wa(a), wb(b);
  sat::TraversalStats ts;
  PlainKernel<float> k(a, b);
  const auto t = sat::traversal_with(k, wa, wb, {}, &ts);
  const auto g = sat::gauss_map(a, b);
  CHECK(g.feature == Feature::edges(0, 0));
  check_same(t, g, "nearly parallel quad and pentagon");
  CHECK(ts.fallback_arcs == wa.edge_count());  // every arc against every arc of -B
  // the same shapes swapped (B flat against A flat, roles exchanged)
  check_same(sat::traversal(b, a), sat::gauss_map(b, a), "swapped");
}

TEST_CASE("traversal early out returns a separating axis exactly when separated", "[traversal]") {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> off(-2.5, 2.5);
  for (int it = 0; it < 100; ++it) {
    const auto a = test::sphere_hull(rng, 16);
    const auto b = test::moved(test::sphere_hull(rng, 12, 0.8), test::random_rotation(rng),
                               V3(off(rng), off(rng), off(rng)));
    const auto full = sat::traversal(a, b);
    const auto eo = sat::traversal(a, b, {.early_out = true});
    CHECK(eo.overlap == full.overlap);
    if (!full.overlap) {
      CHECK(sign(eo.separation) > 0);
    } else {
      CHECK(eo.feature == full.feature);
    }
  }
}

TEST_CASE("traversal terminates on adversarial inputs", "[traversal]") {
  std::mt19937_64 rng(2024);
  auto run = [](const ConvexPolyhedron<double>& a, const ConvexPolyhedron<double>& b) {
    const GaussMapWalk wa(a), wb(b);
    PlainKernel<double> k(a, b);
    sat::TraversalStats ts;
    const auto r = sat::traversal_with(k, wa, wb, {}, &ts);
    // bounded by the size of the overlay: every arc is walked or tested once
    const std::int64_t ea = a.edge_count(), eb = b.edge_count();
    CHECK(ts.arc_tests <= ea * (4 * eb + 2 * b.vertex_count() + 8));
    // full scans only as a climb's fallback, at most one per face
    CHECK(ts.support_scans <= a.face_count() + b.face_count());
    return r;
  };
  // a shape against itself: every arc and Gauss vertex of A lies on one of -B's antipodes
  for (int n : {4, 8, 30}) {
    const auto h = test::sphere_hull(rng, n);
    run(h, h);
    std::vector<V3> neg;
    for (const auto& v : h.vertices()) neg.push_back(-v);
    run(h, test::moved(h, -Eigen::Matrix3d::Identity(), V3(0, 0, 0)));
  }
  // nearly flat and sliver shapes, huge and tiny scales, near-parallel edges
  for (double s : {1e-6, 1.0, 1e6}) {
    const auto slab =
        test::moved(shapes::box<double>(s, s, s * 1e-7), test::random_rotation(rng), V3(0, 0, 0));
    const auto needle =
        test::moved(shapes::box<double>(s * 1e-7, s * 1e-7, s), test::random_rotation(rng), V3(0, 0, 0));
    run(slab, needle);
    run(needle, slab);
    const auto p = shapes::prism<double>(64, s, s);
    const Eigen::Matrix3d tiny = Eigen::AngleAxisd(1e-12, V3(0, 0, 1)).toRotationMatrix();
    run(p, test::moved(p, tiny, V3(0, 0, 0)));
    run(shapes::regular_polygon<double>(64, s),
        test::moved(shapes::regular_polygon<double>(64, s), tiny, V3(0, 0, 0)));
  }
}

TEST_CASE("traversal rejects walk data of another hull", "[traversal]") {
  const auto a = shapes::cube<double>(1.0);
  const auto b = shapes::tetrahedron<double>(1.0);
  const GaussMapWalk wa(a), wb(b);
  CHECK_THROWS_AS(sat::traversal(a, wb, b, wa), InvalidInput);
  CHECK_NOTHROW(sat::traversal(a, wa, b, wb));
  const ConvexPolyhedron<double> empty;
  CHECK_THROWS_AS(sat::traversal(a, empty), InvalidInput);
  CHECK_THROWS_AS(sat::traversal(empty, b), InvalidInput);
}

TEST_CASE("traversal with precomputed walk data does not allocate per query (float, double)", "[traversal]") {
  std::mt19937_64 rng(5150);
  const auto ad = test::sphere_hull(rng, 128);
  const auto bd = test::moved(test::sphere_hull(rng, 128), test::random_rotation(rng), V3(0.4, 0.3, 0.1));
  const auto af = ConvexPolyhedron<float>::convert_from(ad);
  const auto bf = ConvexPolyhedron<float>::convert_from(bd);
  const GaussMapWalk wa(ad), wb(bd);
  SatResult<double> rd;
  SatResult<float> rf, re;
  const long allocations = test::count_allocations([&] {
    rd = sat::traversal(ad, wa, bd, wb);
    rf = sat::traversal(af, wa, bf, wb);
    re = sat::traversal(af, wa, bf, wb, {.early_out = true});
  });
  CHECK(allocations == 0);
  CHECK(rd.feature == sat::gauss_map(ad, bd).feature);
  CHECK(rf.feature == sat::gauss_map(af, bf).feature);
  CHECK(re.overlap == rf.overlap);
  // the convenience overload builds the walk data (allocates): the counter works
  CHECK(test::count_allocations([&] { (void)sat::traversal(ad, bd); }) > 0);
}

TEST_CASE("traversal beyond the inline scratch (more than 1024 faces in total)", "[traversal]") {
  std::mt19937_64 rng(61);
  const auto a = shapes::prism<double>(600, 1.0, 0.5);
  for (int rep = 0; rep < 3; ++rep) {
    const auto b = test::moved(shapes::prism<double>(600, 0.8, 0.6), test::random_rotation(rng),
                               V3(0.5, 0.2 * rep, 0.9));
    REQUIRE(a.face_count() + b.face_count() > sat::kTraversalInlineFaces);
    const auto t = sat::traversal(a, b);
    check_same(t, sat::gauss_map(a, b), "gauss_map");
  }
}
