// sepax/hull/radix_sort.hpp
//
// Linear-time sorts the hull builder runs on every point, each giving the permutation a comparison sort
// with ties by index gives:
//   1. radix_sort: a stable LSD radix sort of items by an unsigned key of one or more words, one byte per
//      pass, least significant byte first, skipping a pass whose byte is the same for every item.  Items
//      that start in index order and tie on the key stay in index order.
//   2. order_key: a float or double as an unsigned key whose order is the number's (-0 as +0: equal, as ==
//      says).
//   3. lex_order: the indices of float or double points in lexicographic order of (x, y, z), equal points
//      in index order (the order welding walks, welded_points.hpp): a radix sort on x, then comparisons
//      within each run of equal x.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "../vec3.hpp"

namespace sepax::hull::detail {

/// Sorts a stably by key: word(item, w) for w = 0 .. kWords - 1 is the key's w-th unsigned word, word 0
/// the most significant.
template <int kWords, class Item, class Word>
inline void radix_sort(std::vector<Item>& a, Word word) {
  using U = decltype(word(a.front(), 0));
  static_assert(std::is_unsigned_v<U>);
  constexpr int kBytes = static_cast<int>(sizeof(U));
  constexpr int kPasses = kWords * kBytes;  // pass q: byte q % kBytes of word kWords - 1 - q / kBytes
  const std::size_t n = a.size();
  if (n < 2) return;
  auto byte = [&](const Item& it, int q) {
    return static_cast<std::size_t>((word(it, kWords - 1 - q / kBytes) >> (8 * (q % kBytes))) & 0xff);
  };
  // every pass's byte counts, in one sweep: count[q][v] items have byte v in pass q
  std::vector<std::array<std::size_t, 256>> count(static_cast<std::size_t>(kPasses));
  for (auto& c : count) c.fill(0);
  for (const Item& it : a)
    for (int q = 0; q < kPasses; ++q) ++count[static_cast<std::size_t>(q)][byte(it, q)];
  std::vector<Item> b(n);
  for (int q = 0; q < kPasses; ++q) {
    std::array<std::size_t, 256>& h = count[static_cast<std::size_t>(q)];
    if (h[byte(a[0], q)] == n) continue;  // (every item in one bucket: the pass keeps the order)
    std::size_t start = 0;
    for (std::size_t& v : h) {
      const std::size_t m = v;
      v = start;
      start += m;
    }
    for (const Item& it : a) b[h[byte(it, q)]++] = it;
    a.swap(b);
  }
}

/// The unsigned key of a float or double x (not NaN) whose order is x's: sign-magnitude bits mapped to a
/// biased order (a negative x's bits inverted, a positive x's sign bit set); -0 is keyed as +0.
template <class F>
requires std::is_same_v<F, float> || std::is_same_v<F, double>
inline auto order_key(F x) {
  using U = std::conditional_t<std::is_same_v<F, float>, std::uint32_t, std::uint64_t>;
  constexpr U kSign = U(1) << (8 * sizeof(U) - 1);
  const U u = std::bit_cast<U>(F(x + F(0)));  // (-0 + 0 is +0 in rounding to nearest)
  return (u & kSign) != 0 ? U(~u) : U(u | kSign);
}

/// The indices of p in lexicographic order of (x, y, z), equal points in index order: sorted by x alone
/// (radix_sort on x's keys), then each run of equal x by (y, z, index) through comparisons (points rarely
/// share an x: most runs are one point; sorting all three keys by radix took three times the passes).
template <class F>
requires std::is_same_v<F, float> || std::is_same_v<F, double>
inline std::vector<int> lex_order(std::span<const Vec3<F>> p) {
  using U = decltype(order_key(F(0)));
  struct Item {
    U key;
    int index;
  };
  std::vector<Item> a(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) a[i] = Item{order_key(p[i][0]), static_cast<int>(i)};
  radix_sort<1>(a, [](const Item& it, int) { return it.key; });
  std::vector<int> order(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) order[i] = a[i].index;
  for (std::size_t r = 0; r < a.size();) {
    std::size_t end = r + 1;
    while (end < a.size() && a[end].key == a[r].key) ++end;
    if (end - r > 1) {
      std::sort(order.begin() + static_cast<std::ptrdiff_t>(r),
                order.begin() + static_cast<std::ptrdiff_t>(end), [&](int i, int j) {
                  const Vec3<F>& u = p[static_cast<std::size_t>(i)];
                  const Vec3<F>& v = p[static_cast<std::size_t>(j)];
                  if (u[1] != v[1]) return u[1] < v[1];
                  if (u[2] != v[2]) return u[2] < v[2];
                  return i < j;
                });
    }
    r = end;
  }
  return order;
}

}  // namespace sepax::hull::detail
