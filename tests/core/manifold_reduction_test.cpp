#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <sepax/manifold_reduction.hpp>

using namespace sepax;

namespace {
using V = Vec3<double>;
const V up(0, 0, 1);

std::vector<V> octagon() {
  std::vector<V> p;
  for (int i = 0; i < 8; ++i) {
    const double t = 2 * std::numbers::pi * i / 8;
    p.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  return p;
}

// Brute force, independent of the library's scans: the largest hull area
// (shoelace of the convex hull, gift wrapping in the xy plane) over every
// subset of 4 points that contains point d.
// Convex hull in the xy plane (Andrew's monotone chain), counter-clockwise,
// without collinear or repeated points; exact for small integers.
std::vector<V> hull_xy(std::vector<V> q) {
  if (q.empty()) return q;
  std::sort(q.begin(), q.end(),
            [](const V& a, const V& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); });
  auto cr = [](const V& o, const V& a, const V& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<V> h(2 * q.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    while (k >= 2 && cr(h[k - 2], h[k - 1], q[i]) <= 0) --k;
    h[k++] = q[i];
  }
  for (std::size_t i = q.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cr(h[k - 2], h[k - 1], q[i]) <= 0) --k;
    h[k++] = q[i];
  }
  h.resize(k - 1);  // the last point repeats the first
  return h;
}

// The hull area (shoelace), 0 with fewer than 3 distinct hull corners.
double hull_area_xy(const std::vector<V>& q) {
  const std::vector<V> h = hull_xy(q);
  if (h.size() < 3) return 0;
  double s = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const V& a = h[i];
    const V& b = h[(i + 1) % h.size()];
    s += a[0] * b[1] - b[0] * a[1];
  }
  return std::abs(s) / 2;
}

double best_quad_with(const std::vector<V>& p, int d) {
  const int n = static_cast<int>(p.size());
  double best = 0;
  for (int j = 0; j < n; ++j)
    for (int k = j + 1; k < n; ++k)
      for (int l = k + 1; l < n; ++l)
        if (j != d && k != d && l != d) best = std::max(best, hull_area_xy({p[d], p[j], p[k], p[l]}));
  return best;
}

double kept_area(const std::vector<V>& p, const std::vector<int>& k) {
  std::vector<V> q;
  for (int i : k) q.push_back(p[static_cast<std::size_t>(i)]);
  return hull_area_xy(q);
}

// A convex polygon of lattice points (counter-clockwise), with `extra`
// collinear points inserted on its edges at lattice positions: every double
// operation of the reduction is exact on these (small integers), so ties are
// exact ties.
std::vector<V> lattice_convex(std::mt19937& rng, int extra) {
  std::uniform_int_distribution<int> u(-20, 20);
  std::vector<V> pts;
  for (int i = 0; i < 12; ++i) pts.emplace_back(u(rng), u(rng), 0);
  const std::vector<V> h = hull_xy(pts);
  // insert midpoints of edges with even coordinate differences
  std::vector<V> out;
  int added = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    out.push_back(h[i]);
    const V& a = h[i];
    const V& b = h[(i + 1) % h.size()];
    const V m = (a + b) / 2;
    if (added < extra && std::floor(m[0]) == m[0] && std::floor(m[1]) == m[1]) {
      out.push_back(m);
      ++added;
    }
  }
  // rotate the start so that the polygon does not always begin at the lowest point
  std::rotate(out.begin(), out.begin() + static_cast<long>(rng() % out.size()), out.end());
  return out;
}
}  // namespace

TEST_CASE("reduction keeps up to 4 points as they are", "[reduction]") {
  std::vector<V> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  CHECK(reduce_contact_points(p, std::vector<double>{0, 0, 0}, up, 0.0, 0.0) == std::vector<int>{0, 1, 2});
  CHECK(reduce_contact_points(std::vector<V>{}, std::vector<double>{}, up, 0.0, 0.0).empty());
  // four points, even collinear or duplicated ones, are not touched
  std::vector<V> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 0, 0}};
  CHECK(reduce_contact_points(line, std::vector<double>{0, -1, 0, 0}, up, 0.0, 0.0) ==
        std::vector<int>{0, 1, 2, 3});
}

