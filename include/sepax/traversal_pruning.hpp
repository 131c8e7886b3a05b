// sepax/traversal_pruning.hpp
//
// The traversal's pruning layer: a candidate exactly below the best so far can
// never be the answer, whatever the tie-break, so the walk skips it and the
// result is unchanged.  Every decision here is a kernel decision (exact under
// policy::Robust), so the robust walk takes exactly the exact walk's path.
//   * offer(): a candidate becomes the best; set_thresholds() then keeps the
//     T thresholds that decide most height comparisons with one comparison;
//   * face_below_best(): a vertex's height above a face is exactly below the
//     best, so the face's separation is (a climb's cutoff, a probe, a seed);
//   * arc_below_best(): two heights of a vertex outside the edge's wedge
//     bound every Minkowski face on an arc of a solid A below the best: the
//     arc is skipped (with a best <= 0 the wedge test is implied);
//     cut_end_bounds() the same for a chunk of arcs (best <= 0 only);
//     support_bounds_arc() the same with the ends' support vertices;
//   * crossing_below_best(): one crossing of an arc walk, likewise.
// Built on traversal_state.hpp; traversal_climb.hpp builds on it.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "traversal_state.hpp"

namespace sepax::sat::detail {

template <SatKernel K>
class TraversalPruning : public TraversalState<K> {
  using Base = TraversalState<K>;

 protected:
  using Base::Base;
  using Base::best_;
  using Base::best_err_;
  using Base::best_sign_;
  using Base::cut_a_;
  using Base::cut_b_;
  using Base::hi_a_;
  using Base::hi_b_;
  using Base::k_;
  using Base::kBounded;
  using Base::kCertified;
  using Base::kFast;
  using Base::lo_a_;
  using Base::lo_b_;
  using Base::prune_arcs_;
  using Base::ts_;
  using typename Base::T;
  using typename Base::Threshold;

  // The exact comparison of a candidate with the current best (which exists).
  int vs_best(const Separation<T>& s, const Feature& f) {
    if constexpr (kBounded) {
      return k_.compare_bounded(s, f, k_.error_bound(f), best_.separation(), best_.feature(), best_err_);
    } else {
      return k_.compare(s, f, best_.separation(), best_.feature());
    }
  }
  // Exactly below the best: such a candidate can never be the answer (the
  // best only grows), whatever the tie-break.
  bool below_best(const Separation<T>& s, const Feature& f) { return best_.has() && vs_best(s, f) < 0; }

  // Face f's height h = fl(fl(n_f.x) - offset) of vertex x (bit for bit the
  // kernel's face_separation value before its sign snap, which compare()
  // does not need: the value is within the kernel's error bound either way)
  // is exactly below the best.  One or two T comparisons against thresholds
  // kept with the best (set_thresholds()): h < lo  implies the exact answer
  // "below", h > hi implies "not below"; only between them (or NaN) the
  // kernel decides (compare_bounded: its filter, exact within it).  Without a
  // best lo = hi = -inf: every finite h is "not below".
  template <bool OfA>
  SEPAX_TRAVERSAL_INLINE bool face_below_best(int f, int x, T h) {
    if (h < (OfA ? lo_a_ : lo_b_)) return true;
    if (h > (OfA ? hi_a_ : hi_b_)) return false;
    return best_.has() && vs_best(Separation<T>{h, T(1)}, this->template face_feature<OfA>(f, x)) < 0;
  }

