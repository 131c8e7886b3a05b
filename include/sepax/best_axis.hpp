// sepax/best_axis.hpp
//
// BestAxis: keeps the candidate axis of maximum separation while a SAT scans
// candidates, applying the tie-break of feature.hpp.  Because the rule is
// "greater separation, or equal separation and an earlier feature", the result
// does not depend on the order in which candidates are visited: brute force,
// Gauss map and traversal, which visit axes in different orders, agree.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "sat_cache.hpp"
#include "sat_kernel.hpp"

namespace sepax::sat::detail {

template <SatKernel K>
class BestAxis {
 public:
  using T = typename K::FT;

  /// Offer a candidate; returns true when it became the best.  below, if
  /// given, is set to whether the candidate is exactly below the best it met
  /// (false when there was none).
  bool consider(const K& k, const Separation<T>& s, const Feature& f, bool* below = nullptr) {
    if constexpr (kBounded) {
      // The best's error bound is kept: one bound per candidate (the one its
      // kernel call has just computed, e.g. the cached edge axis), not the
      // best's recomputed on every comparison.  compare_bounded is compare
      // with both bounds given: the same filter, the same exact fallback.
      const double e = k.error_bound(f);
      if (!has_) {
        set(s, f);
        err_ = e;
        return true;
      }
      const int c = k.compare_bounded(s, f, e, sep_, feature_, err_);
      if (below) *below = c < 0;
      if (c > 0 || (c == 0 && precedes(f, feature_))) {
        set(s, f);
        err_ = e;
        return true;
      }
      return false;
    } else {
      if (!has_) {
        set(s, f);
        return true;
      }
      const int c = k.compare(s, f, sep_, feature_);
      if (below) *below = c < 0;
      if (c > 0 || (c == 0 && precedes(f, feature_))) {
        set(s, f);
        return true;
      }
      return false;
    }
  }

  /// HasFaceEstimate kernels: true when a face axis whose estimate is e
  /// (sat_kernel.hpp, FaceEstimate) is certainly not the best, whatever its
  /// support vertex: its exact separation is strictly below the best's.  The
  /// caller then skips the face (no certified query, no consider, no
  /// early-out check), which is what exact arithmetic does with it:
  ///  * Bounds.  |e.separation - h_f| <= e.error, h_f the exact separation of
  ///    the face (the height of the exactly deepest vertex: the kernel's
  ///    contract; for RobustKernel the min of the float heights is within
  ///    E_face of h_f because every vertex's float height is within E_face of
  ///    its exact height and rounding is monotone).  |sep_ - h_b| <= err_,
  ///    h_b the best's exact separation: err_ = error_bound(feature_), the
  ///    bound compare_bounded uses for it (it holds for snapped values too).
  ///  * The test.  d = x - sep_ in double (two exact conversions and one
  ///    subtraction: nothing an FMA could contract) below -compare_width(ex,
  ///    err_) is compare_bounded's filter answering -1: by the kernel's
  ///    contract for compare_width (its (1+1e-6) margin covers the roundings
  ///    of d and of the width; an overflow of d to -inf is a difference
  ///    beyond any finite width), x - sep_ < -(ex + err_), so h_f <= x + ex <
  ///    sep_ - err_ <= h_b.  NaN compares false: no skip.
  ///  * Why the unknown vertex cannot matter.  The exact run offers the face
  ///    with h_f < h_b: compare is -1 for every support vertex (the feature
  ///    tie-break applies only to equal separations), so the best does not
  ///    change.  Early out: every candidate offered so far had exact sign <=
  ///    0 (otherwise the scan had returned), the best too, so h_f < h_b <= 0
  ///    and the face's sign is -1: no early out either.  Both runs continue
  ///    with the same best, and the robust kernel's later decisions are the
  ///    exact ones.  The first face (no best yet) is never skipped.
  bool certainly_below(const K& k, const FaceEstimate<T>& e) const requires HasFaceEstimate<K> {
    static_assert(kBounded, "a face estimate is compared with the best's error bound");
    return has_ && static_cast<double>(e.separation.num) - static_cast<double>(sep_.num) <
                       -k.compare_width(e.error, err_);
  }

  /// HasEdgePairBelow kernels: true when the Minkowski edge pair (ea, eb) is
  /// certainly not the best, its exact separation strictly below the best's
  /// (k.edge_pair_below with the best's value and kept error bound).  The
  /// caller then skips it (no edges_parallel, edge_separation, consider or
  /// early-out check: the pair is not parallel and its separation is
  /// negative), which is what exact arithmetic does with it.
  bool pair_certainly_below(const K& k, int ea, int eb) const requires HasEdgePairBelow<K> {
    static_assert(kBounded, "the pair is compared with the best's error bound");
    return has_ && k.edge_pair_below(ea, eb, sep_.num, err_);
  }

  bool has() const { return has_; }
  const Separation<T>& separation() const { return sep_; }
  const Feature& feature() const { return feature_; }

  /// The finished result.
  SatResult<T> result(K& k, const SatStats& stats, bool early_out) const {
    SatResult<T> r;
    r.feature = feature_;
    r.separation = sep_;
    r.overlap = k.sign(sep_, feature_) <= 0;
    r.axis = k.axis(feature_);
    r.early_out = early_out;
    r.stats = stats;
    r.stats.exact_fallbacks = k.exact_fallbacks();
    return r;
  }

 private:
  void set(const Separation<T>& s, const Feature& f) {
    sep_ = s;
    feature_ = f;
    has_ = true;
  }

