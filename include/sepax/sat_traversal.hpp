// sepax/sat_traversal.hpp
//
// sat::traversal: the SAT as a walk over the overlaid Gauss maps of A and -B,
// with one support scan per query.  Same result, feature and tie-break as
// sat::brute_force and sat::gauss_map (feature.hpp, best_axis.hpp).
//
// Candidate axes are the vertices of the overlay: face normals of A, face
// normals of B, and crossings of an arc of A with an arc of -B (Minkowski
// edge-edge faces).  The walk finds all of them without a support scan per
// face:
//
//  1. Faces of A, in breadth-first order over face adjacency (GaussMapWalk):
//     the support vertex of B for the root face comes from the one full
//     support scan (k.face_query_a); every other face's support vertex is
//     found by hill-climbing on B's vertex graph from its parent face's
//     support vertex, comparing heights above the face exactly
//     (k.compare of k.face_separation_a(f, v) for neighbouring v).  A linear
//     function on a convex polytope has no local minimum that is not global,
//     so the climb ends at a deepest vertex; when the deepest set is larger
//     than one vertex (a tie: an edge or face of B) it is searched for the
//     lowest index, the tie-break every SAT uses.
//  2. Faces of B likewise, hill-climbing on A (seeded from A's vertex 0).
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
#include <cstdint>
#include <vector>

#include "best_axis.hpp"
#include "gauss_map_walk.hpp"
#include "plain_kernel.hpp"

namespace sepax::sat {

/// Total faces (A + B) the traversal keeps per-face scratch for on the stack.
inline constexpr int kTraversalInlineFaces = 1024;

/// Counters of one traversal query (beyond SatStats), for tests and tuning.
struct TraversalStats {
  std::int64_t support_scans = 0;     // full support scans (k.face_query_*): 1
  std::int64_t climb_steps = 0;       // hill-climb moves
  std::int64_t height_evals = 0;      // k.face_separation_* calls
  std::int64_t arc_tests = 0;         // k.arc_signs calls
  std::int64_t corner_passes = 0;     // walks through a Gauss-map vertex of -B
  std::int64_t lex_starts = 0;        // arcs started by the lexicographic rule
  std::int64_t fallback_arcs = 0;     // arcs tested against every arc of -B
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
            TraversalStats& ts)
      : k_(k), wa_(wa), wb_(wb), opt_(opt), ts_(ts) {}

  SatResult<T> run() {
    const int fa = wa_.face_count(), fb = wb_.face_count();
    FaceScratch scratch(fa + fb);
    // sup(f) for faces of A at [0, fa), for faces of B at [fa, fa + fb):
    // (support vertex << 1) | tie.
    if (faces<true>(scratch, 0)) return best_.result(k_, stats_, true);
    if (faces<false>(scratch, fa)) return best_.result(k_, stats_, true);
    for (int ea = 0; ea < wa_.edge_count(); ++ea) {
      if (arc(scratch, ea)) return best_.result(k_, stats_, true);
    }
    if (scan_side_axes(k_, best_, stats_, opt_)) return best_.result(k_, stats_, true);
    return best_.result(k_, stats_, false);
  }

 private:
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

  struct Support {
    int vertex;
    Separation<T> sep;
    bool tie;
  };

  // Deepest vertex of the other shape below face f, from seed, by hill climb;
  // the lowest index among exactly deepest ones, and whether there was a tie.
  template <bool OfA>
  Support climb(int f, int seed) {
    const GaussMapWalk& w = OfA ? wb_ : wa_;
    int v = seed;
    Separation<T> hv = height<OfA>(f, v);
    int budget = w.vertex_count() + 1;
    for (;;) {
      bool moved = false, tie = false;
      for (int i = w.adj_begin(v); i < w.adj_end(v); ++i) {
        const int u = w.adj_vertex(i);
        const Separation<T> hu = height<OfA>(f, u);
        const int c = cmp<OfA>(f, u, hu, v, hv);
        if (c < 0) {
          v = u;
          hv = hu;
          moved = true;
          break;
        }
        if (c == 0) tie = true;
      }
      if (!moved) {
        // The far vertices of v's non-triangular faces (not neighbours of v):
        // on an exactly convex polytope none is strictly lower, but a face
        // that is planar only up to rounding (the exact image of a rotated
        // float box) can dip below v at a far vertex.
        for (int i = w.adj_begin(v); i < w.adj_end(v) && !moved; ++i) {
          const int h = w.adj_half_edge(i);
          for (int g = w.next(w.next(h)); w.next(g) != h; g = w.next(g)) {
            const int x = w.origin(g);
            const Separation<T> hx = height<OfA>(f, x);
            if (cmp<OfA>(f, x, hx, v, hv) < 0) {
              v = x;
              hv = hx;
              moved = true;
              break;
            }
          }
        }
      }
      if (moved) {
        ++ts_.climb_steps;
        if (--budget < 0) return scan<OfA>(f);  // inconsistent rounding only
        continue;
      }
      if (!tie) return Support{v, hv, false};
      return Support{lowest_tied<OfA>(f, v, hv), hv, true};
    }
  }

  // Only reached when rounding made the climb cycle (never for exact
  // decisions): a full support scan.
  template <bool OfA>
  Support scan(int f) {
    ++ts_.support_scans;
    const auto q = OfA ? k_.face_query_a(f) : k_.face_query_b(f);
    return Support{q.support_vertex, q.separation, true};
  }

