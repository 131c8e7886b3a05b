// The shrinker (fuzz/include/sepax/fuzz/shrink.hpp), driven by injected
// failure predicates so the tests do not depend on a real bug.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <sepax/fuzz/generators.hpp>
#include <sepax/fuzz/shrink.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/sat_gauss_map.hpp>

using namespace sepax;
using namespace sepax::fuzz;
using V = Vec3<double>;

namespace {

bool builds(const ShapeSpec& s) {
  try {
    std::vector<Vec3<float>> v;
    for (const auto& p : s.vertices) v.push_back(vec_from_double<float>(p));
    (void)ConvexPolyhedron<float>::from_faces(std::move(v), s.faces);
    return true;
  } catch (const InvalidInput&) {
    return false;
  }
}

bool has_vertex(const ShapeSpec& s, const V& p) {
  return std::find(s.vertices.begin(), s.vertices.end(), p) != s.vertices.end();
}

std::vector<V> sorted(std::vector<V> v) {
  std::sort(v.begin(), v.end(), [](const V& x, const V& y) {
    return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
  });
  return v;
}

// A hull of n random points on a sphere of radius r around c, plus `extra` points.
ShapeSpec blob(std::uint64_t seed, int n, double r, const V& c, const std::vector<V>& extra) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::vector<V> pts = extra;
  for (int i = 0; i < n; ++i) {
    V d(g(rng), g(rng), g(rng));
    pts.push_back(c + d.normalized() * r);
  }
  return hull_of(pts);
}

}  // namespace

TEST_CASE("shrink: a synthetic failure shrinks to its known minimal case", "[fuzz][shrink]") {
  // The "bug" needs three given vertices in A and three in B.  The unique
  // minimal case is the two triangles made of exactly those vertices.
  const std::vector<V> P{V(2, 0, 0), V(0, 2, 0), V(0, 0, 2)};
  const std::vector<V> Q{V(5, 1, 1), V(7, 1, 1), V(6, 3, 1.5)};
  FuzzCase c;
  c.family = "synthetic";
  c.a = blob(1, 40, 1.0, V(0.3, 0.2, 0.1), P);
  c.b = blob(2, 30, 1.1, V(6, 1.5, 1.2), Q);
  for (const auto& p : P) REQUIRE(has_vertex(c.a, p));
  for (const auto& q : Q) REQUIRE(has_vertex(c.b, q));
  const FailurePredicate fails = [&](const FuzzCase& x) {
    if (!builds(x.a) || !builds(x.b)) return false;
    for (const auto& p : P)
      if (!has_vertex(x.a, p)) return false;
    for (const auto& q : Q)
      if (!has_vertex(x.b, q)) return false;
    return true;
  };
  REQUIRE(fails(c));
  const FuzzCase before = c;
  ShrinkStats st;
  ShrinkOptions opt;
  opt.max_steps = 2000;
  opt.max_seconds = 600;
  const FuzzCase m = shrink(c, fails, opt, &st);
  INFO("steps " << st.steps << " kept " << st.kept);
  CHECK(fails(m));
  CHECK_FALSE(st.out_of_budget);
  CHECK(sorted(m.a.vertices) == sorted(P));
  CHECK(sorted(m.b.vertices) == sorted(Q));
  CHECK(m.a.faces.size() == 2);  // double-sided triangles
  CHECK(m.b.faces.size() == 2);
  // the original is untouched, and the result is deterministic
  CHECK(c.a.vertices == before.a.vertices);
  ShrinkStats st2;
  const FuzzCase m2 = shrink(c, fails, opt, &st2);
  CHECK(m2.a.vertices == m.a.vertices);
  CHECK(m2.b.vertices == m.b.vertices);
  CHECK(st2.steps == st.steps);
}

TEST_CASE("shrink: pose simplification un-rotates B and rounds its offset", "[fuzz][shrink]") {
  // The "bug": two boxes (8 vertices each) that exact arithmetic separates.
  const ShapeSpec cube = builtin_shape("cube");
  FuzzCase c;
  c.family = "synthetic";
  const double tA[3] = {0, 0, 0}, qA[4] = {1, 0, 0, 0};
  const double tB[3] = {2.718281828, 0.314159265, -0.577215665}, qB[4] = {0.9, 0.3, -0.2, 0.25};
  c.a = posed(cube, tA, qA);
  c.b = posed(cube, tB, qB);
  auto exact_sep = [](const FuzzCase& x) {
    auto conv = [](const ShapeSpec& s) {  // the exact image of the float polyhedron, as check_case builds it
      std::vector<Vec3<float>> v;
      for (const auto& p : s.vertices) v.push_back(vec_from_double<float>(p));
      return ConvexPolyhedron<mpq_class>::convert_from(
          ConvexPolyhedron<float>::from_faces(std::move(v), s.faces));
    };
    return sign(sat::gauss_map(conv(x.a), conv(x.b)).separation);
  };
  const FailurePredicate fails = [&](const FuzzCase& x) {
    return builds(x.a) && builds(x.b) && x.a.vertices.size() == 8 && x.b.vertices.size() == 8 &&
           exact_sep(x) > 0;
  };
  REQUIRE(fails(c));
  ShrinkStats st;
  const FuzzCase m = shrink(c, fails, ShrinkOptions{}, &st);
  std::string log;
  for (const auto& l : st.log) log += l + "\n";
  INFO(log);
  REQUIRE(fails(m));
  // B is axis-aligned again: two distinct values per axis.
  for (int k = 0; k < 3; ++k) {
    std::vector<double> xs;
    for (const auto& v : m.b.vertices) xs.push_back(v[k]);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    CHECK(xs.size() == 2);
  }
  // every coordinate is a short dyadic (at most 4 fractional bits): human-readable
  for (const auto* s : {&m.a, &m.b})
    for (const auto& v : s->vertices)
      for (int k = 0; k < 3; ++k) CHECK(std::ldexp(v[k], 4) == std::nearbyint(std::ldexp(v[k], 4)));
}

