// sepax/sat_traversal.hpp
//
// sat::traversal: the SAT as a walk over the overlaid Gauss maps of A and -B,
// with no support scan of every vertex.  Same result, feature and tie-break as
// sat::brute_force and sat::gauss_map (feature.hpp, best_axis.hpp).  Candidate
// axes are the vertices of the overlay: face normals of A and of B, and
// crossings of an arc of A with an arc of -B (Minkowski edge-edge faces).
//   0. start(): two faces near the direction between the shapes, a first best;
//   1. faces<true>(): every face of A, its support vertex climbed on B
//      (traversal_climb.hpp) from its parent face's, or pruned below the best
//      (traversal_pruning.hpp);
//   2. faces<false>(): every face of B likewise, climbing on A;
//   3. run()'s arc loop: every arc of A not pruned is walked across -B's
//      regions (traversal_arc_walk.hpp); then the side axes of flat shapes.
// The shared state (best, thresholds, counters) is traversal_state.hpp.
// Every number and sign goes through the kernel (SatKernel): exact for exact T
// and, under policy::Robust, the decisions exact arithmetic makes; with plain
// float the climb and the arc signs round, like sat::gauss_map.
// Allocation: see traversal() and traversal_with() below.
#pragma once

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "sat_cache.hpp"
#include "traversal_arc_walk.hpp"

namespace sepax::sat {

namespace detail {

// One traversal query: the layers above, and the loop that runs them.
template <SatKernel K>
class Traversal : public TraversalArcWalk<K> {
  using Base = TraversalArcWalk<K>;
  using Base::arc;
  using Base::arc_below_best;
  using Base::below_best;
  using Base::best_;
  using Base::best_nonpositive;
  using Base::cut_end_bounds;
  using Base::fallback;
  using Base::fast_height;
  using Base::gather;
  using Base::k_;
  using Base::kCertified;
  using Base::kFast;
  using Base::kRoundingDecisions;
  using Base::kTie;
  using Base::lo_a_;
  using Base::lo_b_;
  using Base::offer;
  using Base::opt_;
  using Base::plain_flat_;
  using Base::probes_a_;
  using Base::probes_b_;
  using Base::prune_arcs_;
  using Base::seed_;
  using Base::seed_a_;
  using Base::seed_b_;
  using Base::stats_;
  using Base::ts_;
  using Base::wa_;
  using Base::wb_;
  using typename Base::T;

 public:
  Traversal(K& k, const GaussMapWalk& wa, const GaussMapWalk& wb, const SatOptions& opt, TraversalStats& ts,
            const Feature* seed = nullptr)
      : Base(k, wa, wb, opt, ts, seed) {}

