#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <sepax/manifold_reduction.hpp>

using namespace sepax;

namespace {
std::vector<Vec3<double>> octagon() {
  std::vector<Vec3<double>> p;
  for (int i = 0; i < 8; ++i) {
    const double t = 2 * std::numbers::pi * i / 8;
    p.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  return p;
}
const Vec3<double> up(0, 0, 1);
}  // namespace

TEST_CASE("reduction keeps up to 4 points as they are", "[reduction]") {
  std::vector<Vec3<double>> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  CHECK(reduce_contact_points(p, std::vector<double>{0, 0, 0}, up, 0.0, 0.0) == std::vector<int>{0, 1, 2});
  CHECK(reduce_contact_points(std::vector<Vec3<double>>{}, std::vector<double>{}, up, 0.0, 0.0).empty());
}

TEST_CASE("octagon of equal depth: the lowest index, its opposite, and the square", "[reduction]") {
  const auto p = octagon();
  const auto k = reduce_contact_points(p, std::vector<double>(8, -0.1), up, 1e-12, 1e-12);
  REQUIRE(k.size() == 4);
  CHECK(k[0] == 0);
  CHECK(k[1] == 4);
  std::vector<int> s = k;
  std::sort(s.begin(), s.end());
  CHECK(s == std::vector<int>{0, 2, 4, 6});
}

TEST_CASE("the deepest point is always kept, first", "[reduction]") {
  const auto p = octagon();
  for (int d = 0; d < 8; ++d) {
    std::vector<double> keys(8, -0.1);
    keys[static_cast<std::size_t>(d)] = -0.3;
    const auto k = reduce_contact_points(p, keys, up, 1e-12, 1e-12);
    REQUIRE(!k.empty());
    CHECK(k[0] == d);
  }
}

TEST_CASE("collinear points: two extremes only; coincident points: one", "[reduction]") {
  std::vector<Vec3<double>> p;
  for (int i = 0; i < 6; ++i) p.emplace_back(0.1 * i, 0.2 * i, 0);
  const auto k = reduce_contact_points(p, std::vector<double>{-1, -2, -3, -4, -5, -2}, up, 1e-12, 1e-12);
  CHECK(k == std::vector<int>{4, 0});
  std::vector<Vec3<double>> same(5, Vec3<double>(1, 2, 3));
  CHECK(reduce_contact_points(same, std::vector<double>(5, 0.0), up, 1e-12, 1e-12).size() == 1);
}

TEST_CASE("reduction does not depend on the input order (no ties)", "[reduction]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int iter = 0; iter < 50; ++iter) {
    std::vector<Vec3<double>> p;
    std::vector<double> keys;
    for (int i = 0; i < 12; ++i) {
      p.emplace_back(u(rng), u(rng), 0.01 * u(rng));
      keys.push_back(u(rng));
    }
    const auto k1 = reduce_contact_points(p, keys, up, 0.0, 0.0);
    std::vector<int> perm(12);
    for (int i = 0; i < 12; ++i) perm[static_cast<std::size_t>(i)] = i;
    std::shuffle(perm.begin(), perm.end(), rng);
    std::vector<Vec3<double>> p2;
    std::vector<double> keys2;
    for (int i : perm) {
      p2.push_back(p[static_cast<std::size_t>(i)]);
      keys2.push_back(keys[static_cast<std::size_t>(i)]);
    }
    const auto k2 = reduce_contact_points(p2, keys2, up, 0.0, 0.0);
    REQUIRE(k1.size() == k2.size());
    for (std::size_t j = 0; j < k1.size(); ++j) CHECK(perm[static_cast<std::size_t>(k2[j])] == k1[j]);
    // the kept points are distinct and the deepest is first
    CHECK(k1.size() == 4);
    for (double key : keys) CHECK(keys[static_cast<std::size_t>(k1[0])] <= key);
  }
}
