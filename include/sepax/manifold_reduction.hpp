// sepax/manifold_reduction.hpp
//
// reduce_contact_points: at most four of a face contact's points, by an exact,
// deterministic rule (each step is explained on the function that does it):
//   1. d, the deepest point (smallest key; ties: the lowest index);
//   2. the three others that maximise H, the area of the hull of the four seen
//      along the contact normal (contact_hull_area2; ties: the smallest sorted
//      index triple);
//   3. degenerate sets: the best triangle, the ends of a line, or d alone;
//   4. the scan: O(n^2) when the points are in weakly convex order
//      (weakly_convex_sequence), else O(n^3) over all triples; both find the
//      same maximum with the same tie rule.
// Up to four points are returned unchanged.  Float T takes near-tie tolerances
// relative to the shapes' extent (tolerances.hpp); exact T takes 0 and is exact.
// Output order: d first, then the others in cyclic input order after d.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <utility>
#include <vector>

#include "small_vector.hpp"

#include "vec3.hpp"

namespace sepax {

namespace detail {

template <Number T>
T orient(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& n) {
  return dot(cross(Vec3<T>(b - a), Vec3<T>(c - a)), n);
}

/// sorted (x, y, z) < sorted (u, v, w), lexicographically.
inline bool lex_less(std::array<int, 3> x, std::array<int, 3> y) {
  auto sort3 = [](std::array<int, 3>& s) {
    if (s[0] > s[1]) std::swap(s[0], s[1]);
    if (s[1] > s[2]) std::swap(s[1], s[2]);
    if (s[0] > s[1]) std::swap(s[0], s[1]);
  };
  sort3(x);
  sort3(y);
  return x < y;
}

}  // namespace detail

/// The reduction's area objective H of the points `idx` (2 to 4 indices into
/// `points`): the doubled area of their convex hull seen along `normal`, times
/// |normal|.  Exact for exact T.  Used by the tests and the fuzzer to evaluate
/// a kept set.
///   H(a, b, c)    = |T(a, b, c)|,                 T(a,b,c) = ((b-a) x (c-a)) . normal
///   H(a, b, c, e) = (|T(abc)| + |T(abe)| + |T(ace)| + |T(bce)|) / 2
/// The second formula is the hull area of ANY four points: in convex position
/// the two diagonals split the quad into two pairs of triangles (the four
/// areas sum to twice the quad); when one point lies in the triangle of the
/// other three, the three triangles at it sum to the big one.  Products and
/// sums only: exact for exact T, no sqrt.
template <Number T>
T contact_hull_area2(const std::vector<Vec3<T>>& points, const std::vector<int>& idx, const Vec3<T>& normal) {
  auto P = [&](std::size_t i) -> const Vec3<T>& { return points[static_cast<std::size_t>(idx[i])]; };
  using detail::orient;
  if (idx.size() == 3) return abs_of(orient(P(0), P(1), P(2), normal));
  if (idx.size() == 4) {
    const T s = T(abs_of(orient(P(0), P(1), P(2), normal)) + abs_of(orient(P(0), P(1), P(3), normal)) +
                  abs_of(orient(P(0), P(2), P(3), normal)) + abs_of(orient(P(1), P(2), P(3), normal)));
    return T(s / T(2));
  }
  return T(0);
}

/// Are points[q[0]], points[q[1]], ... (a cyclic sequence) in weakly convex
/// position in this order?  On success `sigma` is the orientation (+1: counter-
/// clockwise about `normal`).  Exact for exact T (tol = 0).  For float T,
/// orientations within `tol` (an H value, e.g. the reduction's area_tol) of 0
/// count as straight: a polygon convex up to rounding and near-collinear clip
/// points takes the O(n^2) scan, whose H then differs from the hull area by no
/// more than such tolerances (near-ties).
template <Number T, class Points = std::vector<Vec3<T>>, class Seq = std::vector<int>>
bool weakly_convex_sequence(const Points& points, const Seq& q, const Vec3<T>& normal, int& sigma,
                            const T& tol = T(0)) {
  const std::size_t n = q.size();
  auto P = [&](std::size_t i) -> const Vec3<T>& { return points[static_cast<std::size_t>(q[i % n])]; };
  auto sgn_tol = [&](const T& x) { return x > tol ? 1 : (x < T(-tol) ? -1 : 0); };
  using detail::orient;
  sigma = 0;
  // q[0] must not coincide with its neighbours (its two rays below).
  if (!(squared_norm(Vec3<T>(P(1) - P(0))) > T(0)) || !(squared_norm(Vec3<T>(P(n - 1) - P(0))) > T(0)))
    return false;
  // Fan from q[0]: the angles of q[1..n-1] around q[0] must be monotone ...
  for (std::size_t t = 1; t + 1 < n; ++t) {
    const int s = sgn_tol(orient(P(0), P(t), P(t + 1), normal));
    if (s == 0) continue;
    if (sigma == 0) sigma = s;
    if (s != sigma) return false;
  }
  if (sigma == 0) return false;  // all on a line through q[0]: no polygon
  // ... and within a half-turn: every point on the inner side of the first ray
  // q0->q1 and of the last ray q0->q[n-1] (no second winding around q0).
  for (std::size_t t = 2; t < n; ++t)
    if (sgn_tol(orient(P(0), P(1), P(t), normal)) == -sigma) return false;
  for (std::size_t t = 1; t + 1 < n; ++t)
    if (sgn_tol(orient(P(0), P(t), P(n - 1), normal)) == -sigma) return false;
  // With the angles around q[0] monotone within a half-turn the polygon is
  // simple and star-shaped from q[0]; a simple polygon whose every turn goes
  // the same way (or straight) is convex.
  // Every turn the same way (or straight).
  for (std::size_t t = 0; t < n; ++t) {
    const int s = sgn_tol(orient(P(t + n - 1), P(t), P(t + 1), normal));
    if (s != 0 && s != sigma) return false;
  }
  return true;
}

/// Indices (into `points`) of the kept points, the deepest first.  `keys[i]`
/// orders depth: smaller = deeper.  `key_tol`, `area_tol`: float near-tie
/// tolerances (a key, an H value); 0 for exact T.  `force_general`: always use
/// the O(n^3) scan (tests compare both scans).
///
/// The rule:
///   1. d: the deepest point (smallest key).  Ties: the lowest index.
///   2. M4 = max H(d, a, b, c) over the triples of other points
///      (contact_hull_area2).  The chosen triple is the one with the
///      lexicographically smallest sorted index triple among the maximal ones.
///   3. Degenerate sets (only when more than 4 points were given):
///        * M4 <= M3 + area_tol, M3 = max H(d, a, b) over pairs: a fourth point
///          adds no area (every point lies on the boundary of the best
///          triangle, e.g. duplicates): the best triangle (same tie rule);
///        * M3 <= area_tol (all points on a line through d): d and the extreme
///          points of the line (the point farthest from d, then the point
///          farthest from that one unless d itself is as far: d is an end);
///        * every point within sqrt(area_tol) of d: d alone.
///   Up to 4 points are returned unchanged (all indices, in input order).
///
/// Cost.  The clipped points of a face contact are a convex polygon in input
/// (clip) order, up to duplicates and collinear points.  When the points are
/// in weakly convex position in input order (checked exactly for exact T:
/// every turn and every fan triangle from d has the same sign or is zero),
/// every 4-subset d < j < k < l in cyclic order from d is a weakly convex quad
/// with H = T(d,j,k) + T(d,k,l) (oriented), and for a fixed middle vertex k the
/// best j in (d, k) and the best l in (k, d) are independent: an O(n^2) scan.
/// Otherwise (float rounding, or points not from a convex clip) an O(n^3) scan
/// of all triples with the general formula; n is small.  Both scans maximise
/// the same quantity and use the same tie rule, so they choose the same points.
///
/// Float.  Values within key_tol / area_tol of the maximum (minimum key) count
/// as ties and the tie rule decides, so rounding does not change a choice
/// between (nearly) equal candidates when a configuration is scaled.  Without
/// a (near-)tie the float choice is the exact choice on the same points.
///
/// Output order: d first, then the others in cyclic input order after d (for a
/// convex polygon: the hull order of the kept quad).
///
/// reduce_contact_points_into is the same with any containers: points and
/// keys indexable with size(), out with clear() and push_back() (the kept
/// indices, at most 4).  Its working tables are SmallVectors: no allocation
/// for up to kReductionInlinePoints points (the O(n^3) general scan, taken
/// when the points are not in weakly convex order, for up to
/// kReductionInlineGeneral).
inline constexpr std::size_t kReductionInlinePoints = 64;
inline constexpr std::size_t kReductionInlineGeneral = 16;

template <Number T, class Points, class Keys, class Out>
void reduce_contact_points_into(const Points& points, const Keys& keys, const Vec3<T>& normal,
                                const T& key_tol, const T& area_tol, Out& out, bool force_general = false);

template <Number T>
std::vector<int> reduce_contact_points(const std::vector<Vec3<T>>& points, const std::vector<T>& keys,
                                       const Vec3<T>& normal, const T& key_tol, const T& area_tol,
                                       bool force_general = false) {
  std::vector<int> out;
  reduce_contact_points_into(points, keys, normal, key_tol, area_tol, out, force_general);
  return out;
}

template <Number T, class Points, class Keys, class Out>
void reduce_contact_points_into(const Points& points, const Keys& keys, const Vec3<T>& normal,
                                const T& key_tol, const T& area_tol, Out& out, bool force_general) {
  const int n = static_cast<int>(points.size());
  out.clear();
  if (n == 0) return;
  if (n <= 4) {
    for (int i = 0; i < n; ++i) out.push_back(i);
    return;
  }
  using detail::lex_less;
  using detail::orient;
  auto P = [&](int i) -> const Vec3<T>& { return points[static_cast<std::size_t>(i)]; };
  // 1. the deepest point: the lowest index within key_tol of the smallest key.
  T kmin = keys[0];
  for (const T& k : keys)
    if (k < kmin) kmin = k;
  int d = 0;
  while (keys[static_cast<std::size_t>(d)] > kmin + key_tol) ++d;
  out.push_back(d);
  // The others in cyclic order after d: q[0] = d, q[1..n-1].
  SmallVector<int, kReductionInlinePoints> q(static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t) q[static_cast<std::size_t>(t)] = (d + t) % n;
  auto Q = [&](int t) { return q[static_cast<std::size_t>(t)]; };
  auto cyc = [&](int i) { return (i - d + n) % n; };  // position of index i in q
  auto emit = [&](std::initializer_list<int> list) {
    // up to 3 indices, in cyclic order after d (insertion sort)
    std::array<int, 3> others{};
    std::size_t k = 0;
    for (int x : list) {
      std::size_t at = k++;
      while (at > 0 && cyc(x) < cyc(others[at - 1])) {
        others[at] = others[at - 1];
        --at;
      }
      others[at] = x;
    }
    for (std::size_t i = 0; i < k; ++i) out.push_back(others[i]);
  };

  // 2./3. M4 and the best triple.
  bool have4 = false;
  T m4(0);
  std::array<int, 3> best4{-1, -1, -1};
  int sigma = 0;
  if (!force_general && weakly_convex_sequence(points, q, normal, sigma, area_tol)) {
    // O(n^2): H(d, j, k, l) = sigma (T(d,j,k) + T(d,k,l)) for positions
    // 1 <= a < c < b <= n-1 of j, k, l.
    const Vec3<T> ns = sigma > 0 ? normal : Vec3<T>(-normal);
    const int m = n - 1;
    SmallVector<T, kReductionInlinePoints> bj(static_cast<std::size_t>(n)), bl(static_cast<std::size_t>(n));
    for (int c = 2; c <= m - 1; ++c) {
      T x = orient(P(d), P(Q(1)), P(Q(c)), ns);
      for (int a = 2; a < c; ++a) {
        const T y = orient(P(d), P(Q(a)), P(Q(c)), ns);
        if (y > x) x = y;
      }
      T z = orient(P(d), P(Q(c)), P(Q(c + 1)), ns);
      for (int b = c + 2; b <= m; ++b) {
        const T y = orient(P(d), P(Q(c)), P(Q(b)), ns);
        if (y > z) z = y;
      }
      bj[static_cast<std::size_t>(c)] = x;
      bl[static_cast<std::size_t>(c)] = z;
      const T h = x + z;
      if (!have4 || h > m4) m4 = h, have4 = true;
    }
    // Tie rule: among (j, k, l) with H >= m4 - area_tol, the smallest sorted
    // index triple.  H >= m4 - tol needs T(d,j,k) >= m4 - tol - bl[c] and
    // T(d,k,l) >= m4 - tol - bj[c]; only those are enumerated (one or two each
    // unless collinear points tie).
    const T floor = m4 - area_tol;
    for (int c = 2; c <= m - 1; ++c) {
      const T sj = bj[static_cast<std::size_t>(c)], sl = bl[static_cast<std::size_t>(c)];
      if (sj + sl < floor) continue;
      for (int a = 1; a < c; ++a) {
        const T y = orient(P(d), P(Q(a)), P(Q(c)), ns);
        if (y + sl < floor) continue;
        for (int b = c + 1; b <= m; ++b) {
          const T z = orient(P(d), P(Q(c)), P(Q(b)), ns);
          if (y + z < floor) continue;
          const std::array<int, 3> cand{Q(a), Q(c), Q(b)};
          if (best4[0] < 0 || lex_less(cand, best4)) best4 = cand;
        }
      }
    }
  } else {
    // O(n^3) over all triples (j < k < l by index), the general formula
    // (the same terms in the same order as contact_hull_area2, with the
    // triangles at d tabulated): the maximum, then the first triple in index
    // order within area_tol of it (the smallest sorted triple).
    SmallVector<T, kReductionInlineGeneral * kReductionInlineGeneral> td(
        static_cast<std::size_t>(n) * static_cast<std::size_t>(n), T(0));
    auto TD = [&](int a, int b) -> T& {
      return td[static_cast<std::size_t>(a) * static_cast<std::size_t>(n) + static_cast<std::size_t>(b)];
    };
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        if (a != d && b != d) TD(a, b) = abs_of(orient(P(d), P(a), P(b), normal));
    auto scan = [&](bool find) {
      const T floor = m4 - area_tol;
      for (int j = 0; j < n; ++j) {
        if (j == d) continue;
        for (int k = j + 1; k < n; ++k) {
          if (k == d) continue;
          for (int l = k + 1; l < n; ++l) {
            if (l == d) continue;
            const T h =
                T(T(TD(j, k) + TD(j, l) + TD(k, l) + abs_of(orient(P(j), P(k), P(l), normal))) / T(2));
            if (!find) {
              if (!have4 || h > m4) m4 = h, have4 = true;
            } else if (!(h < floor)) {
              best4 = {j, k, l};
              return;
            }
          }
        }
      }
    };
    scan(false);
    scan(true);
  }

  // 4. M3, for the degenerate cases.
  T m3(0);
  std::array<int, 2> best3{-1, -1};
  for (int pass = 0; pass < 2 && best3[0] < 0; ++pass) {
    const T floor = m3 - area_tol;
    for (int a = 0; a < n && best3[0] < 0; ++a) {
      if (a == d) continue;
      for (int b = a + 1; b < n; ++b) {
        if (b == d) continue;
        const T h = abs_of(orient(P(d), P(a), P(b), normal));
        if (pass == 0) {
          if (h > m3) m3 = h;
        } else if (!(h < floor)) {
          best3 = {a, b};
          break;
        }
      }
    }
  }
  if (m4 > m3 + area_tol) return emit({best4[0], best4[1], best4[2]});
  if (m3 > area_tol) return emit({best3[0], best3[1]});
  // All points on a line through d (within the tolerance): its extremes.
  auto farthest = [&](int from, T& best) {
    best = T(0);
    for (int i = 0; i < n; ++i) {
      const T s = squared_norm(Vec3<T>(P(i) - P(from)));
      if (s > best) best = s;
    }
    for (int i = 0; i < n; ++i)
      if (!(squared_norm(Vec3<T>(P(i) - P(from))) < best - area_tol)) return i;
    return -1;
  };
  T r1;
  const int p1 = farthest(d, r1);
  if (!(r1 > area_tol)) return;  // every point at d
  T r2;
  const int p2 = farthest(p1, r2);
  // d is an end of the line when it is (nearly) as far from p1 as p2 is.
  if (!(squared_norm(Vec3<T>(P(d) - P(p1))) < r2 - area_tol) || p2 == d) return emit({p1});
  return emit({p1, p2});
}

}  // namespace sepax
