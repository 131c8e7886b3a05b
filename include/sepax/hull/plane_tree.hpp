// sepax/hull/plane_tree.hpp
//
// Float T: the largest height of one point above many planes without a pass over every plane, with the
// same value as that pass (VertexTree's dual: the planes are the items, the point is the query):
//   1. PlaneTree: the planes (n, off) in a binary tree of boxes in (n_0, n_1, n_2, off) (median splits on
//      the widest of the four);
//   2. max_height: the largest computed height T(dot(n, x) - off) over the planes, a box skipped when its
//      bound proves every height in it at most the largest found so far (the bound is derived there);
//   3. first_above: the first plane (in index order) whose computed height exceeds a limit;
//   4. first_above_or_highest: that plane, or when there is none the first plane of the largest height.
// Used by the measure of points against a built hull (repair.hpp, outside_points), the quickhull's sweep
// of kept points and its re-assignment over every live face (quickhull.hpp, sweep, assign_live).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../number_traits.hpp"
#include "../vec3.hpp"
#include "box_tree.hpp"
#include "index.hpp"

namespace sepax::hull::detail {

/// Planes from which the builder's searches go through a PlaneTree (below, a pass over the planes is cheaper
/// than the tree's boxes; either gives the same result).
inline constexpr int kPlaneTreeFaces = 512;
/// Points from which the sweep's searches go through a PlaneTree (fewer: the tree costs more to build than
/// the passes it saves).
inline constexpr double kPlaneTreePoints = 64;
/// Passes over the live faces that the forced quickhull steps' re-assignments may add up to before they
/// build their tree of the live faces anew (quickhull.hpp, index_live_faces): about what a build costs
/// (median splits of about 10^5 planes take some 450 instructions a plane, a face test some 25, so one
/// build is about 18 passes), in passes; either way the same faces are found.
inline constexpr double kPlaneTreeBuildPasses = 16;

/// Float T: planes in a tree of bounding boxes of their coefficients, for the largest height of a point.
template <Number T>
class PlaneTree {
  static_assert(std::is_floating_point_v<T>);

 public:
  /// The tree of planes plane(0) .. plane(count - 1).
  template <class PlaneOf>
  PlaneTree(int count, PlaneOf&& plane) : tree_(items(count, plane)) {}

  /// The largest computed height T(dot(n_f, x) - off_f) over the planes: the value a pass over every
  /// plane finds, each plane handed over computed by height(f) (which must compute exactly that
  /// expression).  -infinity for no planes.
  ///
  /// Bound (VertexTree::may_exceed's with the roles of point and plane exchanged).  For a box
  /// [lo, hi] of (n, off) let n*_i = hi_i where x_i > 0, else lo_i, and off* = lo_off: M = n*.x - off* is the
  /// exact maximum of n.x - off over the box; with a_i = max(|lo_i|, |hi_i|) (a_3 for off),
  /// S = sum |x_i| a_i + a_3 >= sum |n_i| |x_i| + |off| for every plane of the box.  The computed height of a
  /// plane is a 4-term dot product: at most n.x - off + gamma_4(T) S + 4 eta(T) <= M + gamma_4(T) S +
  /// 4 eta(T); fl(M) in double >= M - gamma_4(double) S - 4 eta(double).  So every height in the box is at
  /// most lim when fl(M) + (gamma_4(T) + gamma_4(double)) S + 8 eta(T) <= lim, tested with twice that
  /// coefficient (covering the rounding of S and of the final sum, as in VertexTree) and 64 min(T)
  /// (>= 8 eta(T)).  Non-finite values fail the test (the box is then opened).  S is taken once per point,
  /// on the root box (root_slack): every box lies inside it, so its a_i bound every box's.
  template <class Height>
  T max_height(const Vec3<T>& x, Height&& height) const {
    T best = -std::numeric_limits<T>::infinity();
    best_first(
        x, [&](double u) { return u <= static_cast<double>(best); },
        [&](int f) { best = std::max(best, height(f)); });
    return best;
  }

  /// The smallest plane index f whose computed height T(dot(n_f, x) - off_f) exceeds limit, or -1: the
  /// first plane a pass in index order finds above limit.  A box is skipped when max_height's bound proves
  /// every height in it at most limit; every other plane's height(f) (the same expression) is computed.
  template <class Height>
  int first_above(const Vec3<T>& x, T limit, Height&& height) const {
    int first = -1;
    const std::array<double, 3> q{static_cast<double>(x[0]), static_cast<double>(x[1]),
                                  static_cast<double>(x[2])};
    const double lim = static_cast<double>(limit);
    const double slack = root_slack(q);
    tree_.walk(
        true, [&](const Node& nd) { return upper(nd, q, slack) <= lim; },
        [&](const Node& nd) {
          for (int i = nd.begin; i < nd.end; ++i) {
            const int f = tree_.items()[as_index(i)].id;
            if ((first < 0 || f < first) && height(f) > limit) first = f;
          }
        });
    return first;
  }

