// sepax/sat_traversal.hpp
//
// sat::traversal: the SAT as a walk over the overlaid Gauss maps of A and -B,
// with no support scan of every vertex.  Same result, feature and tie-break as
// sat::brute_force and sat::gauss_map (feature.hpp, best_axis.hpp).
//
// Candidate axes are the vertices of the overlay: face normals of A, face
// normals of B, and crossings of an arc of A with an arc of -B (Minkowski
// edge-edge faces).  The walk finds all of them without a support scan per
// face (a scan over every vertex is only the climbs' fallback when rounding
// makes a climb cycle):
//
//  1. Faces of A, in breadth-first order over face adjacency (GaussMapWalk):
//     the root face's climb is seeded by the support vertex of a start face
//     (see Pruning), itself climbed from the deepest probe vertex; every
//     face's support vertex is found by hill-climbing on B's vertex graph
//     from its parent face's vertex, comparing heights above the face
//     exactly (k.compare of k.face_separation_a(f, v) for neighbouring v;
//     float kernels compare fl(n.v) within the kernel's filter, exactly
//     inside it).  A linear function on a convex polytope has no local
//     minimum that is not global, so the climb ends at a deepest vertex;
//     when the deepest set is larger than one vertex (a tie: an edge or face
//     of B) it is searched for the lowest index, the tie-break every SAT
//     uses.
//  2. Faces of B likewise, hill-climbing on A (the root seeded by step 0).
//  3. Arcs of A.  Edge eA is the arc from n(f0) to n(f1).  The walk starts in
//     the region of -B's Gauss map that contains the start of the arc (the
//     region of B's support vertex for f0, known from step 1) and carries that
//     region along the arc: in the region of vertex v it looks, among the arcs
//     of v's fan, for the one the path leaves through -- the one arc whose
//     Minkowski-face test (k.arc_signs) is strict.  Crossing it is a Minkowski
//     edge-edge face (measured with k.edge_separation in O(1)) and moves the
//     walk to the other end of that edge of B.  The walk stops when v is a
//     deepest vertex for f1 (the end of the arc lies in v's closed region).
//     A convex region is left at most once by a great-circle arc, so every
//     crossing is found exactly once and the walk moves monotonically along
//     the arc.
//
// Pruning (candidates exactly below the best so far can never be the answer,
// whatever the tie-break, so they are skipped; the result is unchanged):
//   * step 0 evaluates two faces near the direction between the shapes'
//     bounding-box centres first (start()), for a good first best;
//   * on large shapes (long face chunks, GaussMapWalk::face_chunks()) the
//     seed tests of a chunk of faces are taken in one pass without a branch
//     on their outcome (no face's parent is in its chunk, so the seeds are
//     final), then the faces not certainly below go on one by one, with the
//     same decisions as the one-face loop of small shapes;
//   * a face whose seed (its parent's vertex) is not below the best tries
//     the other shape's probe vertices (GaussMapWalk::probes(), a fixed list
//     of vertices spread over the shape) before it climbs, and takes the
//     deepest: when its height is exactly below the best, the face is pruned
//     without a climb (probe_below_best()), as most faces that would climb
//     are;
//   * a face's climb stops at the first vertex whose height is exactly below
//     the best (every vertex's height bounds the face's separation); that
//     vertex seeds the face's children and is climbed on (certify()) only if
//     an arc walk needs the support vertex;
//   * an arc of a solid A is skipped when two heights bound every Minkowski
//     face on it below a best <= 0 (arc_below_best(); first for a chunk of
//     arcs at once in cut_end_bounds(); in arc() again with the support
//     vertices its ends are climbed to, before the walk), and so is a single
//     crossing (crossing_below_best()).
// Every pruning decision is a kernel decision (exact under policy::Robust),
// so the robust walk takes exactly the exact walk's path.
//
// Degenerate cases, decided by the same signs:
//   * the path leaves a region through a Gauss-map vertex of -B (a face g of B
//     whose normal lies on the arc, e.g. boxes against boxes): no fan arc is
//     strictly crossed; the exit corner is the face g of v with
//     sign(n_g . eA) == 0 whose two fan arcs both have the rest of the path on
//     the far side (or on the arc's plane, when the path runs along an arc).
//     The region entered is the vertex of g lowest along the path's tangent;
//     the sign of the tangent against each edge of g is the ArcSigns sign of
//     the arc's end normal (valid because the corner lies strictly inside the
//     arc).  The Minkowski-face test is not strict for g's edges, exactly as
//     in sat::gauss_map, so no pair is reported there.
//   * the start of an arc is on the boundary of a region (a tie in step 1):
//     the walk starts from the other end of the arc if that end is clean;
//     otherwise (solid A) the start region is the lexicographic minimum of
//     (height over f0, height over f1) over the tie set, which is the region
//     the path enters.
//   * anything the rules above cannot decide (both ends of an arc of a flat A
//     on region boundaries; the path passing through a Gauss vertex of a flat
//     B, where both corners of a lune are on the arc; more than one candidate
//     exit; a step budget of V + E of B exhausted) makes the walk of that one
//     arc fall back to testing the arc against every arc of -B (O(E_B), what
//     sat::gauss_map does per arc).  Pairs found twice are harmless (BestAxis
//     keeps the first of equal candidates).  The fallback count is in
//     TraversalStats.
// Kernels with rounded decisions (PlainKernel<float/double>) and a flat shape
// skip the walk of step 3: every arc of A is tested against every arc of -B,
// as sat::gauss_map does (see run(); the rounded climb can start a walk one
// region off).
// Every step moves strictly forward along a finite arc, and every loop has a
// budget, so the walk terminates for any input and any kernel, exact or not.
//
// Every number and sign goes through the kernel (SatKernel), so the walk is
// exact for exact T and, under policy::Robust, makes the decisions exact
// arithmetic would make.  With plain float arithmetic the hill climb and the
// arc signs are evaluated in rounding arithmetic, like sat::gauss_map.
//
// Allocation: the convenience overload builds GaussMapWalk for both shapes
// (heap).  The overload taking GaussMapWalk data does not allocate for hulls
// with up to kTraversalInlineFaces faces in total (scratch on the stack); with
// float/double it allocates nothing at all per query.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "best_axis.hpp"
#include "sat_cache.hpp"
#include "gauss_map_walk.hpp"
#include "plain_kernel.hpp"
#include "simd_lanes.hpp"

/// The walk's O(1) per-face checks: inlined into their loops even when the
/// inliner's size heuristics would not.
#if defined(__GNUC__) || defined(__clang__)
#define SEPAX_TRAVERSAL_INLINE [[gnu::always_inline]] inline
#else
#define SEPAX_TRAVERSAL_INLINE inline
#endif