TEST_CASE("shrink: the step budget is respected, and a passing case is returned unchanged",
          "[fuzz][shrink]") {
  FuzzCase c;
  c.a = blob(3, 30, 1.0, V(0, 0, 0), {});
  c.b = blob(4, 30, 1.0, V(1, 0, 0), {});
  int calls = 0;
  const FailurePredicate always = [&](const FuzzCase&) {
    ++calls;
    return true;
  };
  ShrinkOptions opt;
  opt.max_steps = 7;
  ShrinkStats st;
  (void)shrink(c, always, opt, &st);
  CHECK(st.steps == 7);
  CHECK(calls == 7);
  CHECK(st.out_of_budget);

  const FailurePredicate never = [](const FuzzCase&) { return false; };
  const FuzzCase same = shrink(c, never, {}, &st);
  CHECK(st.steps == 1);
  CHECK(st.kept == 0);
  CHECK(same.a.vertices == c.a.vertices);
}

TEST_CASE("shrink: failure signatures and the reproducer file", "[fuzz][shrink]") {
  CaseReport r;
  r.valid = true;
  r.unexplained.push_back({"feature", "float_plain", "gauss_map", "synthetic"});
  r.unexplained.push_back({"separation", "double_plain", "brute_force", "synthetic"});
  r.unexplained_count = 2;
  const FailureSignature s = signature_of(r);
  CHECK(s.str() == "feature float_plain gauss_map");
  CHECK(has_failure(r, s));
  CHECK_FALSE(has_failure(r, FailureSignature{"feature", "double_plain", "gauss_map"}));
  CHECK(signature_of(CaseReport{}).comparison.empty());
  CHECK(shrunk_path("dir/unexplained-boxes-7.case") == "dir/unexplained-boxes-7-min.case");
  CHECK(shrunk_path("dir/x.case", "out") == "out/x-min.case");
  // A real case has no unexplained finding: nothing to shrink, nothing written.
  const FuzzCase c = generate("boxes", 5);
  CHECK_FALSE(write_shrunk_reproducer("shrink-test-out/none.case", "-", c, check_case_guarded(c)));
  CHECK_FALSE(std::filesystem::exists("shrink-test-out/none.case"));
}

TEST_CASE("shrink: end to end through the real checker", "[fuzz][shrink]") {
  // Preserve a real classification (a float_plain feature tie on a generated
  // touching pair) instead of a bug: the shrinker must keep it while simplifying.
  auto has_tie = [](const FuzzCase& x) {
    const CaseReport r = check_case_guarded(x);
    const auto it = r.by_config.find("feature/float_plain");
    return r.valid && it != r.by_config.end() && it->second[Classification::tie] > 0;
  };
  FuzzCase c;
  bool found = false;
  for (std::uint64_t seed = 0; seed < 200 && !found; ++seed) {
    c = generate("touching", seed);
    found = has_tie(c);
  }
  REQUIRE(found);
  ShrinkOptions opt;
  opt.max_steps = 120;
  ShrinkStats st;
  const FuzzCase m = shrink(c, has_tie, opt, &st);
  std::string log;
  for (const auto& l : st.log) log += l + "\n";
  INFO("seed " << c.seed << "\n" << log);
  CHECK(has_tie(m));
  CHECK(st.steps <= 120);
  CHECK(st.kept > 0);
  CHECK(m.a.vertices.size() + m.b.vertices.size() <= c.a.vertices.size() + c.b.vertices.size());
}

TEST_CASE("shrink: terminates on its own (no cycles), even when every valid case 'fails'", "[fuzz][shrink]") {
  // Steps that undo each other (rotate, round, rotate, ...) used to cycle
  // until the budget ran out; every kept step must now simplify the case.
  FuzzCase c;
  c.a = blob(5, 25, 1.0, V(10.1, -3.3, 7.7), {});
  c.b = blob(6, 25, 0.7, V(11.3, -2.9, 7.1), {});
  const FailurePredicate valid = [](const FuzzCase& x) { return builds(x.a) && builds(x.b); };
  ShrinkOptions opt;
  opt.max_steps = 100000;
  opt.max_seconds = 600;
  ShrinkStats st;
  const FuzzCase m = shrink(c, valid, opt, &st);
  CHECK_FALSE(st.out_of_budget);
  CHECK(st.steps < 2000);
  CHECK(m.a.vertices.size() == 3);
  CHECK(m.b.vertices.size() == 3);
  CHECK(valid(m));
}
