// sepax/manifold_compare.hpp
//
// compare_manifolds: how far a float manifold is from the exact one computed
// on the same inputs (the exact image of the float shapes), for the fuzzer and
// audits.  Exact values are converted to double for the error measures only
// (reporting), never for a decision of the manifold itself.
#pragma once

#include <algorithm>
#include <cmath>

#include "contact_manifold.hpp"

namespace sepax {

struct ManifoldDifference {
  bool same_kind = false;
  bool same_feature = false;       // the SAT feature
  bool same_faces = false;         // reference shape, reference and incident face
  bool same_count = false;         // number of points
  bool same_ids = false;           // feature ids, point by point (implies same_count)
  bool same_deepest = false;       // the deepest point's id
  double deepest_depth_error = 0;  // |depth difference| of the deepest points
  double max_depth_error = 0;      // over points with the same index (when same_count)
  double max_position_error = 0;   // Euclidean, over points with the same index (when same_count)

  /// Everything combinatorial agrees.
  bool identical() const { return same_kind && same_feature && same_faces && same_ids; }
};

namespace detail {
template <Number T>
int deepest_index(const ContactManifold<T>& m) {
  int best = -1;
  for (int i = 0; i < m.size(); ++i) {
    if (best < 0 || compare(m.points[static_cast<std::size_t>(i)].separation,
                            m.points[static_cast<std::size_t>(best)].separation) < 0)
      best = i;
  }
  return best;
}
}  // namespace detail

/// Compare manifold `x` (e.g. float) with `y` (e.g. exact) of the same pair.
template <Number X, Number Y>
ManifoldDifference compare_manifolds(const ContactManifold<X>& x, const ContactManifold<Y>& y) {
  ManifoldDifference d;
  d.same_kind = x.kind == y.kind;
  d.same_feature = x.feature == y.feature;
  d.same_faces = x.reference_shape == y.reference_shape && x.reference_face == y.reference_face &&
                 x.incident_face == y.incident_face;
  d.same_count = x.size() == y.size();
  d.same_ids = d.same_count;
  for (int i = 0; d.same_count && i < x.size(); ++i) {
    const auto& p = x.points[static_cast<std::size_t>(i)];
    const auto& q = y.points[static_cast<std::size_t>(i)];
    d.same_ids = d.same_ids && p.id == q.id;
    d.max_depth_error = std::max(d.max_depth_error, std::abs(p.depth() - q.depth()));
    d.max_position_error =
        std::max(d.max_position_error, (vec_to_double(p.position) - vec_to_double(q.position)).norm());
  }
  const int ix = detail::deepest_index(x), iy = detail::deepest_index(y);
  if (ix >= 0 && iy >= 0) {
    d.same_deepest = x.points[static_cast<std::size_t>(ix)].id == y.points[static_cast<std::size_t>(iy)].id;
    d.deepest_depth_error = std::abs(x.points[static_cast<std::size_t>(ix)].depth() -
                                     y.points[static_cast<std::size_t>(iy)].depth());
  } else {
    d.same_deepest = ix < 0 && iy < 0;
  }
  return d;
}

}  // namespace sepax