namespace sepax::sat {

/// Total faces (A + B) the traversal keeps per-face scratch for on the stack.
inline constexpr int kTraversalInlineFaces = 1024;

/// Steps 1 and 2 (float kernels) take the seed tests of a chunk of faces
/// (GaussMapWalk::face_chunks()) in one pass when a shape's chunks hold at
/// least this many faces on average; on shorter chunks (small shapes) the
/// per-chunk loop exits cost more than the one-face loop's mispredicted
/// seed tests (docs/traversal.md, "Why it is built this way").
inline constexpr int kTraversalMinMeanChunk = 12;

/// Counters of one traversal query (beyond SatStats), for tests and tuning.
struct TraversalStats {
  std::int64_t support_scans = 0;     // full support scans (k.face_query_*): only a
                                      // climb's fallback when rounding makes it cycle
  std::int64_t climb_steps = 0;       // hill-climb moves
  std::int64_t height_evals = 0;      // k.face_separation_* calls
  std::int64_t arc_tests = 0;         // k.arc_signs calls
  std::int64_t corner_passes = 0;     // walks through a Gauss-map vertex of -B
  std::int64_t lex_starts = 0;        // arcs started by the lexicographic rule
  std::int64_t fallback_arcs = 0;     // arcs tested against every arc of -B
  std::int64_t pruned_faces = 0;      // faces whose climb stopped below the best
  std::int64_t probe_checks = 0;      // faces that looked for the deepest probe vertex
  std::int64_t probe_pruned = 0;      // faces pruned by a probe vertex (in pruned_faces)
  std::int64_t pruned_arcs = 0;       // arcs skipped: every crossing below the best
  std::int64_t late_pruned_arcs = 0;  // of them, skipped after climbing an end (arc())
  std::int64_t late_certified = 0;    // pruned faces climbed on for an arc walk
  std::int64_t pruned_crossings = 0;  // crossings skipped: below the best
};

namespace detail {

// Per-face int scratch: on the stack up to kTraversalInlineFaces, else heap.
class FaceScratch {
 public:
  explicit FaceScratch(int n) {
    if (n > kTraversalInlineFaces) heap_.resize(static_cast<std::size_t>(n));
    data_ = n > kTraversalInlineFaces ? heap_.data() : inline_.data();
  }
  FaceScratch(const FaceScratch&) = delete;
  FaceScratch& operator=(const FaceScratch&) = delete;
  int& operator[](int i) { return data_[i]; }

 private:
  std::array<int, kTraversalInlineFaces> inline_;
  std::vector<int> heap_;
  int* data_;
};

template <SatKernel K>
class Traversal {
 public:
  using T = typename K::FT;

  Traversal(K& k, const GaussMapWalk& wa, const GaussMapWalk& wb, const SatOptions& opt,
            TraversalStats& ts, const Feature* seed = nullptr)
      : k_(k), wa_(wa), wb_(wb), opt_(opt), ts_(ts), seed_(seed), prune_arcs_(!wa.is_flat()),
        plain_flat_(wa.is_flat() || wb.is_flat()) {}

  SatResult<T> run() {
    const int fa = wa_.face_count(), fb = wb_.face_count();
    FaceScratch st(fa + fb);
    // st(f) for faces of A at [0, fa), for faces of B at [fa, fa + fb):
    // (vertex << 2) | kCertified | kTie, see climb().
    if constexpr (kFast) {
      gather(probes_a_, wa_, k_.a());
      gather(probes_b_, wb_, k_.b());
    }
    // (plain float/double climbs and walks in rounding arithmetic, where a
    // seed's full-scan value need not be the one the walk finds: no warm start)
    if constexpr (!kRoundingDecisions) {
      if (seed_ && warm_start()) return best_.result(k_, stats_, true);
    }
    if (start()) return best_.result(k_, stats_, true);
    if (faces<true>(st, 0)) return best_.result(k_, stats_, true);
    if (faces<false>(st, fa)) return best_.result(k_, stats_, true);
    const int ne = wa_.edge_count();
    if constexpr (kRoundingDecisions) {
      // Plain float/double with a flat shape (a polygon lying on or near the
      // other shape, fuzz/corpus/37-...): every arc is tested against every
      // arc of -B, as sat::gauss_map does, with no walk and no arc pruning.
      // The walk starts an arc in the region of the support vertex that the
      // climb picked by comparing fl(n.v), and a flat shape nearly parallel
      // to a face of the other makes those heights rounding ties: a start
      // one region off skips a crossing the arc test itself accepts.  Exact
      // and robust kernels decide both exactly and consistently and walk.
      if (plain_flat_) {
        for (int ea = 0; ea < ne; ++ea) {
          if (fallback(ea)) return best_.result(k_, stats_, true);
        }
        if (scan_side_axes(k_, best_, stats_, opt_)) return best_.result(k_, stats_, true);
        return best_.result(k_, stats_, false);
      }
    }
    const int* sa = &st[0];  // faces of A (arc() updates them through st)
    std::int64_t pruned = 0;
    bool stop = false;
    // Arcs in chunks of 64.  First, without a data-dependent branch (its
    // outcome varies from arc to arc and a mispredicted branch costs more
    // than the test), the arcs that steps 1 and 2 already settle are marked:
    // both ends with the same state, and
    //  * the same unique support vertex, certified at both ends: both ends
    //    are in the closed region of that vertex, which is convex, so the arc
    //    stays inside it: no crossing;
    //  * or both climbs cut off at the same vertex x and the best <= 0: both
    //    heights of x are exactly below the best (arc_below_best with x).
    //    best_nonpositive() is asked once per chunk; the best only grows, so
    //    heights below an earlier best are below every later one, and an arc
    //    whose Minkowski faces are all below a best <= 0 stays pruned.
    // Second, with the best <= 0, the unsettled arcs with a cut-off end are
    // tried with that end's vertex below the other end's face, again
    // without a branch on the outcome (cut_end_bounds()).  The arcs left go
    // through the full test, on their current states.  All passes are
    // kernel decisions, so the exact walk marks and prunes the same arcs.
    const int* ef = wa_.edge_faces();
    for (int base = 0; base < ne && !stop; base += 64) {
      const int end = ne - base < 64 ? ne : base + 64;
      // bit `kind` (a state's low two bits) is set for the kinds that equal
      // states settle: kCertified alone always, 0 (cut off) when prunable
      const unsigned kinds = (1u << kCertified) | (prune_arcs_ && best_nonpositive() ? 1u : 0u);
      std::uint64_t settled = 0;
      for (int ea = base; ea < end; ++ea) {
        const int s0 = sa[ef[2 * ea]], s1 = sa[ef[2 * ea + 1]];
        const unsigned skip = static_cast<unsigned>(s0 == s1) & (kinds >> (s0 & 3));
        settled |= static_cast<std::uint64_t>(skip) << (ea - base);
        pruned += skip & ~static_cast<unsigned>(s0 >> 1);  // kind 0 (kind kCertified has bit 1 set)
      }
      const std::uint64_t all = end - base == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << (end - base)) - 1;
      std::uint64_t todo = ~settled & all;
      if (kinds & 1u) todo &= ~cut_end_bounds(base, todo, sa, ef, pruned);
      for (; todo != 0; todo &= todo - 1) {
        const int ea = base + std::countr_zero(todo);
        const int f0 = wa_.edge_face(ea, 0), f1 = wa_.edge_face(ea, 1);
        const int s0 = sa[f0], s1 = sa[f1];
        if (s0 == s1) {
          if ((s0 & 3) == kCertified) continue;
          if ((s0 & 3) == 0 && prune_arcs_ && best_nonpositive()) {
            ++pruned;
            continue;
          }
        }
        if (arc_below_best(s0, s1, f0, f1)) {
          ++pruned;
          continue;
        }
        if (arc(st, ea, f0, f1)) {
          stop = true;
          break;
        }
      }
    }
    ts_.pruned_arcs += pruned;
    if (stop) return best_.result(k_, stats_, true);
    if (scan_side_axes(k_, best_, stats_, opt_)) return best_.result(k_, stats_, true);
    return best_.result(k_, stats_, false);
  }