  // The deepest set through v is a face of the other polytope containing v
  // (a vertex, an edge, or a polygon): v's tied neighbours and, for a polygon,
  // the loop of the face that contains it.  Returns its lowest vertex index.
  template <bool OfA>
  int lowest_tied(int f, int v, const Separation<T>& hv) {
    const GaussMapWalk& w = OfA ? wb_ : wa_;
    auto tied = [&](int u) { return cmp<OfA>(f, u, height<OfA>(f, u), v, hv) == 0; };
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

  // Steps 1 and 2: support vertices of all faces of A (OfA) or of B.
  template <bool OfA>
  bool faces(FaceScratch& sup, int base) {
    const GaussMapWalk& w = OfA ? wa_ : wb_;
    const auto& order = w.face_order();
    const auto& parent = w.face_parent();
    for (std::size_t i = 0; i < order.size(); ++i) {
      const int f = order[i];
      int seed;
      if (parent[i] >= 0) {
        seed = sup[base + parent[i]] >> 1;
      } else if (OfA) {
        ++ts_.support_scans;
        seed = k_.face_query_a(f).support_vertex;
      } else {
        seed = 0;
      }
      const Support s = climb<OfA>(f, seed);
      sup[base + f] = (s.vertex << 1) | (s.tie ? 1 : 0);
      ++stats_.face_axes;
      const Feature feat = face_feature<OfA>(f, s.vertex);
      best_.consider(k_, s.sep, feat);
      if (opt_.early_out && k_.sign(s.sep, feat) > 0) return true;
    }
    return false;
  }

  // ---- step 3: arcs of A ---------------------------------------------------
  ArcSigns signs(int ea, int eb) {
    ++ts_.arc_tests;
    ++stats_.edge_pairs;
    return k_.arc_signs(ea, eb);
  }

  // A strictly crossing pair: a candidate axis unless the edges are parallel.
  // Returns true on early out.
  bool pair(int ea, int eb) {
    if (k_.edges_parallel(ea, eb)) return false;
    ++stats_.minkowski_faces;
    const auto s = k_.edge_separation(ea, eb);
    const Feature feat = Feature::edges(ea, eb);
    best_.consider(k_, s, feat);
    return opt_.early_out && k_.sign(s, feat) > 0;
  }

  // Arc ea against every arc of -B.  Returns true on early out.
  bool fallback(int ea) {
    ++ts_.fallback_arcs;
    for (int eb = 0; eb < wb_.edge_count(); ++eb) {
      if (signs(ea, eb).minkowski_face() && pair(ea, eb)) return true;
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

  bool arc(FaceScratch& sup, int ea) {
    const int f0 = wa_.edge_face(ea, 0), f1 = wa_.edge_face(ea, 1);
    const int s0 = sup[f0], s1 = sup[f1];
    bool forward;
    int v;
    if (!(s0 & 1)) {
      forward = true;
      v = s0 >> 1;
    } else if (!(s1 & 1)) {
      forward = false;
      v = s1 >> 1;
    } else if (!wa_.is_flat()) {
      forward = true;
      v = lex_start(f0, f1, s0 >> 1);
      if (v < 0) return fallback(ea);
    } else {
      return fallback(ea);
    }
    const int fe = forward ? f1 : f0;
    const int se = forward ? s1 : s0;
    const int end_vertex = se >> 1;
    const bool end_tie = (se & 1) != 0;
    Separation<T> end_h;
    bool have_end_h = false;
    int entry = -1;
    for (int budget = wb_.vertex_count() + wb_.edge_count() + 2; budget > 0; --budget) {
      // The end of the arc is in v's closed region (v is a deepest vertex for
      // the end face): no crossing is left.  Without a tie the deepest vertex
      // is unique.
      if (v == end_vertex) return false;
      if (end_tie) {
        if (!have_end_h) {
          end_h = height<true>(fe, end_vertex);
          have_end_h = true;
        }
        if (cmp<true>(fe, v, height<true>(fe, v), end_vertex, end_h) == 0) return false;
      }
      // The fan arc the path leaves v's region through.
      int exit_edge = -1;
      for (int i = wb_.adj_begin(v); i < wb_.adj_end(v); ++i) {
        const int eb = wb_.adj_edge(i);
        if (eb == entry) continue;
        if (signs(ea, eb).minkowski_face()) {
          exit_edge = eb;
          v = wb_.adj_vertex(i);
          break;
        }
      }
      if (exit_edge >= 0) {
        if (pair(ea, exit_edge)) return true;
        entry = exit_edge;
        continue;
      }
      // No arc crossed strictly: the path leaves through a corner.
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
  BestAxis<K> best_;
  SatStats stats_;
};

}  // namespace detail

/// Traversal SAT with a kernel built for (A, B) and the walk data of A and B
/// (built from the same hulls or with_vertices/convert_from copies of them).
/// ts, when given, receives the walk's counters.
template <SatKernel K>
SatResult<typename K::FT> traversal_with(K& k, const GaussMapWalk& wa, const GaussMapWalk& wb,
                                         const SatOptions& opt = {}, TraversalStats* ts = nullptr) {
  if (k.a().empty() || k.b().empty()) {
    throw InvalidInput(ErrorCode::TooFewPoints,
                       std::string("traversal: shape ") + (k.a().empty() ? "A" : "B") +
                           " is empty (a default-constructed ConvexPolyhedron)");
  }
  wa.check_fits(k.a(), "A");
  wb.check_fits(k.b(), "B");
  TraversalStats local;
  detail::Traversal<K> t(k, wa, wb, opt, ts ? *ts : local);
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
