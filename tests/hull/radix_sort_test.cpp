// hull/radix_sort.hpp: lex_order's radix sort gives the permutation a comparison sort on (x, y, z, index) gives, for
// float and double points with duplicates, ties in one or two coordinates, both zeros, both signs,
// subnormals and the extremes of the range.
#include <catch2/catch.hpp>

#include <sepax/hull/radix_sort.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <span>
#include <utility>
#include <vector>

namespace {

using sepax::Vec3;
using sepax::hull::detail::lex_order;
using sepax::hull::detail::order_key;
using sepax::hull::detail::radix_sort;

template <class F>
std::vector<int> compared_order(const std::vector<Vec3<F>>& p) {
  std::vector<int> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    const auto& a = p[static_cast<std::size_t>(i)];
    const auto& b = p[static_cast<std::size_t>(j)];
    if (a[0] != b[0]) return a[0] < b[0];
    if (a[1] != b[1]) return a[1] < b[1];
    if (a[2] != b[2]) return a[2] < b[2];
    return i < j;
  });
  return order;
}

// n points whose coordinates come from a small pool (many ties and duplicates) of values of every kind.
template <class F>
std::vector<Vec3<F>> tied_points(std::size_t n, unsigned seed) {
  using L = std::numeric_limits<F>;
  const std::vector<F> pool{F(0),     -F(0),     F(1),         F(-1),           F(0.5),
                            F(-0.5),  L::min(),  -L::min(),    L::denorm_min(), -L::denorm_min(),
                            L::max(), -L::max(), L::epsilon(), F(1e-3),         F(-1e-3),
                            F(3),     F(-3)};
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
  std::vector<Vec3<F>> p;
  p.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const F x = pool[pick(rng)];
    const F y = pool[pick(rng)];
    const F z = pool[pick(rng)];
    p.emplace_back(x, y, z);
  }
  return p;
}

// n points of random coordinates in [-s, s] (mostly distinct), every tenth a copy of an earlier one.
template <class F>
std::vector<Vec3<F>> spread_points(std::size_t n, unsigned seed, F s) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<F> u(-s, s);
  std::vector<Vec3<F>> p;
  p.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && i % 10 == 0) {
      p.push_back(p[i / 2]);
      continue;
    }
    const F x = u(rng);
    const F y = u(rng);
    const F z = u(rng);
    p.emplace_back(x, y, z);
  }
  return p;
}

template <class F>
void check_orders() {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    for (const std::size_t n : {0u, 1u, 2u, 17u, 1000u, 20000u}) {
      const auto tied = tied_points<F>(n, seed);
      CHECK(lex_order(std::span<const Vec3<F>>(tied)) == compared_order(tied));
      const auto spread = spread_points<F>(n, seed, F(seed == 4 ? 1e30 : 1));
      CHECK(lex_order(std::span<const Vec3<F>>(spread)) == compared_order(spread));
    }
  }
}

}  // namespace

TEST_CASE("lex_order: the order of a comparison sort, ties by index", "[hull][lex_order]") {
  check_orders<float>();
  check_orders<double>();
}

TEST_CASE("lex_order: a key orders as its value, the two zeros alike", "[hull][lex_order]") {
  for (const double a : {-1e300, -2.0, -1.0, -1e-310, 0.0, 1e-310, 1.0, 2.0, 1e300}) {
    for (const double b : {-1e300, -2.0, -1.0, -1e-310, 0.0, 1e-310, 1.0, 2.0, 1e300}) {
      CHECK((order_key(a) < order_key(b)) == (a < b));
      CHECK((order_key(float(a)) < order_key(float(b))) == (float(a) < float(b)));
    }
  }
  CHECK(order_key(-0.0) == order_key(0.0));
  CHECK(order_key(-0.0f) == order_key(0.0f));
}

TEST_CASE("radix_sort: a stable sort by a one-word key (Morton codes with ties)", "[hull][radix_sort]") {
  std::mt19937_64 rng(7);
  for (const std::uint64_t range :
       {std::uint64_t{1}, std::uint64_t{300}, std::uint64_t{1} << 40, ~std::uint64_t{0}}) {
    std::uniform_int_distribution<std::uint64_t> u(0, range - (range == ~std::uint64_t{0} ? 0 : 1));
    std::vector<std::pair<std::uint64_t, int>> keyed;
    for (int i = 0; i < 5000; ++i) keyed.emplace_back(u(rng), i);
    auto sorted = keyed;
    std::sort(sorted.begin(), sorted.end());
    radix_sort<1>(keyed, [](const std::pair<std::uint64_t, int>& k, int) { return k.first; });
    CHECK(keyed == sorted);
  }
}