TEST_CASE("octagon of equal depth: the lowest index and the square, in polygon order", "[reduction]") {
  const auto p = octagon();
  const auto k = reduce_contact_points(p, std::vector<double>(8, -0.1), up, 1e-12, 1e-12);
  CHECK(k == std::vector<int>{0, 2, 4, 6});
  // exact tie rule (tolerances 0) on the same points: the square is the unique maximum
  CHECK(reduce_contact_points(p, std::vector<double>(8, -0.1), up, 0.0, 0.0) == std::vector<int>{0, 2, 4, 6});
}

TEST_CASE("the deepest point is always kept, first, and the quad is the largest containing it",
          "[reduction]") {
  const auto p = octagon();
  for (int d = 0; d < 8; ++d) {
    std::vector<double> keys(8, -0.1);
    keys[static_cast<std::size_t>(d)] = -0.3;
    const auto k = reduce_contact_points(p, keys, up, 1e-12, 1e-12);
    REQUIRE(k.size() == 4);
    CHECK(k[0] == d);
    CHECK(kept_area(p, k) >= best_quad_with(p, d) - 1e-12);
  }
}

TEST_CASE("deepest ties: the lowest index (exactly equal keys, and float keys within key_tol)",
          "[reduction]") {
  const auto p = octagon();
  std::vector<double> keys(8, 0.0);
  keys[5] = -1;
  keys[3] = -1;
  CHECK(reduce_contact_points(p, keys, up, 0.0, 0.0)[0] == 3);
  keys[3] = -1 + 1e-13;  // not the deepest exactly, but within key_tol
  CHECK(reduce_contact_points(p, keys, up, 0.0, 0.0)[0] == 5);
  CHECK(reduce_contact_points(p, keys, up, 1e-12, 0.0)[0] == 3);
}

TEST_CASE("maximum area against brute force, convex lattice polygons with collinear points, both scans",
          "[reduction]") {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> key(-3, 0);  // few distinct keys: many depth ties
  int tested = 0;
  for (int iter = 0; iter < 300; ++iter) {
    const auto p = lattice_convex(rng, iter % 4);
    if (p.size() < 5) continue;
    ++tested;
    std::vector<double> keys;
    for (std::size_t i = 0; i < p.size(); ++i) keys.push_back(key(rng));
    INFO("iteration " << iter << ", " << p.size() << " points");
    const auto k = reduce_contact_points(p, keys, up, 0.0, 0.0);
    const auto g = reduce_contact_points(p, keys, up, 0.0, 0.0, /*force_general=*/true);
    // the points are in weakly convex position from every start (so the
    // O(n^2) scan ran), and the O(n^2) and O(n^3) scans choose the same points
    for (std::size_t s0 = 0; s0 < p.size(); ++s0) {
      std::vector<int> q;
      for (std::size_t t = 0; t < p.size(); ++t) q.push_back(static_cast<int>((s0 + t) % p.size()));
      int sigma = 0;
      CHECK(weakly_convex_sequence(p, q, up, sigma));
      CHECK(sigma == 1);
    }
    CHECK(k == g);
    REQUIRE(k.size() >= 3);
    // the deepest, lowest index on ties
    const double kmin = *std::min_element(keys.begin(), keys.end());
    const int d = static_cast<int>(std::find(keys.begin(), keys.end(), kmin) - keys.begin());
    CHECK(k[0] == d);
    // exactly maximal (integer coordinates: all areas exact in double)
    const double best = best_quad_with(p, d);
    CHECK(kept_area(p, k) == best);
    // fewer than 4 only when no fourth point adds area
    if (k.size() == 3) {
      for (int j = 0; j < static_cast<int>(p.size()); ++j) {
        if (std::find(k.begin(), k.end(), j) != k.end()) continue;
        CHECK(hull_area_xy({p[k[0]], p[k[1]], p[k[2]], p[j]}) == kept_area(p, k));
      }
    }
  }
  CHECK(tested >= 200);
}

