// sepax/hull/vertex_tree.hpp
//
// Float T: "every vertex at most `limit` above this plane" without a pass over every vertex, with the same
// decision as that pass, vertex for vertex:
//   1. VertexTree: the vertices in a binary tree of boxes (median splits on the widest axis).
//   2. may_exceed: per plane, a subtree is skipped when its box proves that the computed height
//      T(dot(n, x) - off) of each of its vertices is at most the limit (the bound is derived there; its
//      rounding slack is computed once per plane, on the root box);
//      every other vertex is handed to the caller, which computes its height as before.
//   3. max_height: the largest computed height, with the largest found so far as the limit (best first).
// Used by the pre-check (precheck.hpp), the hull's validation (to_polyhedron.hpp) and the slab
// fallback's widths (fallbacks.hpp, thin_plane).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../number_traits.hpp"
#include "../vec3.hpp"
#include "box_tree.hpp"
#include "index.hpp"

namespace sepax::hull::detail {

/// Float T: vertices in a tree of bounding boxes, for the vertices a plane may have above a height limit.
template <Number T>
class VertexTree {
  static_assert(std::is_floating_point_v<T>);

 public:
  /// The tree of the vertices ids, at point(id).
  template <class Point>
  VertexTree(const std::vector<int>& ids, Point&& point) : tree_(items(ids, point)) {}

  /// Calls visit(v) for every vertex v whose computed height T(dot(n, x_v) - off) may exceed limit; every
  /// vertex not visited has a computed height at most limit (with or without FMA contraction).
  ///
  /// Bound.  For a box [lo, hi] let x* be its corner with x*_i = hi_i where n_i > 0, else lo_i, so that
  /// M = n.x* - off is the exact maximum of n.x - off over the box, and a_i = max(|lo_i|, |hi_i|),
  /// S = sum |n_i| a_i + |off| >= sum |n_i| |x_i| + |off| for every x in the box.  The computed height of a
  /// vertex x in T is a 4-term dot product (n.x - 1.off): at most 4 roundings on each term's path, fused or
  /// not, so it is at most n.x - off + gamma_4(T) S + 4 eta(T) <= M + gamma_4(T) S + 4 eta(T) (eta: half
  /// the smallest subnormal, the absolute error of an underflowing operation).  M computed in double is
  /// the same kind of dot product: fl(M) >= M - gamma_4(double) S - 4 eta(double).  So every vertex of the
  /// box is at most limit when fl(M) + (gamma_4(T) + gamma_4(double)) S + 8 eta(T) <= limit.  at_most
  /// tests it with k = 2 (gamma_4(T) + gamma_4(double)) and 64 min(T) (>= 8 eta(T) by far): the factor 2
  /// covers the rounding of S (4 additions, relative gamma_4(double)), of k S and of the final sum (|fl(M)|
  /// <= S (1 + gamma_4), relative u(double) each), and the absolute term any underflow in them.  Non-finite
  /// values fail the test (the box is then opened).
  ///
  /// One S per plane: every box of the tree lies inside the root box, so its a_i are at most the root's
  /// and the root's S (computed once, root_slack()) is an upper bound of every box's S; with it in place of the
  /// box's own, each test above still holds (only looser), and the rounding of the one S is covered by the
  /// same factor 2.
  template <class F>
  void may_exceed(const Plane<T>& pl, T limit, F&& visit) const {
    const double n0 = static_cast<double>(pl.normal[0]), n1 = static_cast<double>(pl.normal[1]),
                 n2 = static_cast<double>(pl.normal[2]), off = static_cast<double>(pl.offset);
    const double lim = static_cast<double>(limit);
    const double slack = root_slack(n0, n1, n2, off);
    tree_.walk(
        false, [&](const Node& nd) { return at_most(nd, n0, n1, n2, off, slack, lim); },
        [&](const Node& nd) {
          for (int i = nd.begin; i < nd.end; ++i) visit(tree_.items()[as_index(i)].id);
        });
  }

  /// The largest computed height T(dot(n, x) - off) over the vertices: the value a pass over every vertex
  /// finds, each vertex handed over computed by height(id) (which must compute exactly that expression).
  /// A box is skipped when may_exceed's bound proves its vertices at most the largest height found so far
  /// (none of them can raise it).  -infinity for an empty tree.
  template <class Height>
  T max_height(const Plane<T>& pl, Height&& height) const {
    T best = -std::numeric_limits<T>::infinity();
    const double n0 = static_cast<double>(pl.normal[0]), n1 = static_cast<double>(pl.normal[1]),
                 n2 = static_cast<double>(pl.normal[2]), off = static_cast<double>(pl.offset);
    const double slack = root_slack(n0, n1, n2, off);
    tree_.best_first([&](const Node& nd) { return upper(nd, n0, n1, n2, off, slack); },
                     [&](double u) { return u <= static_cast<double>(best); },
                     [&](const Node& nd) {
                       for (int i = nd.begin; i < nd.end; ++i)
                         best = std::max(best, height(tree_.items()[as_index(i)].id));
                     });
    return best;
  }

