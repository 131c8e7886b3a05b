// sepax/hull/box_tree.hpp
//
// Float T: the tree of boxes under VertexTree (vertices, D = 3) and PlaneTree (planes as (n, off), D = 4):
//   1. BoxTree<D>: items of D coordinates (exactly as doubles) in a binary tree of bounding boxes, median
//      splits on the widest coordinate of the node's cell down to leaves of kLeaf items, then each box
//      made tight from its leaves up;
//   2. walk (depth first) and best_first (the child with the larger bound first): the trees' searches;
//   3. DotBound<T>: the slack of the trees' box tests, for computed 4-term dot products in T bounded in
//      double (derived in VertexTree::may_exceed).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../number_traits.hpp"
#include "index.hpp"

namespace sepax::hull::detail {

/// The rounding slack of a box test on a computed 4-term dot product in T, bounded in double:
/// kSlack = 2 (gamma_4(T) + gamma_4(double)) relative to the sum of the terms' magnitudes, kTiny = 64 min(T)
/// (>= 8 eta(T), eta half the smallest subnormal) absolute (VertexTree::may_exceed derives them).
template <class T>
struct DotBound {
  static constexpr double kSlack = 2 * (rounding_gamma(4, number_traits<T>::unit_roundoff) +
                                        rounding_gamma(4, number_traits<double>::unit_roundoff));
  static constexpr double kTiny = 64 * static_cast<double>(std::numeric_limits<T>::min());
};

/// Items (an id and D coordinates) in a binary tree of bounding boxes.
template <int D>
class BoxTree {
 public:
  struct Item {
    std::array<double, D> c;
    int id;
  };
  struct Node {
    double lo[D], hi[D], mag[D];  ///< box; mag_i = max(|lo_i|, |hi_i|)
    int begin = 0, end = 0;       ///< items()[begin, end)
    int left = -1;                ///< children left, left + 1 (-1: a leaf)
  };

  BoxTree() = default;
  explicit BoxTree(std::vector<Item> items) : items_(std::move(items)) {
    if (items_.empty()) return;
    nodes_.push_back(fill(0, static_cast<int>(items_.size())));
    expand(0);
    tighten(0);
  }

  const std::vector<Item>& items() const { return items_; }
  const std::vector<Node>& nodes() const { return nodes_; }

  /// Depth first from the root: a node for which skip(node) holds is passed over with its subtree; every
  /// other leaf is handed to leaf(node); children are entered left first when left_first, else right first.
  template <class Skip, class Leaf>
  void walk(bool left_first, Skip&& skip, Leaf&& leaf) const {
    if (nodes_.empty()) return;
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& nd = nodes_[as_index(stack[--top])];
      if (skip(nd)) continue;
      if (nd.left < 0) {
        leaf(nd);
      } else {
        stack[top++] = left_first ? nd.left + 1 : nd.left;
        stack[top++] = left_first ? nd.left : nd.left + 1;
      }
    }
  }

  /// Best first from the root: each node's bound(node) is taken when its parent is opened, and the child
  /// with the larger bound is entered first (the left one on a tie), so that a search for a largest value
  /// finds a high one early; a node for which skip(its bound) holds, tested when it is entered, is passed
  /// over with its subtree; every other leaf is handed to leaf(node).
  template <class Bound, class Skip, class Leaf>
  void best_first(Bound&& bound, Skip&& skip, Leaf&& leaf) const {
    if (nodes_.empty()) return;
    int stack[64];
    double bounds[64];
    int top = 0;
    stack[top] = 0;
    bounds[top++] = bound(nodes_[0]);
    while (top > 0) {
      --top;
      const Node& nd = nodes_[as_index(stack[top])];
      if (skip(bounds[top])) continue;
      if (nd.left < 0) {
        leaf(nd);
      } else {
        const double bl = bound(nodes_[as_index(nd.left)]);
        const double br = bound(nodes_[as_index(nd.left + 1)]);
        const bool left_first = !(br > bl);
        stack[top] = left_first ? nd.left + 1 : nd.left;
        bounds[top++] = left_first ? br : bl;
        stack[top] = left_first ? nd.left : nd.left + 1;
        bounds[top++] = left_first ? bl : br;
      }
    }
  }