  SatResult<T> run() {
    const int fa = wa_.face_count(), fb = wb_.face_count();
    FaceScratch states(fa + fb);
    // states(f) for faces of A at [0, fa), for faces of B at [fa, fa + fb):
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
    if (faces<true>(states, 0)) return best_.result(k_, stats_, true);
    if (faces<false>(states, fa)) return best_.result(k_, stats_, true);
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
    const int* a_states = &states[0];  // faces of A (arc() updates them through states)
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
    const int* edge_faces = wa_.edge_faces();
    for (int base = 0; base < ne && !stop; base += 64) {
      const int end = ne - base < 64 ? ne : base + 64;
      // bit `kind` (a state's low two bits) is set for the kinds that equal
      // states settle: kCertified alone always, 0 (cut off) when prunable
      const unsigned kinds = (1u << kCertified) | (prune_arcs_ && best_nonpositive() ? 1u : 0u);
      std::uint64_t settled = 0;
      for (int ea = base; ea < end; ++ea) {
        const int s0 = a_states[edge_faces[2 * ea]], s1 = a_states[edge_faces[2 * ea + 1]];
        const unsigned skip = static_cast<unsigned>(s0 == s1) & (kinds >> (s0 & 3));
        settled |= static_cast<std::uint64_t>(skip) << (ea - base);
        pruned += skip & ~static_cast<unsigned>(s0 >> 1);  // kind 0 (kind kCertified has bit 1 set)
      }
      const std::uint64_t all = end - base == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << (end - base)) - 1;
      std::uint64_t todo = ~settled & all;
      if (kinds & 1u) todo &= ~cut_end_bounds(base, todo, a_states, edge_faces, pruned);
      for (; todo != 0; todo &= todo - 1) {
        const int ea = base + std::countr_zero(todo);
        const int f0 = wa_.edge_face(ea, 0), f1 = wa_.edge_face(ea, 1);
        const int s0 = a_states[f0], s1 = a_states[f1];
        if (s0 == s1) {
          if ((s0 & 3) == kCertified) continue;
          if ((s0 & 3) == 0 && prune_arcs_ && best_nonpositive()) {
            ++pruned;
            continue;
          }
        }
        if (arc_below_best(ea, s0, s1, f0, f1)) {
          ++pruned;
          continue;
        }
        if (arc(states, ea, f0, f1)) {
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
  // Step 0: a good first candidate.
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
    const int p = this->template deepest_probe<true>(fa);
    int s = this->template climb<true>(fa, p >= 0 ? p : 0, false);
    seed_a_ = s >> 2;
    if (offer_face<true>(fa, seed_a_)) return true;
    s = this->template climb<false>(fb, va, true);
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
    ++(ty == FeatureType::EdgePair                            ? stats_.edge_pairs
       : ty == FeatureType::FaceA || ty == FeatureType::FaceB ? stats_.face_axes
                                                              : stats_.side_axes);
    if (ty == FeatureType::EdgePair) ++stats_.minkowski_faces;
    offer(ev->second, ev->first);
    return stops_early(k_, ev->second, ev->first, opt_);
  }

  // Offer face f with its support vertex v; true on early out.
  template <bool OfA>
  bool offer_face(int f, int v) {
    const Feature feat = this->template face_feature<OfA>(f, v);
    const Separation<T> h = this->template height<OfA>(f, v);
    offer(h, feat);
    return stops_early(k_, h, feat, opt_);
  }

  // Steps 1 and 2: support vertices of all faces of A (OfA) or of B, in
  // breadth-first order over face adjacency (GaussMapWalk), each climbed
  // (climb()) on the other shape's vertex graph from its parent face's vertex
  // with the cutoff; the root face from the support vertex step 0 found.
  // Each face tries its seed, then the probes (probe_below_best()), then
  // climbs.  On large shapes (long face chunks, GaussMapWalk::face_chunks())
  // the seed tests of a chunk are taken in one pass without a branch on their
  // outcome (no face's parent is in its chunk, so the seeds are final), then
  // the faces not certainly below go on one by one, with the same decisions
  // as the one-face loop of small shapes.
  template <bool OfA>
  bool faces(FaceScratch& states, int base) {
    const GaussMapWalk& w = OfA ? wa_ : wb_;
    const int* order = w.face_order().data();
    const int* parent = w.face_parent().data();
    const int nf = static_cast<int>(w.face_order().size());  // every face (BFS of a connected map)
    if constexpr (kFast) {
      const Plane<T>* planes = (OfA ? k_.a() : k_.b()).planes().data();
      const Vec3<T>* vs = (OfA ? k_.b() : k_.a()).vertices().data();
      std::int64_t pruned = 0;
      bool stop = false;
      int* shape_states = &states[base];  // this shape's per-face states
      const std::vector<int>& chunks = w.face_chunks();
      const int nc = static_cast<int>(chunks.size()) - 1;
      int i = 0;  // the last face processed when stopped
      if (nf < kTraversalMinMeanChunk * nc) {
        // Short chunks (small shapes): one face at a time.
        for (; i < nf; ++i) {
          const int f = order[i];
          // the BFS root (i = 0, parent -1) is seeded by step 0
          const int seed = i > 0 ? shape_states[parent[i]] >> 2 : OfA ? seed_a_ : seed_b_;
          // most faces stop at their seed: decided here, without a call
          const T h = fast_height(planes[f], vs[seed]);
          shape_states[f] = seed << 2;
          if (h < (OfA ? lo_a_ : lo_b_)) {
            ++pruned;
            continue;
          }
          if (beyond_seed<OfA>(shape_states, f, seed, h, pruned)) {
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
            const int seed = j > 0 ? shape_states[parent[j]] >> 2 : OfA ? seed_a_ : seed_b_;
            const T h = fast_height(planes[f], vs[seed]);
            shape_states[f] = seed << 2;
            fail |= static_cast<std::uint64_t>(!(h < lo)) << (j - b);
          }
          // Then the others, in order, with the current best.
          int last = e - 1;
          for (std::uint64_t todo = fail; todo != 0; todo &= todo - 1) {
            const int j = b + std::countr_zero(todo);
            const int f = order[j];
            const int seed = shape_states[f] >> 2;
            if (beyond_seed<OfA>(shape_states, f, seed, fast_height(planes[f], vs[seed]), pruned)) {
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
        const int seed = parent[i] >= 0 ? states[base + parent[i]] >> 2 : OfA ? seed_a_ : seed_b_;
        ++stats_.face_axes;
        // the same decisions in the same order as the fast path: the seed,
        // the probes, then the climb
        if (below_best(this->template height<OfA>(f, seed), this->template face_feature<OfA>(f, seed))) {
          states[base + f] = seed << 2;
          ++ts_.pruned_faces;
          continue;
        }
        if (const int p = this->template probe_below_best<OfA>(f, seed); p >= 0) {
          states[base + f] = p << 2;
          ++ts_.pruned_faces;
          ++ts_.probe_pruned;
          continue;
        }
        const int s = this->template climb<OfA>(f, seed, true, false);
        states[base + f] = s;
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
  // between the thresholds), then the probes, then the climb.  Sets shape_states[f]
  // (already seed << 2) and counts pruned faces; true on early out.
  template <bool OfA>
  bool beyond_seed(int* shape_states, int f, int seed, T h, std::int64_t& pruned) {
    if (this->template face_below_best<OfA>(f, seed, h)) {
      ++pruned;
      return false;
    }
    if (const int p = this->template probe_below_best<OfA>(f, seed); p >= 0) {
      shape_states[f] = p << 2;
      ++pruned;
      ++ts_.probe_pruned;
      return false;
    }
    const int s = this->template climb<OfA>(f, seed, true, false);
    shape_states[f] = s;
    if (!(s & kCertified)) {
      ++pruned;
      return false;
    }
    return offer_face<OfA>(f, s >> 2);
  }
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
    throw InvalidInput(ErrorCode::TooFewPoints, std::string("traversal: shape ") +
                                                    (k.a().empty() ? "A" : "B") +
                                                    " is empty (a default-constructed ConvexPolyhedron)");
  }
  check_options(opt);
  wa.check_fits(k.a(), "A");
  wb.check_fits(k.b(), "B");
  TraversalStats local;
  detail::Traversal<K> t(k, wa, wb, opt, ts ? *ts : local, seed);
  return t.run();
}

/// Traversal SAT of A and B with precomputed walk data.  It does not
/// allocate for hulls with up to kTraversalInlineFaces faces in total
/// (per-face scratch on the stack); with float/double it allocates nothing
/// at all per query.
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
SatResult<T> traversal(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b,
                       const SatOptions& opt = {}) {
  const GaussMapWalk wa(a), wb(b);
  return traversal<Policy>(a, wa, b, wb, opt);
}

}  // namespace sepax::sat