  // Kernels that expose their value error bounds (RobustKernel).
  static constexpr bool kBounded = HasBoundedCompare<K>;

  bool has_ = false;
  Separation<T> sep_;
  Feature feature_;
  double err_ = 0;  // kBounded: k.error_bound(feature_)
};

/// Offers the axes i = 0 .. n-1 of one kind: query(i) is a FaceQuery (a
/// separation and the other shape's support vertex), feature(i, support)
/// names it; each is counted in `counter`.  With an `estimate` (not
/// nullptr: estimate(i) is a FaceEstimate, see HasFaceEstimate), query(i) is
/// asked only when the estimate is not certainly below the best
/// (BestAxis::certainly_below); a skipped axis is still counted.  Returns
/// true when early_out is set and a separating axis was found.
template <SatKernel K, class Query, class MakeFeature, class Estimate = std::nullptr_t>
bool scan_queries(K& k, BestAxis<K>& best, std::int64_t& counter, int n, const SatOptions& opt, Query&& query,
                  MakeFeature&& feature, Estimate&& estimate = nullptr) {
  for (int i = 0; i < n; ++i) {
    ++counter;
    if constexpr (!std::is_null_pointer_v<std::remove_cvref_t<Estimate>>) {
      if (best.certainly_below(k, estimate(i))) continue;
    }
    const auto q = query(i);
    const Feature feat = feature(i, q.support_vertex);
    best.consider(k, q.separation, feat);
    if (stops_early(k, q.separation, feat, opt)) return true;
  }
  return false;
}

/// The face axes of A then of B: shared by every SAT.  HasFaceEstimate
/// kernels certify the support vertex only of the faces whose estimate is
/// not certainly below the best so far (scan_queries).  Returns true when
/// early_out is set and a separating face axis was found.
template <SatKernel K>
bool scan_face_axes(K& k, BestAxis<K>& best, SatStats& stats, const SatOptions& opt) {
  // nullptr (every face certified) unless the kernel has the estimates
  const auto estimate_a = [&] {
    if constexpr (HasFaceEstimate<K>)
      return [&](int f) { return k.face_estimate_a(f); };
    else
      return nullptr;
  }();
  const auto estimate_b = [&] {
    if constexpr (HasFaceEstimate<K>)
      return [&](int f) { return k.face_estimate_b(f); };
    else
      return nullptr;
  }();
  return scan_queries(
             k, best, stats.face_axes, k.a().face_count(), opt, [&](int f) { return k.face_query_a(f); },
             [](int f, int v) { return Feature::face_a(f, v); }, estimate_a) ||
         scan_queries(
             k, best, stats.face_axes, k.b().face_count(), opt, [&](int f) { return k.face_query_b(f); },
             [](int f, int v) { return Feature::face_b(v, f); }, estimate_b);
}

/// Warm start (SatCache): offer the seed feature, re-evaluated at this pose
/// by `reevaluate` (sat_cache.hpp), as the first candidate.  It is one of the
/// SAT's own candidates with the value the SAT computes for it, so the result
/// does not change (the best is order-independent), only the pruning starts
/// from it.  edge_pairs: whether an edge-pair seed is a candidate of this
/// SAT in the O(1) form (false for the brute force, whose edge values use
/// the projection form).  Returns true when it stops the query early.
template <SatKernel K>
bool seed_best(K& k, BestAxis<K>& best, SatStats& stats, const SatOptions& opt, const Feature* seed,
               bool edge_pairs) {
  if (!seed || (seed->type == FeatureType::EdgePair && !edge_pairs)) return false;
  const auto ev = reevaluate(k, *seed);
  if (!ev) return false;
  const FeatureType ty = ev->first.type;
  ++(ty == FeatureType::EdgePair                            ? stats.edge_pairs
     : ty == FeatureType::FaceA || ty == FeatureType::FaceB ? stats.face_axes
                                                            : stats.side_axes);
  best.consider(k, ev->second, ev->first);
  return stops_early(k, ev->second, ev->first, opt);
}

/// The side axes (feature.hpp), shared by every SAT after its other axes,
/// when A and B are both flat (double-sided polygons).  A polygon's sides are
/// faces of zero thickness with normals u = (head - tail) x n: in-plane,
/// outward.  For two polygons in one plane they are the only axes that can see
/// a gap: the Minkowski difference is flat, every face normal and every eA x eB
/// is the plane normal, with separation exactly 0.  For two polygons in
/// different planes they are valid separating directions too (any direction
/// is), so adding them never changes a verdict in exact arithmetic; they are
/// taken for every pair of flat shapes, with no coplanarity test, so that
/// float and exact runs always have the same candidates.  Face axes win every
/// exact tie, so a side feature is reported only when its separation is the
/// largest.  Returns true when early_out is set and a separating side axis
/// was found.
template <SatKernel K>
bool scan_side_axes(K& k, BestAxis<K>& best, SatStats& stats, const SatOptions& opt) {
  if (!k.a().is_flat() || !k.b().is_flat()) return false;
  return scan_queries(
             k, best, stats.side_axes, k.a().edge_count(), opt, [&](int e) { return k.side_query_a(e); },
             [](int e, int v) { return Feature::side_a(e, v); }) ||
         scan_queries(
             k, best, stats.side_axes, k.b().edge_count(), opt, [&](int e) { return k.side_query_b(e); },
             [](int e, int v) { return Feature::side_b(v, e); });
}

}  // namespace sepax::sat::detail
