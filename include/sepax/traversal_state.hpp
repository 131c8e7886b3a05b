// sepax/traversal_state.hpp
//
// What one traversal query (sat_traversal.hpp) keeps while it walks:
//   * kTraversalInlineFaces, TraversalStats (the walk's counters) and
//     FaceScratch (per-face support states, on the stack for small shapes);
//   * TraversalState<K>: the kernel, both shapes' walk data, the options,
//     the best candidate so far and its thresholds, the probe vertices in
//     SIMD lanes (gather()), the per-face state bits, the kernel
//     capabilities the walk asks for, and the heights of vertices above
//     faces (height(), cmp()).
// The layers built on it, each a class deriving from the one before:
//   traversal_pruning.hpp   what the best so far rules out (faces, arcs);
//   traversal_climb.hpp     support vertices by hill climbing, probes;
//   traversal_arc_walk.hpp  step 3, the walk along the arcs of A;
//   sat_traversal.hpp       the query itself and the public entry points.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "best_axis.hpp"
#include "gauss_map_walk.hpp"
#include "plain_kernel.hpp"

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
  std::int64_t pruned_crossings = 0;  // arc walks ended at a crossing below the best
  std::int64_t pruned_rest = 0;       // of them, by the bound on the rest of the walk
  std::int64_t wedge_tests = 0;       // k.in_edge_wedge_a calls (arc bounds with a best > 0)
};

namespace detail {

// Per-face int scratch (the support states): on the stack up to
// kTraversalInlineFaces, else heap.
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

// The state of one query and the heights every layer asks for.  Built by
// the Traversal at the top of the layers (sat_traversal.hpp), which inherits
// this constructor.
template <SatKernel K>
class TraversalState {
 protected:
  using T = typename K::FT;

  TraversalState(K& k, const GaussMapWalk& wa, const GaussMapWalk& wb, const SatOptions& opt,
                 TraversalStats& ts, const Feature* seed = nullptr)
      : k_(k),
        wa_(wa),
        wb_(wb),
        opt_(opt),
        ts_(ts),
        seed_(seed),
        prune_arcs_(!wa.is_flat()),
        plain_flat_(wa.is_flat() || wb.is_flat()) {}

  // face_below_best's threshold type (T for float/double; unused otherwise).
  using Threshold = std::conditional_t<std::is_floating_point_v<T>, T, float>;
  static constexpr Threshold kNegInf = -std::numeric_limits<Threshold>::infinity();

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

  K& k_;
  const GaussMapWalk& wa_;
  const GaussMapWalk& wb_;
  const SatOptions& opt_;
  TraversalStats& ts_;
  const Feature* seed_;  // warm start (warm_start())
  const bool prune_arcs_;
  const bool plain_flat_;        // a flat shape (used with kRoundingDecisions only, see run())
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
  double best_err_ = 0;           // k.error_bound of the best's feature (kBounded)
  double cut_a_ = 0, cut_b_ = 0;  // compare_width of a face of A / B against the best
  // face_below_best's thresholds (kFast; see set_thresholds())
  Threshold lo_a_ = kNegInf, hi_a_ = kNegInf, lo_b_ = kNegInf, hi_b_ = kNegInf;
  int best_sign_ = 2;  // k.sign of the best, 2 = not known yet
  SatStats stats_;
};

}  // namespace detail

}  // namespace sepax::sat