  /// Whether every vertex x with |x_i| <= mag_i whose computed height T(dot(n, x) - off) was found at most
  /// below, evaluated anywhere (with or without FMA contraction), also has a computed height at most limit.
  ///
  /// Bound.  Each evaluation is within gamma_4(T) S + 4 eta(T) of the exact n.x - off (may_exceed's bound,
  /// S = sum |n_i| mag_i + |off|), so two evaluations differ by at most 2 gamma_4(T) S + 8 eta(T).  The
  /// margin is computed in double as kSlack S + kTiny (kSlack = 2 (gamma_4(T) + gamma_4(double)) >= the
  /// 2 gamma_4(T) needed, with the factor of may_exceed covering the rounding of S; kTiny >= 8 eta(T)).
  /// The test fl(below + margin) <= fl(limit (1 - 4u)) (u of double) implies below + margin < limit: the
  /// sum of two non-negative doubles is rounded down by at most a factor (1 - u).  Non-finite values fail.
  static bool height_holds(const Plane<T>& pl, const std::array<double, 3>& mag, T below, T limit) {
    const double s = std::abs(static_cast<double>(pl.normal[0])) * mag[0] +
                     std::abs(static_cast<double>(pl.normal[1])) * mag[1] +
                     std::abs(static_cast<double>(pl.normal[2])) * mag[2] +
                     std::abs(static_cast<double>(pl.offset));
    const double b = static_cast<double>(below);
    if (!(b >= 0)) return false;
    constexpr double kShrink = 1 - 4 * number_traits<double>::unit_roundoff;
    return b + (kSlack * s + kTiny) <= static_cast<double>(limit) * kShrink;
  }

 private:
  using Node = typename BoxTree<3>::Node;
  static constexpr double kSlack = DotBound<T>::kSlack;
  static constexpr double kTiny = DotBound<T>::kTiny;

  /// The vertices as tree items (T widens exactly to double).
  template <class Point>
  static std::vector<typename BoxTree<3>::Item> items(const std::vector<int>& ids, Point& point) {
    std::vector<typename BoxTree<3>::Item> out;
    out.reserve(ids.size());
    for (int v : ids) {
      const Vec3<T>& x = point(v);
      out.push_back({{static_cast<double>(x[0]), static_cast<double>(x[1]), static_cast<double>(x[2])}, v});
    }
    return out;
  }

  /// kSlack S + kTiny for the plane (n, off), S taken on the root box: at least the slack of every box of
  /// the tree (may_exceed's bound).  0 for an empty tree (no box is tested).
  double root_slack(double n0, double n1, double n2, double off) const {
    if (tree_.nodes().empty()) return 0;
    const Node& root = tree_.nodes()[0];
    double s = std::abs(n0) * root.mag[0];
    s = s + std::abs(n1) * root.mag[1];
    s = s + std::abs(n2) * root.mag[2];
    s = s + std::abs(off);
    return kSlack * s + kTiny;
  }

  /// Whether the box of nd proves every computed height of its vertices at most lim (may_exceed's bound),
  /// with slack from root_slack().
  static bool at_most(const Node& nd, double n0, double n1, double n2, double off, double slack, double lim) {
    return upper(nd, n0, n1, n2, off, slack) <= lim;
  }

  /// may_exceed's bound of nd's box: every computed height of its vertices is at most lim when the value
  /// is at most lim (slack from root_slack(); a non-finite value skips no box but an infinite limit's).
  static double upper(const Node& nd, double n0, double n1, double n2, double off, double slack) {
    const double x0 = n0 > 0 ? nd.hi[0] : nd.lo[0], x1 = n1 > 0 ? nd.hi[1] : nd.lo[1],
                 x2 = n2 > 0 ? nd.hi[2] : nd.lo[2];
    double m = n0 * x0;
    m = m + n1 * x1;
    m = m + n2 * x2;
    m = m - off;
    return m + slack;
  }

  BoxTree<3> tree_;
};

}  // namespace sepax::hull::detail