  // Thresholds of face_below_best after the best changed.
  //  * kBounded: compare_bounded(h, best) is -1 without its exact fallback
  //    when best - h > cut (cut = compare_width of the two error bounds, which
  //    already makes a difference beyond it certain), and +1 when h - best >
  //    cut.  t = fl(best - cut) is within |t| 2^-53 of the real best - cut (one
  //    double subtraction, nothing to contract).  below(t) moves t down by
  //    ~(|t| 2^-20 + 2^-140) in double (at most 3 roundings, relative 2^-53
  //    each; fewer under FMA contraction; the product by 2^-20 is exact) and
  //    rounds to T (in any rounding mode off by at most one T spacing,
  //    max(|x| 2^-23, 2^-149)), so below(t) < t - |t| 2^-53 <= best - cut
  //    for every finite t (the 2^-140 covers 0 and the subnormal range;
  //    for T = double the conversion is exact); h < lo then implies best - h > cut
  //    in real arithmetic: the exact comparison is < 0, compare_bounded's
  //    answer.  above(t) likewise for hi ("not below").  best is a finite T
  //    value, so best - cut never rounds up past the largest T.
  //  * plain float/double: compare() of two normalised values is the
  //    comparison of the T numbers: lo = hi = best (equal, NaN: compare()).
  static Threshold below(double t) { return static_cast<Threshold>(t - (std::abs(t) * 0x1p-20 + 0x1p-140)); }
  static Threshold above(double t) { return static_cast<Threshold>(t + (std::abs(t) * 0x1p-20 + 0x1p-140)); }
  void set_thresholds() {
    if constexpr (kFast) {
      if constexpr (kBounded) {
        const double b = static_cast<double>(best_.separation().num);
        lo_a_ = below(b - cut_a_);
        hi_a_ = above(b + cut_a_);
        lo_b_ = below(b - cut_b_);
        hi_b_ = above(b + cut_b_);
      } else {
        lo_a_ = hi_a_ = lo_b_ = hi_b_ = best_.separation().num;
      }
    }
  }
  // The height face_below_best(f, x, h) takes (float kernels): fl(fl(n.x) -
  // offset) of plane pl and point x, computed here only, so that every
  // caller passes the kernel's face separation value bit for bit.
  SEPAX_TRAVERSAL_INLINE static T fast_height(const Plane<T>& pl, const Vec3<T>& x) {
    return T(dot(pl.normal, x) - pl.offset);
  }
  // The same for any kernel (height from the kernel).
  template <bool OfA>
  SEPAX_TRAVERSAL_INLINE bool face_below_best(int f, int x) {
    if constexpr (kFast) {
      ++ts_.height_evals;
      return face_below_best<OfA>(
          f, x, fast_height((OfA ? k_.a() : k_.b()).plane(f), (OfA ? k_.b() : k_.a()).vertex(x)));
    } else {
      return below_best(this->template height<OfA>(f, x), this->template face_feature<OfA>(f, x));
    }
  }

  // Returns whether the candidate is exactly below the best it met (false
  // when there was none): the same decision for every kernel.
  bool offer(const Separation<T>& s, const Feature& f) {
    if constexpr (kBounded) {
      if (best_.has() && vs_best(s, f) < 0) return true;  // the common case: one filter
    }
    bool below = false;
    if (best_.consider(k_, s, f, &below)) {
      if constexpr (kBounded) {
        best_err_ = k_.error_bound(f);
        cut_a_ = k_.compare_width(k_.error_bound(Feature::face_a(0, 0)), best_err_);
        cut_b_ = k_.compare_width(k_.error_bound(Feature::face_b(0, 0)), best_err_);
      }
      set_thresholds();
      best_sign_ = 2;
    }
    return below;
  }

  // The best so far has separation <= 0 (exactly).
  bool best_nonpositive() {
    if (!best_.has()) return false;
    if (best_sign_ == 2) best_sign_ = k_.sign(best_.separation(), best_.feature());
    return best_sign_ <= 0;
  }

  // The arc loop's second pass over a chunk's unsettled arcs (todo, bit i =
  // arc base + i), asked only when the best is <= 0: arc_below_best's
  // first bound for an arc with a cut-off end, x = that end's vertex (known
  // below the best under its own face) below the other end's face -- f1
  // with x0 when f0 was cut off, else f0 with x1.  Returns the arcs it
  // prunes (and counts them); the others go through the full test.  Taken
  // for every such arc of the chunk before any of them is walked, in the
  // same order by every kernel (the exact face_below_best decides), so the
  // robust walk still takes the exact walk's steps.  The fast kernels
  // compute every height and decide "h < lo" without a data-dependent
  // branch; only a height between the thresholds asks the kernel.
  std::uint64_t cut_end_bounds(int base, std::uint64_t todo, const int* a_states, const int* edge_faces,
                               std::int64_t& pruned) {
    std::uint64_t out = 0;
    std::int64_t evals = 0;  // heights of cut-off ends' vertices (as face_below_best counts them)
    for (; todo != 0; todo &= todo - 1) {
      const int i = std::countr_zero(todo);
      const int f0 = edge_faces[2 * (base + i)], f1 = edge_faces[2 * (base + i) + 1];
      const int s0 = a_states[f0], s1 = a_states[f1];
      const bool c0 = !(s0 & kCertified);
      const bool cut = c0 || !(s1 & kCertified);
      const int f = c0 ? f1 : f0;
      const int x = (c0 ? s0 : s1) >> 2;
      bool below;
      if constexpr (kFast) {
        const T h = fast_height(k_.a().plane(f), k_.b().vertex(x));
        below = cut & (h < lo_a_);
        evals += cut;
        if (cut & !(h < lo_a_) & !(h > hi_a_)) [[unlikely]]
          below = face_below_best<true>(f, x, h);
      } else {
        below = cut && face_below_best<true>(f, x);
      }
      out |= static_cast<std::uint64_t>(below) << i;
    }
    ts_.height_evals += evals;
    pruned += std::popcount(out);
    return out;
  }