TEST_CASE("convex position test: a star polygon and a reflex vertex are not convex", "[reduction]") {
  // pentagram (regular pentagon visited 0,2,4,1,3) around its centre: every
  // fan triangle from the centre and every turn has the same sign, but the
  // sequence winds twice
  std::vector<V> p{{0, 0, 0}};
  for (int i = 0; i < 5; ++i) {
    const double t = 2 * std::numbers::pi * ((2 * i) % 5) / 5;
    p.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  int sigma = 0;
  CHECK_FALSE(weakly_convex_sequence(p, {0, 1, 2, 3, 4, 5}, up, sigma));
  CHECK_FALSE(weakly_convex_sequence(p, {1, 2, 3, 4, 5}, up, sigma));
  // square with one corner pushed in
  std::vector<V> r{{0, 0, 0}, {4, 0, 0}, {2, 2, 0}, {4, 4, 0}, {0, 4, 0}};
  CHECK_FALSE(weakly_convex_sequence(r, {0, 1, 2, 3, 4}, up, sigma));
  CHECK_FALSE(weakly_convex_sequence(r, {2, 3, 4, 0, 1}, up, sigma));
  // the square with a point on an edge, clockwise about up
  std::vector<V> c{{0, 0, 0}, {0, 4, 0}, {4, 4, 0}, {4, 2, 0}, {4, 0, 0}};
  CHECK(weakly_convex_sequence(c, {0, 1, 2, 3, 4}, up, sigma));
  CHECK(sigma == -1);
  CHECK(weakly_convex_sequence(c, {3, 4, 0, 1, 2}, up, sigma));
}

TEST_CASE("convex position up to a float tolerance: near-straight turns count as straight", "[reduction]") {
  // a square with a point on an edge pushed inwards by 1e-9: reflex exactly,
  // straight within a tolerance of 1e-6 (doubled area)
  std::vector<V> c{{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {4, 4, 0}, {0, 4, 0}};
  c[2][0] -= 1e-9;
  int sigma = 0;
  CHECK_FALSE(weakly_convex_sequence(c, {0, 1, 2, 3, 4}, up, sigma));
  CHECK(weakly_convex_sequence(c, {0, 1, 2, 3, 4}, up, sigma, 1e-6));
  CHECK(sigma == 1);
  // both scans pick the square's corners
  const std::vector<double> keys{0, 0, 0, 0, -1};
  const auto k = reduce_contact_points(c, keys, up, 0.0, 1e-6);
  CHECK(k == std::vector<int>{4, 0, 1, 3});
  CHECK(reduce_contact_points(c, keys, up, 0.0, 1e-6, true) == k);
}

TEST_CASE("points not in convex position: the general scan, still the maximum", "[reduction]") {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> u(-10, 10);
  for (int iter = 0; iter < 200; ++iter) {
    std::vector<V> p;
    std::vector<double> keys;
    const int n = 5 + iter % 6;
    for (int i = 0; i < n; ++i) {
      p.emplace_back(u(rng), u(rng), 0);
      keys.push_back(u(rng));
    }
    INFO("iteration " << iter);
    const auto k = reduce_contact_points(p, keys, up, 0.0, 0.0);
    const int d = static_cast<int>(std::min_element(keys.begin(), keys.end()) - keys.begin());
    REQUIRE(!k.empty());
    CHECK(k[0] == d);
    CHECK(kept_area(p, k) == best_quad_with(p, d));
    // tie rule: the smallest sorted index triple among the maximal quads
    if (k.size() == 4) {
      std::array<int, 3> mine{k[1], k[2], k[3]};
      std::sort(mine.begin(), mine.end());
      bool earlier_max = false;
      for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
          for (int c = b + 1; c < n; ++c) {
            if (a == d || b == d || c == d) continue;
            if (std::array<int, 3>{a, b, c} < mine &&
                hull_area_xy({p[d], p[a], p[b], p[c]}) == kept_area(p, k))
              earlier_max = true;
          }
      CHECK_FALSE(earlier_max);
    }
  }
}

TEST_CASE("collinear points: the deepest and the two extremes; coincident points: one", "[reduction]") {
  std::vector<V> p;
  for (int i = 0; i < 6; ++i) p.emplace_back(0.1 * i, 0.2 * i, 0);
  // deepest in the middle (index 4): the two ends 0 and 5
  CHECK(reduce_contact_points(p, std::vector<double>{-1, -2, -3, -4, -5, -2}, up, 1e-12, 1e-12) ==
        std::vector<int>{4, 5, 0});
  // deepest at an end: the other end only
  CHECK(reduce_contact_points(p, std::vector<double>{-1, -2, -3, -4, -5, -9}, up, 1e-12, 1e-12) ==
        std::vector<int>{5, 0});
  std::vector<V> same(5, V(1, 2, 3));
  CHECK(reduce_contact_points(same, std::vector<double>(5, 0.0), up, 1e-12, 1e-12) == std::vector<int>{0});
  CHECK(reduce_contact_points(same, std::vector<double>(5, 0.0), up, 0.0, 0.0) == std::vector<int>{0});
}

TEST_CASE("duplicates: a triangle with repeated corners gives the triangle", "[reduction]") {
  std::vector<V> p{{0, 0, 0}, {4, 0, 0}, {4, 0, 0}, {0, 3, 0}, {0, 3, 0}, {0, 0, 0}, {2, 0, 0}};
  const auto k = reduce_contact_points(p, std::vector<double>{0, 0, -1, 0, 0, 0, 0}, up, 0.0, 0.0);
  REQUIRE(k.size() == 3);
  CHECK(k[0] == 2);
  CHECK(kept_area(p, k) == 6);
}

TEST_CASE("deterministic, and independent of the input order when there is no tie", "[reduction]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int iter = 0; iter < 50; ++iter) {
    std::vector<V> p;
    std::vector<double> keys;
    for (int i = 0; i < 12; ++i) {
      p.emplace_back(u(rng), u(rng), 0.01 * u(rng));
      keys.push_back(u(rng));
    }
    const auto k1 = reduce_contact_points(p, keys, up, 0.0, 0.0);
    CHECK(reduce_contact_points(p, keys, up, 0.0, 0.0) == k1);
    std::vector<int> perm(12);
    for (int i = 0; i < 12; ++i) perm[static_cast<std::size_t>(i)] = i;
    std::shuffle(perm.begin(), perm.end(), rng);
    std::vector<V> p2;
    std::vector<double> keys2;
    for (int i : perm) {
      p2.push_back(p[static_cast<std::size_t>(i)]);
      keys2.push_back(keys[static_cast<std::size_t>(i)]);
    }
    const auto k2 = reduce_contact_points(p2, keys2, up, 0.0, 0.0);
    REQUIRE(k1.size() == 4);
    REQUIRE(k2.size() == 4);
    CHECK(perm[static_cast<std::size_t>(k2[0])] == k1[0]);
    std::vector<int> s1(k1.begin(), k1.end()), s2;
    for (int i : k2) s2.push_back(perm[static_cast<std::size_t>(i)]);
    std::sort(s1.begin(), s1.end());
    std::sort(s2.begin(), s2.end());
    CHECK(s1 == s2);
    for (double key : keys) CHECK(keys[static_cast<std::size_t>(k1[0])] <= key);
  }
}