 private:
  static constexpr int kLeaf = 8;  ///< items per leaf at most

  Node fill(int b, int e) const {
    Node nd;
    nd.begin = b;
    nd.end = e;
    for (int c = 0; c < D; ++c) nd.lo[c] = nd.hi[c] = items_[as_index(b)].c[as_index(c)];
    for (int i = b + 1; i < e; ++i)
      for (int c = 0; c < D; ++c) {
        nd.lo[c] = std::min(nd.lo[c], items_[as_index(i)].c[as_index(c)]);
        nd.hi[c] = std::max(nd.hi[c], items_[as_index(i)].c[as_index(c)]);
      }
    for (int c = 0; c < D; ++c) nd.mag[c] = std::max(std::abs(nd.lo[c]), std::abs(nd.hi[c]));
    return nd;
  }

  /// Median split of node id on its cell's widest coordinate, recursively down to leaves of kLeaf items: a
  /// depth of at most log2(n / kLeaf) + 1, so a traversal's stack (depth + 1 entries) fits 64 for any int
  /// count.  A child's cell is its parent's cut at the median item's coordinate (its items lie in it); the
  /// boxes are made tight afterwards (tighten), so the splits read no item but through nth_element.
  void expand(int id) {
    const Node nd = nodes_[as_index(id)];
    if (nd.end - nd.begin <= kLeaf) return;
    int axis = 0;
    for (int c = 1; c < D; ++c)
      if (nd.hi[c] - nd.lo[c] > nd.hi[axis] - nd.lo[axis]) axis = c;
    const int mid = nd.begin + (nd.end - nd.begin) / 2;
    std::nth_element(items_.begin() + nd.begin, items_.begin() + mid, items_.begin() + nd.end,
                     [&](const Item& p, const Item& q) { return p.c[as_index(axis)] < q.c[as_index(axis)]; });
    const double cut = items_[as_index(mid)].c[as_index(axis)];
    Node l = nd, r = nd;
    l.end = r.begin = mid;
    l.left = r.left = -1;
    l.hi[axis] = cut;
    r.lo[axis] = cut;
    const int left = static_cast<int>(nodes_.size());
    nodes_.push_back(l);
    nodes_.push_back(r);
    nodes_[as_index(id)].left = left;
    expand(left);
    expand(left + 1);
  }

  /// The tight box of node id and of its subtree: a leaf's from its items (fill), an inner node's the union
  /// of its children's (the box a fill over its items gives: minima and maxima are exact).  The nodes
  /// are not moved while it runs (nodes_ does not grow), so the references stay valid.
  void tighten(int id) {
    Node& nd = nodes_[as_index(id)];
    if (nd.left < 0) {
      const Node f = fill(nd.begin, nd.end);
      for (int c = 0; c < D; ++c) nd.lo[c] = f.lo[c], nd.hi[c] = f.hi[c], nd.mag[c] = f.mag[c];
      return;
    }
    tighten(nd.left);
    tighten(nd.left + 1);
    const Node& a = nodes_[as_index(nd.left)];
    const Node& b = nodes_[as_index(nd.left + 1)];
    for (int c = 0; c < D; ++c) {
      nd.lo[c] = std::min(a.lo[c], b.lo[c]);
      nd.hi[c] = std::max(a.hi[c], b.hi[c]);
      nd.mag[c] = std::max(std::abs(nd.lo[c]), std::abs(nd.hi[c]));
    }
  }

  std::vector<Item> items_;
  std::vector<Node> nodes_;
};

}  // namespace sepax::hull::detail