  // Arc pruning.  For a unit n on the (short, A not flat) arc of eA from
  // n0 = n(f0) to n1 = n(f1), A's support along n is eA, so the separation
  // along n is min_B n.b - n.a_tail <= n.w, w = x - a_tail, for any vertex x
  // of B.  n0.w = height(f0, x) and n1.w = height(f1, x) (a_tail lies on
  // both faces).  The arc's normals lie in the plane orthogonal to eA, where
  // n.w = |w'| cos(angle(n, w')), w' the part of w in that plane: its maximum
  // over the arc is |w'| if w' points strictly between n0 and n1 (x inside
  // the wedge of eA), else the larger of the two heights (the cosine falls
  // off on both sides of w', and the arc, shorter than pi, misses w').  So
  // when both heights of x are exactly below the best and x is not strictly
  // inside the wedge (k.in_edge_wedge_a, exact), every Minkowski face on the
  // arc (its exact separation is the separation along its normal) is exactly
  // below the best, and the arc is skipped.  With a best <= 0 the wedge test
  // is not needed: x inside the wedge has a height > 0 over the nearer end
  // (w' is within half the arc, less than pi/2, of n0 or n1), so two heights
  // below a best <= 0 already put x outside.  Kernels without the wedge test
  // prune only with a best <= 0.  x: the vertex stored for f0 or f1.
  // Every decision is exact (k.compare, k.sign, in_edge_wedge_a), so
  // policy::Robust prunes exactly where exact arithmetic prunes.
  // A face whose climb was cut off has its stored vertex's height exactly
  // below an earlier best, hence below the current one: not asked again.
  SEPAX_TRAVERSAL_INLINE bool arc_below_best(int ea, int s0, int s1, int f0, int f1) {
    if (!prune_arcs_ || !best_.has()) return false;
    const int x0 = s0 >> 2, x1 = s1 >> 2;
    if (!(s0 & kCertified)) {
      if (!(s1 & kCertified) && x0 == x1) return outside_wedge(ea, x0);         // both known below, same x
      if (face_below_best<true>(f1, x0) && outside_wedge(ea, x0)) return true;  // x = x0
      return !(s1 & kCertified) && x1 != x0 && face_below_best<true>(f0, x1) && outside_wedge(ea, x1);
    }
    if (!(s1 & kCertified)) return face_below_best<true>(f0, x1) && outside_wedge(ea, x1);  // x = x1
    return face_below_best<true>(f0, x0) && face_below_best<true>(f1, x0) && outside_wedge(ea, x0);
  }

  // The wedge condition of the arc bound for x, whose heights over both ends
  // of edge ea are exactly below the best: the best is <= 0, or x is not
  // strictly inside the wedge of ea.
  SEPAX_TRAVERSAL_INLINE bool outside_wedge(int ea, int x) {
    if (best_nonpositive()) return true;
    if constexpr (HasEdgeWedge<K>) {
      ++ts_.wedge_tests;
      return !k_.in_edge_wedge_a(ea, x);
    } else {
      return false;
    }
  }

  SEPAX_TRAVERSAL_INLINE bool crossing_below_best(int ea, int f0, int f1, int v) {
    return prune_arcs_ && best_.has() && face_below_best<true>(f0, v) && face_below_best<true>(f1, v) &&
           outside_wedge(ea, v);
  }

  // The same bound on the rest of the walk only, from a crossing exactly
  // below the best to the walk's end face fe, entering vertex v.  Along
  // the arc of ea, every Minkowski face's separation at its normal n is at
  // most n.(v - a) (a on ea, v in B), a linear function of n whose value at
  // the crossing's normal is the crossing's own separation (v ends the
  // crossed edge, B's support there); with that below the best and v's
  // height over fe below the best, the function is below the best on the
  // whole part of the arc still to walk unless its maximum there is
  // inside, which the wedge condition excludes as in arc_below_best (the
  // part lies within the arc, so outside the edge's wedge is outside the
  // part's; with a best <= 0 the nearer end's height argument holds for
  // the part as for the arc).  Exact decisions (face_below_best,
  // in_edge_wedge_a), asked in the same order by every kernel.
  SEPAX_TRAVERSAL_INLINE bool rest_below_best(int ea, int fe, int v) {
    return prune_arcs_ && best_.has() && face_below_best<true>(fe, v) && outside_wedge(ea, v);
  }

  // arc()'s bound with x = the support vertex of end f (certified state s;
  // cut: f was cut off before its late climb, so x is known below the best
  // under f), below f and the other end g, outside the wedge of edge ea;
  // counts the pruned arc.
  bool support_bounds_arc(int ea, int f, bool cut, int s, int g) {
    const int x = s >> 2;
    if (!((cut || face_below_best<true>(f, x)) && face_below_best<true>(g, x) && outside_wedge(ea, x)))
      return false;
    ++ts_.pruned_arcs;
    ++ts_.late_pruned_arcs;
    return true;
  }
};

}  // namespace sepax::sat::detail