 private:
  // face_below_best's threshold type (T for float/double; unused otherwise).
  using Thr = std::conditional_t<std::is_floating_point_v<T>, T, float>;
  static constexpr Thr kNegInf = -std::numeric_limits<Thr>::infinity();

  // Per-face state bits (below the vertex index).
  static constexpr int kTie = 1;        // the deepest set has more than one vertex
  static constexpr int kCertified = 2;  // the vertex is the support vertex (else: a
                                        // vertex whose height is below the best)

  // Kernels with the filtered support comparison (sat_kernel.hpp,
  // HasSupportFilter: PlainKernel<float/double>, RobustKernel): the climb
  // compares fl(n.v) values, support_sign within the kernel's filter.
  static constexpr bool kFast = HasSupportFilter<K>;
  // Kernels whose decisions are rounded (PlainKernel<float/double>, or a
  // wrapper of it), unlike RobustKernel's and exact kernels': see run().
  static constexpr bool kRoundingDecisions = !exact_decisions_v<K>;
  // Kernels that expose their value error bounds (RobustKernel): the current
  // best's bound is kept, so comparing a candidate with the best costs one
  // filter (the same filter and exact fallback as k.compare).
  static constexpr bool kBounded = HasBoundedCompare<K>;

  // ---- heights -------------------------------------------------------------
  // OfA: face f of A, vertex v of B; else face f of B, vertex v of A.
  template <bool OfA>
  static Feature face_feature(int f, int v) {
    return OfA ? Feature::face_a(f, v) : Feature::face_b(v, f);
  }
  template <bool OfA>
  Separation<T> height(int f, int v) {
    ++ts_.height_evals;
    return OfA ? k_.face_separation_a(f, v) : k_.face_separation_b(f, v);
  }
  // compare heights of vertices v and w above face f (exact in exact/robust)
  template <bool OfA>
  int cmp(int f, int v, const Separation<T>& hv, int w, const Separation<T>& hw) {
    return k_.compare(hv, face_feature<OfA>(f, v), hw, face_feature<OfA>(f, w));
  }