  /// first_above_or_highest's answer: the face, its computed height, and whether that is above the limit.
  struct Highest {
    int face = -1;
    T height = -std::numeric_limits<T>::infinity();
    bool above = false;
  };

  /// In one walk: the smallest plane index whose computed height exceeds limit (above), else the largest
  /// computed height and the smallest index at that height (face -1 for no planes).  A box is skipped when
  /// max_height's bound u proves every height in it at most limit (u <= limit) and, until a plane above
  /// limit is found, below the highest so far (u < highest: no larger height and no tie with a smaller
  /// index); every other plane's height(f) (the same expression) is computed.
  template <class Height>
  Highest first_above_or_highest(const Vec3<T>& x, T limit, Height&& height) const {
    Highest r;
    const double lim = static_cast<double>(limit);
    best_first(
        x, [&](double u) { return u <= lim && (r.above || u < static_cast<double>(r.height)); },
        [&](int f) {
          const T h = height(f);
          if (h > limit) {
            if (!r.above || f < r.face) r = Highest{f, h, true};
          } else if (!r.above && (h > r.height || (h == r.height && f < r.face))) {
            r = Highest{f, h, false};
          }
        });
    return r;
  }

 private:
  using Node = typename BoxTree<4>::Node;
  static constexpr double kSlack = DotBound<T>::kSlack;
  static constexpr double kTiny = DotBound<T>::kTiny;

  /// The planes as tree items (n_0, n_1, n_2, off; T widens exactly to double).
  template <class PlaneOf>
  static std::vector<typename BoxTree<4>::Item> items(int count, PlaneOf& plane) {
    std::vector<typename BoxTree<4>::Item> out;
    out.reserve(as_index(count));
    for (int f = 0; f < count; ++f) {
      const Plane<T>& pl = plane(f);
      out.push_back({{static_cast<double>(pl.normal[0]), static_cast<double>(pl.normal[1]),
                      static_cast<double>(pl.normal[2]), static_cast<double>(pl.offset)},
                     f});
    }
    return out;
  }

  /// kSlack S + kTiny at x, S taken on the root box: at least the slack of every box of the tree
  /// (max_height's bound); 0 for an empty tree (no box is tested).
  double root_slack(const std::array<double, 3>& x) const {
    if (tree_.nodes().empty()) return 0;
    const Node& root = tree_.nodes()[0];
    double s = std::abs(x[0]) * root.mag[0];
    s = s + std::abs(x[1]) * root.mag[1];
    s = s + std::abs(x[2]) * root.mag[2];
    s = s + root.mag[3];
    return kSlack * s + kTiny;
  }

  /// The best-first walk of max_height and first_above_or_highest at x (BoxTree::best_first on the bound
  /// u of upper): a box is skipped when skip(u), else leaf(f) runs for each plane f of a leaf box.
  template <class Skip, class Leaf>
  void best_first(const Vec3<T>& x, Skip&& skip, Leaf&& leaf) const {
    const std::array<double, 3> q{static_cast<double>(x[0]), static_cast<double>(x[1]),
                                  static_cast<double>(x[2])};
    const double slack = root_slack(q);
    tree_.best_first([&](const Node& nd) { return upper(nd, q, slack); }, skip,
                     [&](const Node& nd) {
                       for (int i = nd.begin; i < nd.end; ++i) leaf(tree_.items()[as_index(i)].id);
                     });
  }

  /// A bound u with: every computed height of nd's planes at x is at most lim whenever u <= lim
  /// (max_height's bound, with slack from root_slack; NaN when a value is not finite, so that no comparison
  /// skips the box).
  static double upper(const Node& nd, const std::array<double, 3>& x, double slack) {
    double m = (x[0] > 0 ? nd.hi[0] : nd.lo[0]) * x[0];
    m = m + (x[1] > 0 ? nd.hi[1] : nd.lo[1]) * x[1];
    m = m + (x[2] > 0 ? nd.hi[2] : nd.lo[2]) * x[2];
    m = m - nd.lo[3];
    const double u = m + slack;
    return std::isfinite(u) ? u : std::numeric_limits<double>::quiet_NaN();
  }

  BoxTree<4> tree_;
};

}  // namespace sepax::hull::detail