  // ---- the best candidate --------------------------------------------------
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
    return best_.has() && vs_best(Separation<T>{h, T(1)}, face_feature<OfA>(f, x)) < 0;
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
  static Thr below(double t) { return static_cast<Thr>(t - (std::abs(t) * 0x1p-20 + 0x1p-140)); }
  static Thr above(double t) { return static_cast<Thr>(t + (std::abs(t) * 0x1p-20 + 0x1p-140)); }
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
      return face_below_best<OfA>(f, x, fast_height((OfA ? k_.a() : k_.b()).plane(f), (OfA ? k_.b() : k_.a()).vertex(x)));
    } else {
      return below_best(height<OfA>(f, x), face_feature<OfA>(f, x));
    }
  }

  void offer(const Separation<T>& s, const Feature& f) {
    if constexpr (kBounded) {
      if (best_.has() && vs_best(s, f) < 0) return;  // the common case: one filter
    }
    if (best_.consider(k_, s, f)) {
      if constexpr (kBounded) {
        best_err_ = k_.error_bound(f);
        cut_a_ = k_.compare_width(k_.error_bound(Feature::face_a(0, 0)), best_err_);
        cut_b_ = k_.compare_width(k_.error_bound(Feature::face_b(0, 0)), best_err_);
      }
      set_thresholds();
      best_sign_ = 2;
    }
  }

  // The best so far has separation <= 0 (exactly).
  bool best_nonpositive() {
    if (!best_.has()) return false;
    if (best_sign_ == 2) best_sign_ = k_.sign(best_.separation(), best_.feature());
    return best_sign_ <= 0;
  }

  // ---- support vertices by hill climbing -----------------------------------
  // Deepest vertex of the other shape below face f, by hill climb from seed v;
  // the lowest index among exactly deepest ones.  Returns
  // (vertex << 2) | kCertified | (kTie if the deepest set has more than one
  // vertex).  With cutoff, the climb stops as soon as the height of its
  // current vertex is exactly below the best candidate so far: every vertex's
  // height is >= the face's separation, so the face cannot be the answer; it
  // returns (vertex << 2) without kCertified, and certify() resumes the same
  // deterministic climb from there if the support vertex is needed later.
  // check_seed = false: the caller has just found the seed not below the best.
  // The climb is written once against a SupportOrder (below): the kernel's
  // filtered comparison of projections (kFast) or its heights and compare().
  template <bool OfA>
  int climb(int f, int v, bool cutoff, bool check_seed = true) {
    const auto o = support_order<OfA>(f);
    const GaussMapWalk& w = OfA ? wb_ : wa_;
    cutoff = cutoff && best_.has();
    int budget = w.vertex_count() + 1;
    std::int64_t evals = 1;  // keys computed (heights, as face_separation_* counts them)
    auto kv = o.key(v);
    for (bool check = check_seed;; check = true) {
      if (cutoff && check && o.below_best(v, kv)) {
        ts_.height_evals += evals;
        return v << 2;
      }
      bool moved = false, tie = false;
      const int end = w.adj_end(v);
      for (int i = w.adj_begin(v); i < end; ++i) {
        const int u = w.adj_vertex(i);
        const auto ku = o.key(u);
        ++evals;
        const int c = o.cmp(u, ku, v, kv);
        if (c > 0) continue;  // the common case: u higher
        if (c == 0) {
          tie = true;
          continue;
        }
        v = u;
        kv = ku;
        moved = true;
        break;
      }
      if (!moved && !w.triangulated()) {
        // The far vertices of v's non-triangular faces (not neighbours of v):
        // on an exactly convex polytope none is strictly lower, but a face
        // that is planar only up to rounding (the exact image of a rotated
        // float box) can dip below v at a far vertex.
        for (int i = w.adj_begin(v); i < end && !moved; ++i) {
          const int h = w.adj_half_edge(i);
          for (int g = w.next(w.next(h)); w.next(g) != h; g = w.next(g)) {
            const int x = w.origin(g);
            const auto kx = o.key(x);
            ++evals;
            if (o.cmp(x, kx, v, kv) < 0) {
              v = x;
              kv = kx;
              moved = true;
              break;
            }
          }
        }
      }
      if (moved) {
        ++ts_.climb_steps;
        if (--budget < 0) {  // inconsistent rounding only
          ts_.height_evals += evals;
          return scan<OfA>(f);
        }
        continue;
      }
      if (tie) {
        // the deepest set through v: its lowest vertex index (the lambda
        // captures copies, so that v, kv and evals stay in registers above)
        std::int64_t tied_evals = 0;
        auto tied = [&o, &tied_evals, v, kv](int u) {
          ++tied_evals;
          return o.cmp(u, o.key(u), v, kv) == 0;
        };
        v = lowest_tied_with<OfA>(v, tied);
        evals += tied_evals;
      }
      ts_.height_evals += evals;
      return (v << 2) | kCertified | (tie ? kTie : 0);
    }
  }

  // The order of the other shape's vertices below face f, as the climb asks
  // it: a key per vertex, the sign of the difference
  // of two vertices' heights, and whether a vertex is exactly below the best.
  //  * FilteredOrder (kFast: sat_kernel.hpp, HasSupportFilter): the key is
  //    g = fl(n.v), the support scan's value; two keys are compared within
  //    the kernel's filter (support_cmp), exactly for the robust kernel;
  //    fl(g - offset) is bit for bit the kernel's face separation value.
  //  * HeightOrder (any other kernel): the key is the kernel's height, the
  //    comparison k.compare.
  // Under policy::Robust and exact arithmetic both are the exact sign of
  // N.(u - v), so the robust walk and the exact walk climb alike.
  template <bool OfA>
  struct FilteredOrder {
    using Key = T;
    Traversal& t;
    int f;
    const Vec3<T>* vs;
    Vec3<T> n;
    T offset;
    T width;
    SEPAX_TRAVERSAL_INLINE Key key(int x) const { return dot(n, vs[x]); }
    SEPAX_TRAVERSAL_INLINE int cmp(int u, Key ku, int v, Key kv) const {
      return t.template support_cmp<OfA>(f, u, v, T(ku - kv), width);
    }
    SEPAX_TRAVERSAL_INLINE bool below_best(int v, Key kv) const {
      return t.template face_below_best<OfA>(f, v, T(kv - offset));
    }
  };
  template <bool OfA>
  struct HeightOrder {
    using Key = Separation<T>;
    Traversal& t;
    int f;
    Key key(int x) const { return OfA ? t.k_.face_separation_a(f, x) : t.k_.face_separation_b(f, x); }
    int cmp(int u, const Key& ku, int v, const Key& kv) const { return t.template cmp<OfA>(f, u, ku, v, kv); }
    bool below_best(int v, const Key& kv) const { return t.below_best(kv, face_feature<OfA>(f, v)); }
  };
  template <bool OfA>
  auto support_order(int f) {
    if constexpr (kFast) {
      const Plane<T>& pl = (OfA ? k_.a() : k_.b()).plane(f);
      return FilteredOrder<OfA>{*this, f, (OfA ? k_.b() : k_.a()).vertices().data(), pl.normal, pl.offset,
                                filter<OfA>()};
    } else {
      return HeightOrder<OfA>{*this, f};
    }
  }

  // Filter width for comparing fl(n.u) - fl(n.v) (0 for plain float).
  template <bool OfA>
  T filter() const {
    return OfA ? k_.support_filter_a() : k_.support_filter_b();
  }
  // The kernel's sign of height(f, u) - height(f, v), asked only when
  // d = fl(n.u) - fl(n.v) is within the filter (or NaN): exact for the
  // robust kernel; plain float (filter 0, d 0 or NaN here) answers 0
  // (equal), as compare() of two rounded values.
  template <bool OfA>
  int exact_vs(int f, int u, int v, T d) {
    return OfA ? k_.support_sign_a(f, u, v, d) : k_.support_sign_b(f, u, v, d);
  }

  // The sign of height(f, u) - height(f, v), exactly, from d = fl(g_u) - fl(g_v)
  // (g = fl(n.x)): the filter decides beyond W, exact_vs within it (or NaN).
  template <bool OfA>
  SEPAX_TRAVERSAL_INLINE int support_cmp(int f, int u, int v, T d, T W) {
    if (d > W) return 1;
    if (d < -W) return -1;
    return exact_vs<OfA>(f, u, v, d);
  }

  // Only reached when rounding made the climb cycle (never for exact
  // decisions): a full support scan.
  template <bool OfA>
  int scan(int f) {
    ++ts_.support_scans;
    const auto q = OfA ? k_.face_query_a(f) : k_.face_query_b(f);
    return (q.support_vertex << 2) | kCertified | kTie;
  }

  template <bool OfA, class Tied>
  int lowest_tied_with(int v, Tied&& tied) {
    const GaussMapWalk& w = OfA ? wb_ : wa_;
    int m = v;
    for (int i = w.adj_begin(v); i < w.adj_end(v); ++i) {
      const int u = w.adj_vertex(i);
      if (!tied(u)) continue;
      if (u < m) m = u;
      const int h = w.adj_half_edge(i);
      for (int g = w.next(w.next(h)); g != h; g = w.next(g)) {
        const int x = w.origin(g);
        if (!tied(x)) break;
        if (x < m) m = x;
      }
    }
    return m;
  }

  // ---- step 0: a good first candidate ---------------------------------------
  // The cutoff prunes a face only against the best so far, so the walk first
  // takes two faces that are likely near the answer: with d the vector
  // between the bounding-box centres (A to B), the face of A at A's vertex
  // furthest along d (its region of the Gauss map contains d) and the face of
  // B at B's vertex furthest along -d.  Their support vertices also seed the
  // face walks of step 1 and 2 (the root face of A and of B).
  //
  // The choice is a heuristic (any choice gives the same result on exactly
  // convex inputs), but it is made so that a float shape and its exact image
  // (convert_from) choose the same faces, under every FMA contraction
  // setting: coordinates and d are rounded to float, so every product
  // float * float is exact in double and contraction cannot change it; the
  // sums are plain double additions; ties keep the first vertex looked at
  // (furthest() visits vertices in an order fixed by the walk data).  Hence
  // policy::Robust and exact arithmetic still take identical steps.
  static double key_coord(const T& x) { return static_cast<double>(static_cast<float>(to_double(x))); }
  // A vertex of p furthest along d, without a scan of every vertex: the
  // probe with the largest key (the first of equal ones), then, unless
  // every vertex is a probe, a steepest-ascent climb on p's vertex graph
  // (the first neighbour of the largest key).  Keys rise strictly, so the
  // climb ends; on a convex polytope it ends at a furthest vertex unless
  // rounding of the keys makes a tie.  (It replaced a scan of every vertex
  // of both shapes and a full support scan for the start face: -6% wall
  // time at N = 256, docs/traversal.md "Why it is built this way".)
  static int furthest(const ConvexPolyhedron<T>& p, const GaussMapWalk& w, const double (&d)[3]) {
    auto key = [&](int i) {
      const Vec3<T>& v = p.vertex(i);
      return key_coord(v[0]) * d[0] + key_coord(v[1]) * d[1] + key_coord(v[2]) * d[2];
    };
    const auto& ids = w.probes();
    int best = ids.empty() ? 0 : ids[0];
    double m = key(best);
    for (std::size_t c = 1; c < ids.size(); ++c) {
      const double x = key(ids[c]);
      if (x > m) {
        m = x;
        best = ids[c];
      }
    }
    if (static_cast<int>(ids.size()) == p.vertex_count()) return best;  // every vertex is a probe
    for (int up = best; up >= 0;) {
      best = up;
      up = -1;
      for (int i = w.adj_begin(best); i < w.adj_end(best); ++i) {
        const int u = w.adj_vertex(i);
        const double x = key(u);
        if (x > m) {
          m = x;
          up = u;
        }
      }
    }
    return best;
  }

  // Returns true on early out.
  bool start() {
    const ConvexPolyhedron<T>& a = k_.a();
    const ConvexPolyhedron<T>& b = k_.b();
    double d[3], md[3];
    for (int c = 0; c < 3; ++c) {
      const double cb = key_coord(b.bounds_min()[c]) + key_coord(b.bounds_max()[c]);
      const double ca = key_coord(a.bounds_min()[c]) + key_coord(a.bounds_max()[c]);
      d[c] = static_cast<double>(static_cast<float>(cb - ca));
      md[c] = -d[c];
    }
    const int va = furthest(a, wa_, d), vb = furthest(b, wb_, md);
    const int fa = wa_.face(wa_.adj_half_edge(wa_.adj_begin(va)));
    const int fb = wb_.face(wb_.adj_half_edge(wb_.adj_begin(vb)));
    // fa's support vertex: climbed (exactly, no cutoff) from the deepest
    // probe of B below fa -- the same vertex a full support scan gives
    const int p = deepest_probe<true>(fa);
    int s = climb<true>(fa, p >= 0 ? p : 0, false);
    seed_a_ = s >> 2;
    if (offer_face<true>(fa, seed_a_)) return true;
    s = climb<false>(fb, va, true);
    seed_b_ = s >> 2;
    if ((s & kCertified) && offer_face<false>(fb, seed_b_)) return true;
    return false;
  }

  // Warm start (SatCache): the seed feature, re-evaluated at this pose
  // (reevaluate, sat_cache.hpp: the same kernel queries the walk makes for
  // that feature, so the same separation), is offered first.  It is one of
  // the SAT's own candidates (a face with its certified support vertex, or a
  // non-parallel Minkowski edge pair), so offering it early changes no
  // result: the best is order-independent (best_axis.hpp) and every pruning
  // test compares with a best that is some candidate's exact value, which
  // only grows.  It makes that best strong from the first face on.  A seed
  // that is out of range or no longer a Minkowski pair is ignored.
  bool warm_start() {
    const auto ev = reevaluate(k_, *seed_);
    if (!ev) return false;
    const FeatureType ty = ev->first.type;
    ++(ty == FeatureType::EdgePair ? stats_.edge_pairs : ty == FeatureType::FaceA || ty == FeatureType::FaceB
                                                             ? stats_.face_axes
                                                             : stats_.side_axes);
    if (ty == FeatureType::EdgePair) ++stats_.minkowski_faces;
    offer(ev->second, ev->first);
    return stops_early(k_, ev->second, ev->first, opt_);
  }

  // Offer face f with its support vertex v; true on early out.
  template <bool OfA>
  bool offer_face(int f, int v) {
    const Feature feat = face_feature<OfA>(f, v);
    const Separation<T> h = height<OfA>(f, v);
    offer(h, feat);
    return stops_early(k_, h, feat, opt_);
  }

  // Steps 1 and 2: support vertices of all faces of A (OfA) or of B, each
  // climbed from its parent face's vertex with the cutoff.
  template <bool OfA>
  bool faces(FaceScratch& st, int base) {
    const GaussMapWalk& w = OfA ? wa_ : wb_;
    const int* order = w.face_order().data();
    const int* parent = w.face_parent().data();
    const int nf = static_cast<int>(w.face_order().size());  // every face (BFS of a connected map)
    if constexpr (kFast) {
      const Plane<T>* planes = (OfA ? k_.a() : k_.b()).planes().data();
      const Vec3<T>* vs = (OfA ? k_.b() : k_.a()).vertices().data();
      std::int64_t pruned = 0;
      bool stop = false;
      int* sb = &st[base];  // this shape's per-face states
      const std::vector<int>& chunks = w.face_chunks();
      const int nc = static_cast<int>(chunks.size()) - 1;
      int i = 0;  // the last face processed when stopped
      if (nf < kTraversalMinMeanChunk * nc) {
        // Short chunks (small shapes): one face at a time.
        for (; i < nf; ++i) {
          const int f = order[i];
          // the BFS root (i = 0, parent -1) is seeded by step 0
          const int seed = i > 0 ? sb[parent[i]] >> 2 : OfA ? seed_a_ : seed_b_;
          // most faces stop at their seed: decided here, without a call
          const T h = fast_height(planes[f], vs[seed]);
          sb[f] = seed << 2;
          if (h < (OfA ? lo_a_ : lo_b_)) {
            ++pruned;
            continue;
          }
          if (beyond_seed<OfA>(sb, f, seed, h, pruned)) {
            stop = true;
            break;
          }
        }
      } else {
        for (int c = 0; c < nc && !stop; ++c) {
          const int b = chunks[static_cast<std::size_t>(c)], e = chunks[static_cast<std::size_t>(c) + 1];
          // First every face's test at its seed, without a branch on the
          // outcome: no face's parent is in its chunk, so the seeds are
          // final.  A face certainly below (h < lo) is pruned at its seed,
          // as the one-face loop prunes it; the best only grows, so a later
          // look could not decide otherwise.
          const T lo = OfA ? lo_a_ : lo_b_;
          std::uint64_t fail = 0;
          for (int j = b; j < e; ++j) {
            const int f = order[j];
            const int seed = j > 0 ? sb[parent[j]] >> 2 : OfA ? seed_a_ : seed_b_;
            const T h = fast_height(planes[f], vs[seed]);
            sb[f] = seed << 2;
            fail |= static_cast<std::uint64_t>(!(h < lo)) << (j - b);
          }
          // Then the others, in order, with the current best.
          int last = e - 1;
          for (std::uint64_t todo = fail; todo != 0; todo &= todo - 1) {
            const int j = b + std::countr_zero(todo);
            const int f = order[j];
            const int seed = sb[f] >> 2;
            if (beyond_seed<OfA>(sb, f, seed, fast_height(planes[f], vs[seed]), pruned)) {
              stop = true;
              i = last = j;
              break;
            }
          }
          // the faces pruned in the first pass, up to the last one processed
          const int upto = last - b + 1;
          const std::uint64_t seen = upto == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << upto) - 1;
          pruned += upto - std::popcount(fail & seen);
        }
      }
      const int done = stop ? i + 1 : nf;  // faces processed
      stats_.face_axes += done;
      ts_.height_evals += done;  // each face's seed height, taken here
      ts_.pruned_faces += pruned;
      return stop;
    } else {
      for (int i = 0; i < nf; ++i) {
        const int f = order[i];
        const int seed = parent[i] >= 0 ? st[base + parent[i]] >> 2 : OfA ? seed_a_ : seed_b_;
        ++stats_.face_axes;
        // the same decisions in the same order as the fast path: the seed,
        // the probes, then the climb
        if (below_best(height<OfA>(f, seed), face_feature<OfA>(f, seed))) {
          st[base + f] = seed << 2;
          ++ts_.pruned_faces;
          continue;
        }
        if (const int p = probe_below_best<OfA>(f, seed); p >= 0) {
          st[base + f] = p << 2;
          ++ts_.pruned_faces;
          ++ts_.probe_pruned;
          continue;
        }
        const int s = climb<OfA>(f, seed, true, false);
        st[base + f] = s;
        if (!(s & kCertified)) {
          ++ts_.pruned_faces;
          continue;
        }
        if (offer_face<OfA>(f, s >> 2)) return true;
      }
      return false;
    }
  }

  // Fast kernels, face f whose seed's height h is not certainly below the
  // best (h >= lo, or NaN): the full decision at the seed (the filter, exact
  // between the thresholds), then the probes, then the climb.  Sets sb[f]
  // (already seed << 2) and counts pruned faces; true on early out.
  template <bool OfA>
  bool beyond_seed(int* sb, int f, int seed, T h, std::int64_t& pruned) {
    if (face_below_best<OfA>(f, seed, h)) {
      ++pruned;
      return false;
    }
    if (const int p = probe_below_best<OfA>(f, seed); p >= 0) {
      sb[f] = p << 2;
      ++pruned;
      ++ts_.probe_pruned;
      return false;
    }
    const int s = climb<OfA>(f, seed, true, false);
    sb[f] = s;
    if (!(s & kCertified)) {
      ++pruned;
      return false;
    }
    return offer_face<OfA>(f, s >> 2);
  }

  // Before a face climbs (its seed is not below the best): the deepest probe
  // vertex p of the other shape below it.  If p's height is exactly below the
  // best, p bounds the face's separation below the best, as a climb's cutoff
  // vertex does, and takes its place in the face's state (the deepest probe,
  // because the state seeds the face's children): the face is pruned without
  // a climb.  Returns p, or -1 (then the face climbs from its seed; starting
  // from p when it is lower was measured: fewer climb steps, more
  // instructions).  Every decision is exact under policy::Robust (the climb's
  // support comparison, face_below_best), so the exact walk takes the same
  // steps.
  template <bool OfA>
  int probe_below_best(int f, int seed) {
    if (!best_.has()) return -1;
    const int p = deepest_probe<OfA>(f);
    if (p < 0 || p == seed) return -1;  // the seed was just found not below
    return face_below_best<OfA>(f, p) ? p : -1;
  }

  // The deepest of the other shape's probe vertices (GaussMapWalk::probes())
  // below face f -- exactly, the first in the probe order among equally deep
  // ones; -1 without probes.
  //
  // Float kernels take every probe's n.x at once in SIMD lanes (dot()'s
  // operations in its order), then the lanes not certainly above the lowest
  // (fl(g - g_min) <= the climb's filter width: every exactly deepest probe
  // is among them); usually one, else they are compared exactly in order.
  // NaN lanes (overflow): the comparisons one by one, as the climb makes them.
  template <bool OfA>
  int deepest_probe(int f) {
    const GaussMapWalk& w = OfA ? wb_ : wa_;
    const auto& ids = w.probes();
    if (ids.empty()) return -1;
    if constexpr (kFast) {
      using L = simd::Lanes<T>;
      using V = typename L::V;
      constexpr int W = L::width;
      constexpr int kGroups = GaussMapWalk::kMaxProbes / W;
      const ProbeLanes& pr = OfA ? probes_b_ : probes_a_;
      const Plane<T>& pl = (OfA ? k_.a() : k_.b()).plane(f);
      const Vec3<T>* vs = (OfA ? k_.b() : k_.a()).vertices().data();
      const Vec3<T> n = pl.normal;
      const T filt = filter<OfA>();
      const auto nx = L::set1(n[0]), ny = L::set1(n[1]), nz = L::set1(n[2]);
      // the groups of lanes that hold probes (the lanes past the probe count
      // repeat probe 0 and are masked off).  A run-time trip count: the fully
      // unrolled loop over kGroups was slower in the bench binary (robust row
      // 1.83 vs 1.57 us at N = 16), with 2% fewer instructions.
      const int groups = (pr.count + W - 1) / W;
      V g[kGroups];
      V gmin = L::set1(std::numeric_limits<T>::infinity());
      unsigned ordered = 0;  // lanes that are not NaN
      for (int i = 0; i < groups; ++i) {
        g[i] = simd::dot3<L>(nx, ny, nz, L::load(pr.x + i * W), L::load(pr.y + i * W), L::load(pr.z + i * W));
        gmin = L::min_lt(g[i], gmin);
        ordered |= L::bits(L::eq(g[i], g[i])) << (i * W);
      }
      ++ts_.probe_checks;  // pr.count heights in lanes (not in height_evals)
      const unsigned valid = pr.valid;
      unsigned cand = 0;  // lanes not certainly above the lowest
      if ((ordered & valid) == valid) {
        const V mneg = L::set1(-L::first(L::hmin(gmin)));
        const V width = L::set1(filt);
        for (int i = 0; i < groups; ++i) cand |= L::bits(L::le(L::add(g[i], mneg), width)) << (i * W);
        cand &= valid;  // empty only when the lowest is -inf (then g - g_min is NaN)
      }
      int j = 0;  // position of the deepest probe
      if (cand != 0) {
        j = std::countr_zero(cand);
        for (unsigned rest = cand & (cand - 1); rest != 0; rest &= rest - 1) {
          const int c = std::countr_zero(rest);
          const int u = ids[static_cast<std::size_t>(c)], v = ids[static_cast<std::size_t>(j)];
          if (support_cmp<OfA>(f, u, v, T(dot(n, vs[u]) - dot(n, vs[v])), filt) < 0) j = c;
        }
      } else {  // NaN or infinite values: one by one, as the climb compares
        T gj = dot(n, vs[ids[0]]);
        for (int c = 1; c < pr.count; ++c) {
          const int u = ids[static_cast<std::size_t>(c)];
          const T gu = dot(n, vs[u]);
          if (support_cmp<OfA>(f, u, ids[static_cast<std::size_t>(j)], T(gu - gj), filt) < 0) {
            j = c;
            gj = gu;
          }
        }
      }
      return ids[static_cast<std::size_t>(j)];
    } else {
      ++ts_.probe_checks;
      int m = ids[0];
      Separation<T> hm = height<OfA>(f, m);
      for (std::size_t c = 1; c < ids.size(); ++c) {
        const int u = ids[c];
        const Separation<T> hu = height<OfA>(f, u);
        if (cmp<OfA>(f, u, hu, m, hm) < 0) {
          m = u;
          hm = hu;
        }
      }
      return m;
    }
  }

  // The support state of face f of A, climbed to the support vertex if the
  // cutoff stopped it.
  int certify(FaceScratch& st, int f) {
    int s = st[f];
    if (!(s & kCertified)) {
      ++ts_.late_certified;
      s = climb<true>(f, s >> 2, false);
      st[f] = s;
    }
    return s;
  }

  // ---- step 3: arcs of A ---------------------------------------------------
  ArcSigns signs(int ea, int eb) {
    ++ts_.arc_tests;
    ++stats_.edge_pairs;
    return k_.arc_signs(ea, eb);
  }
  // == signs(ea, eb).minkowski_face(), through the kernel's early-out form
  // when it has one (the same decision from the same values).
  SEPAX_TRAVERSAL_INLINE bool crosses(int ea, int eb) {
    if constexpr (HasMinkowskiFace<K>) {
      ++ts_.arc_tests;
      ++stats_.edge_pairs;
      return k_.minkowski_face(ea, eb);
    } else {
      return signs(ea, eb).minkowski_face();
    }
  }

  // A strictly crossing pair: a candidate axis unless the edges are parallel.
  // Returns true on early out.
  bool pair(int ea, int eb) {
    if constexpr (HasEdgePairBelow<K>) {
      // Certainly below the best (so not parallel, and not separating): what
      // offer would conclude, without the unit axis and its bound.
      if (best_.pair_certainly_below(k_, ea, eb)) {
        ++stats_.minkowski_faces;
        return false;
      }
    }
    if (k_.edges_parallel(ea, eb)) return false;
    ++stats_.minkowski_faces;
    const auto s = k_.edge_separation(ea, eb);
    const Feature feat = Feature::edges(ea, eb);
    offer(s, feat);
    return stops_early(k_, s, feat, opt_);
  }

  // Arc ea against every arc of -B.  Returns true on early out.
  bool fallback(int ea) {
    ++ts_.fallback_arcs;
    for (int eb = 0; eb < wb_.edge_count(); ++eb) {
      if (crosses(ea, eb) && pair(ea, eb)) return true;
    }
    return false;
  }

  // sign(n_end . dB) for edge eb, from its ArcSigns (dB = head - tail).
  static int end_sign(const ArcSigns& s, bool forward) { return forward ? -s.bdc : -s.adc; }
  // sign(t . (x_other - x_v)) along edge e of B at v, t the path's tangent.
  int lower(int v, int e, const ArcSigns& s, bool forward) const {
    const int es = end_sign(s, forward);
    return wb_.edge_tail(e) == v ? es : -es;
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
  std::uint64_t cut_end_bounds(int base, std::uint64_t todo, const int* sa, const int* ef, std::int64_t& pruned) {
    std::uint64_t out = 0;
    std::int64_t evals = 0;  // heights of cut-off ends' vertices (as face_below_best counts them)
    for (; todo != 0; todo &= todo - 1) {
      const int i = std::countr_zero(todo);
      const int f0 = ef[2 * (base + i)], f1 = ef[2 * (base + i) + 1];
      const int s0 = sa[f0], s1 = sa[f1];
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
  // along n is min_B n.b - n.a_tail <= n.(x - a_tail) for any vertex x of B.
  // With n = (a n0 + b n1)/|a n0 + b n1| (a, b >= 0), n0.(x - a_tail) =
  // height(f0, x) and n1.(x - a_tail) = height(f1, x) (a_tail lies on both
  // faces), and |a n0 + b n1| <= a + b: if both heights are <= m <= 0 then
  // n.(x - a_tail) <= (a + b) m / |a n0 + b n1| <= m.  So when both heights
  // are exactly below a best that is <= 0, every Minkowski face on the arc
  // (its exact separation is the separation along its normal) is exactly
  // below the best, and the arc is skipped.  x: the vertex stored for f0 or f1.
  // All three decisions are exact (k.compare, k.sign), so policy::Robust
  // prunes exactly where exact arithmetic prunes.
  // A face whose climb was cut off has its stored vertex's height exactly
  // below an earlier best, hence below the current one: not asked again.
  SEPAX_TRAVERSAL_INLINE bool arc_below_best(int s0, int s1, int f0, int f1) {
    if (!prune_arcs_ || !best_nonpositive()) return false;
    const int x0 = s0 >> 2, x1 = s1 >> 2;
    if (!(s0 & kCertified)) {
      if (!(s1 & kCertified) && x0 == x1) return true;  // both known below, same x
      if (face_below_best<true>(f1, x0)) return true;   // x = x0
      return !(s1 & kCertified) && x1 != x0 && face_below_best<true>(f0, x1);  // x = x1
    }
    if (!(s1 & kCertified)) return face_below_best<true>(f0, x1);  // x = x1
    return face_below_best<true>(f0, x0) && face_below_best<true>(f1, x0);  // x = x0
  }

  SEPAX_TRAVERSAL_INLINE bool crossing_below_best(int f0, int f1, int v) {
    return prune_arcs_ && best_nonpositive() && face_below_best<true>(f0, v) && face_below_best<true>(f1, v);
  }

  // arc()'s bound with x = the support vertex of end f (certified state s;
  // cut: f was cut off before its late climb, so x is known below the best
  // under f), below f and the other end g; counts the pruned arc.
  bool support_bounds_arc(int f, bool cut, int s, int g) {
    const int x = s >> 2;
    if (!((cut || face_below_best<true>(f, x)) && face_below_best<true>(g, x))) return false;
    ++ts_.pruned_arcs;
    ++ts_.late_pruned_arcs;
    return true;
  }

  // Arc ea from face f0 to face f1 of A, not pruned by arc_below_best.
  //
  // Before the walk, the arc bound (arc_below_best) is tried again with the
  // support vertices the ends are climbed to: x = v0, f0's support, prunes
  // the arc when both heights of v0 are exactly below the best.  Below f0
  // that is known when f0 was cut off (v0 is at most as high there as the
  // cut-off vertex, which was below an earlier best), else asked; then below
  // f1.  If it prunes, f1 is not climbed.  Then likewise x = v1 (f1's
  // support) after f1's climb.  All exact decisions (face_below_best), taken
  // in the same order by every kernel.  At N = 256 (overlapping sphere
  // hulls) the walked arcs drop from ~12 to ~4 per query and the crossing
  // tests from 50 to 18.
  bool arc(FaceScratch& st, int ea, int f0, int f1) {
    const bool cut0 = !(st[f0] & kCertified), cut1 = !(st[f1] & kCertified);
    const bool bound = prune_arcs_ && best_nonpositive();
    int s0 = certify(st, f0);
    if (bound && support_bounds_arc(f0, cut0, s0, f1)) return false;
    int s1 = certify(st, f1);
    if (bound && support_bounds_arc(f1, cut1, s1, f0)) return false;
    bool forward;
    int v;
    if (!(s0 & kTie)) {
      forward = true;
      v = s0 >> 2;
    } else if (!(s1 & kTie)) {
      forward = false;
      v = s1 >> 2;
    } else if (!wa_.is_flat()) {
      forward = true;
      v = lex_start(f0, f1, s0 >> 2);
      if (v < 0) return fallback(ea);
    } else {
      return fallback(ea);
    }
    const int fe = forward ? f1 : f0;
    const int se = forward ? s1 : s0;
    const int end_vertex = se >> 2;
    const bool end_tie = (se & kTie) != 0;
    Separation<T> end_h;
    bool have_end_h = false;
    int entry = -1;
    for (int budget = wb_.vertex_count() + wb_.edge_count() + 2; budget > 0; --budget) {
      // The end of the arc is in v's closed region (v is the deepest vertex
      // for the end face, unique without a tie): no crossing is left.
      if (v == end_vertex) return false;
      // The fan arc the path leaves v's region through.
      int exit_edge = -1;
      for (int i = wb_.adj_begin(v); i < wb_.adj_end(v); ++i) {
        const int eb = wb_.adj_edge(i);
        if (eb == entry) continue;
        if (crosses(ea, eb)) {
          exit_edge = eb;
          v = wb_.adj_vertex(i);
          break;
        }
      }
      if (exit_edge >= 0) {
        // The crossing's normal n lies on the arc and B's support along it is
        // the crossed edge (both ends): its separation is n.(v - a_tail) for
        // the vertex v just entered, bounded as in arc_below_best.
        if (crossing_below_best(f0, f1, v)) {
          ++ts_.pruned_crossings;
        } else if (pair(ea, exit_edge)) {
          return true;
        }
        entry = exit_edge;
        continue;
      }
      // No arc crossed strictly.  With a tie at the end, v may be another
      // deepest vertex for the end face: then the end is in v's closed region
      // and the walk is over.  This is asked only after the exit scan: in
      // exact arithmetic a path that strictly leaves v's region cannot end in
      // its closure (a region meets a great circle in one arc shorter than pi,
      // and a flat B's lunes are met in one arc unless the circle passes
      // through B's poles, where no crossing is strict), so the order changes
      // nothing there; in plain float, where a tie is "equal after rounding",
      // it keeps the walk consistent with its own arc signs: a crossing the
      // arc test accepts is taken even when the heights at the end round to a
      // tie (nearly coplanar flat shapes, fuzz/corpus/35-...).
      if (end_tie) {
        if (!have_end_h) {
          end_h = height<true>(fe, end_vertex);
          have_end_h = true;
        }
        if (cmp<true>(fe, v, height<true>(fe, v), end_vertex, end_h) == 0) return false;
      }
      // Otherwise the path leaves through a corner.
      v = corner(ea, v, forward);
      if (v < 0) return fallback(ea);
      entry = -1;
    }
    return fallback(ea);
  }

  // The start region when the arc's start n(f0) lies on a region boundary:
  // the lexicographic minimum of (height over f0, height over f1) over B,
  // reached by descending over f1 inside the tie set of f0.  -1 when the path
  // runs along a boundary arc from the start (two regions qualify).
  int lex_start(int f0, int f1, int v) {
    ++ts_.lex_starts;
    Separation<T> h0 = height<true>(f0, v), h1 = height<true>(f1, v);
    for (int budget = wb_.vertex_count() + 1; budget > 0; --budget) {
      bool moved = false, flat_tie = false;
      for (int i = wb_.adj_begin(v); i < wb_.adj_end(v); ++i) {
        const int u = wb_.adj_vertex(i);
        const Separation<T> u0 = height<true>(f0, u);
        if (cmp<true>(f0, u, u0, v, h0) != 0) continue;
        const Separation<T> u1 = height<true>(f1, u);
        const int c = cmp<true>(f1, u, u1, v, h1);
        if (c < 0) {
          v = u;
          h0 = u0;
          h1 = u1;
          moved = true;
          break;
        }
        if (c == 0) flat_tie = true;
      }
      if (!moved) return flat_tie ? -1 : v;
    }
    return -1;
  }

  // The path leaves v's region through a Gauss-map vertex -n(g), g a face of B
  // at v.  Returns the vertex whose region the path enters, or -1 when the
  // exit corner is not unique.
  int corner(int ea, int v, bool forward) {
    int found = -1, matches = 0;
    for (int i = wb_.adj_begin(v); i < wb_.adj_end(v); ++i) {
      const int h = wb_.adj_half_edge(i);  // v -> next vertex of face g
      const int e1 = h >> 1, e2 = wb_.prev(h) >> 1;
      const ArcSigns a1 = signs(ea, e1);
      const int g_sign = (h & 1) == 0 ? a1.cba : a1.dba;  // sign(n_g . eA)
      if (g_sign != 0) continue;
      const ArcSigns a2 = signs(ea, e2);
      const int l1 = lower(v, e1, a1, forward), l2 = lower(v, e2, a2, forward);
      if (l1 <= 0 && l2 <= 0 && (l1 < 0 || l2 < 0)) {
        ++matches;
        found = h;
      }
    }
    if (matches != 1) return -1;
    ++ts_.corner_passes;
    // Descend along the loop of g, in the direction the tangent decreases.
    const int h = found;
    int cur = v;
    int budget = wb_.vertex_count();
    if (lower(v, h >> 1, signs(ea, h >> 1), forward) < 0) {
      int hh = h;
      for (;;) {
        cur = wb_.origin(wb_.next(hh));
        hh = wb_.next(hh);
        if (--budget < 0) return -1;
        if (lower(cur, hh >> 1, signs(ea, hh >> 1), forward) >= 0) break;
      }
    } else {
      int hh = wb_.prev(h);  // ends at v
      for (;;) {
        cur = wb_.origin(hh);
        if (--budget < 0) return -1;
        const int hp = wb_.prev(hh);
        if (lower(cur, hp >> 1, signs(ea, hp >> 1), forward) >= 0) break;
        hh = hp;
      }
    }
    return cur;
  }

  K& k_;
  const GaussMapWalk& wa_;
  const GaussMapWalk& wb_;
  const SatOptions& opt_;
  TraversalStats& ts_;
  const Feature* seed_;  // warm start (warm_start())
  const bool prune_arcs_;
  const bool plain_flat_;  // a flat shape (used with kRoundingDecisions only, see run())
  int seed_a_ = 0, seed_b_ = 0;  // root seeds of step 1 and 2 (from step 0)
  // The probe vertices' coordinates, one array per coordinate (kFast only):
  // probes_b_ of B (for faces of A), probes_a_ of A.  The lanes up to the
  // probe count rounded up to 4 (every lane deepest_probe() reads, for 4
  // float or 2 double lanes) are filled: those past the probe count repeat
  // probe 0, and `valid` has a bit for each real one.
  // (float for the other kernels, unused: no exact number objects per query)
  using LaneT = std::conditional_t<kFast, T, float>;
  struct ProbeLanes {
    alignas(16) LaneT x[GaussMapWalk::kMaxProbes], y[GaussMapWalk::kMaxProbes], z[GaussMapWalk::kMaxProbes];
    int count = 0;
    unsigned valid = 0;
  };
  static_assert(GaussMapWalk::kMaxProbes % 4 == 0 && GaussMapWalk::kMaxProbes < 32);
  ProbeLanes probes_a_, probes_b_;
  static void gather(ProbeLanes& pr, const GaussMapWalk& w, const ConvexPolyhedron<T>& p) {
    const auto& ids = w.probes();
    pr.count = static_cast<int>(ids.size());
    pr.valid = (1u << pr.count) - 1;
    if (pr.count == 0) return;
    const int filled = (pr.count + 3) / 4 * 4;
    for (int i = 0; i < filled; ++i) {
      const Vec3<T>& v = p.vertex(ids[static_cast<std::size_t>(i < pr.count ? i : 0)]);
      pr.x[i] = v[0];
      pr.y[i] = v[1];
      pr.z[i] = v[2];
    }
  }
  BestAxis<K> best_;
  double best_err_ = 0;  // k.error_bound of the best's feature (kBounded)
  double cut_a_ = 0, cut_b_ = 0;  // compare_width of a face of A / B against the best
  // face_below_best's thresholds (kFast; see set_thresholds())
  Thr lo_a_ = kNegInf, hi_a_ = kNegInf, lo_b_ = kNegInf, hi_b_ = kNegInf;
  int best_sign_ = 2;    // k.sign of the best, 2 = not known yet
  SatStats stats_;
};

}  // namespace detail

/// Traversal SAT with a kernel built for (A, B) and the walk data of A and B
/// (built from the same hulls or with_vertices/convert_from copies of them).
/// ts, when given, receives the walk's counters.
template <SatKernel K>
SatResult<typename K::FT> traversal_with(K& k, const GaussMapWalk& wa, const GaussMapWalk& wb,
                                         const SatOptions& opt = {}, TraversalStats* ts = nullptr,
                                         const Feature* seed = nullptr) {
  if (k.a().empty() || k.b().empty()) {
    throw InvalidInput(ErrorCode::TooFewPoints,
                       std::string("traversal: shape ") + (k.a().empty() ? "A" : "B") +
                           " is empty (a default-constructed ConvexPolyhedron)");
  }
  check_options(opt);
  wa.check_fits(k.a(), "A");
  wb.check_fits(k.b(), "B");
  TraversalStats local;
  detail::Traversal<K> t(k, wa, wb, opt, ts ? *ts : local, seed);
  return t.run();
}

/// Traversal SAT of A and B with precomputed walk data (no allocation per
/// query for float/double; see the header comment).
template <class Policy = policy::Plain, Number T>
SatResult<T> traversal(const ConvexPolyhedron<T>& a, const GaussMapWalk& wa, const ConvexPolyhedron<T>& b,
                       const GaussMapWalk& wb, const SatOptions& opt = {}) {
  kernel_t<Policy, T> k(a, b);
  return traversal_with(k, wa, wb, opt);
}

/// Traversal SAT of A and B (both in one frame) under a policy.  Builds the
/// walk data of both shapes on every call: keep GaussMapWalk objects and use
/// the overload above when a hull is queried more than once.
template <class Policy = policy::Plain, Number T>
SatResult<T> traversal(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b, const SatOptions& opt = {}) {
  const GaussMapWalk wa(a), wb(b);
  return traversal<Policy>(a, wa, b, wb, opt);
}

}  // namespace sepax::sat
