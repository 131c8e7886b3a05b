// sepax/traversal_arc_walk.hpp
//
// Step 3 of the traversal (sat_traversal.hpp): the arcs of A (its edges on the
// Gauss map) walked across the regions of -B's Gauss map, which finds every
// Minkowski edge-edge face without testing every pair of edges.
//   * arc(): the walk of one arc, from the region of its start face's support
//     vertex, crossing fan arcs (crosses(), then pair() for the crossing's
//     edge pair) until the region that holds the arc's end;
//   * corner(): the path leaves a region through a Gauss-map vertex of -B;
//   * lex_start(): the arc starts on a region boundary (a tie in step 1);
//   * fallback(): the arc against every arc of -B, for whatever the rules
//     above cannot decide.
// Degenerate cases are decided by the same kernel signs as the rest, so the
// robust walk takes the exact walk's path.
// Built on traversal_climb.hpp; sat_traversal.hpp builds on it.
#pragma once

#include "traversal_climb.hpp"

namespace sepax::sat::detail {

template <SatKernel K>
class TraversalArcWalk : public TraversalClimb<K> {
  using Base = TraversalClimb<K>;

 protected:
  using Base::Base;
  using Base::best_;
  using Base::best_nonpositive;
  using Base::certify;
  using Base::crossing_below_best;
  using Base::k_;
  using Base::kCertified;
  using Base::kTie;
  using Base::offer;
  using Base::opt_;
  using Base::prune_arcs_;
  using Base::rest_below_best;
  using Base::stats_;
  using Base::support_bounds_arc;
  using Base::ts_;
  using Base::wa_;
  using Base::wb_;
  using typename Base::T;

  // One Minkowski-face test of arc ea of A against arc eb of -B.
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
  // Returns true on early out; below: whether the pair's separation is
  // exactly below the best (false for parallel edges), the same decision
  // for every kernel.
  bool pair(int ea, int eb, bool& below) {
    below = false;
    if constexpr (HasEdgePairBelow<K>) {
      // Certainly below the best (so not parallel, and not separating): what
      // offer would conclude, without the unit axis and its bound.
      if (best_.pair_certainly_below(k_, ea, eb)) {
        ++stats_.minkowski_faces;
        below = true;
        return false;
      }
    }
    if (k_.edges_parallel(ea, eb)) return false;
    ++stats_.minkowski_faces;
    const auto s = k_.edge_separation(ea, eb);
    const Feature feat = Feature::edges(ea, eb);
    below = offer(s, feat);
    return stops_early(k_, s, feat, opt_);
  }
  bool pair(int ea, int eb) {
    bool below;
    return pair(ea, eb, below);
  }

  // Arc ea against every arc of -B (O(E_B), what sat::gauss_map does per
  // arc).  Returns true on early out.  The walk of one arc falls back to it
  // for anything its rules cannot decide: both ends of an arc of a flat A on
  // region boundaries; the path passing through a Gauss vertex of a flat B,
  // where both corners of a lune are on the arc; more than one candidate
  // exit; a step budget of V + E of B exhausted.  Pairs found twice are
  // harmless (BestAxis keeps the first of equal candidates).
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

  // Arc ea from face f0 to face f1 of A, not pruned by arc_below_best.
  // Edge eA is the arc from n(f0) to n(f1).  The walk starts in the region of
  // -B's Gauss map that contains the start of the arc (the region of B's
  // support vertex for f0, known from step 1) and carries that region along
  // the arc: in the region of vertex v it looks, among the arcs of v's fan,
  // for the one the path leaves through -- the one arc whose Minkowski-face
  // test (k.arc_signs) is strict.  Crossing it is a Minkowski edge-edge face
  // (measured with k.edge_separation in O(1)) and moves the walk to the other
  // end of that edge of B.  The walk stops when v is a deepest vertex for f1
  // (the end of the arc lies in v's closed region).  A convex region is left
  // at most once by a great-circle arc, so every crossing is found exactly
  // once and the walk moves monotonically along the arc.  The start of an
  // arc on the boundary of a region (a tie in step 1): the walk starts from
  // the other end if that end is clean, else (solid A) at lex_start().
  // Every step moves strictly forward along a finite arc, and every loop has
  // a budget, so the walk terminates for any input and any kernel.
  //
  // Before the walk, the arc bound (arc_below_best) is tried again with the
  // support vertices the ends are climbed to: x = v0, f0's support, prunes
  // the arc when both heights of v0 are exactly below the best and v0 is not
  // strictly inside the edge's wedge (implied with a best <= 0).  Below f0
  // that is known when f0 was cut off (v0 is at most as high there as the
  // cut-off vertex, which was below an earlier best), else asked; then below
  // f1.  If it prunes, f1 is not climbed.  Then likewise x = v1 (f1's
  // support) after f1's climb.  All exact decisions (face_below_best,
  // in_edge_wedge_a), taken in the same order by every kernel.  At N = 256
  // (overlapping sphere hulls) the walked arcs drop from ~12 to ~4 per query
  // and the crossing tests from 50 to 18.
  bool arc(FaceScratch& states, int ea, int f0, int f1) {
    const bool cut0 = !(states[f0] & kCertified), cut1 = !(states[f1] & kCertified);
    const bool bound = prune_arcs_ && best_.has();
    int s0 = certify(states, f0);
    if (bound && support_bounds_arc(ea, f0, cut0, s0, f1)) return false;
    int s1 = certify(states, f1);
    if (bound && support_bounds_arc(ea, f1, cut1, s1, f0)) return false;
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
        // the vertex v just entered.  When v's heights over both end faces
        // are exactly below the best and v is outside the edge's wedge,
        // arc_below_best's bound with x = v holds
        // for every n on the arc, not only this crossing's: every Minkowski
        // face left on the arc is exactly below the best, and the walk ends.
        if (crossing_below_best(ea, f0, f1, v)) {
          ++ts_.pruned_crossings;
          return false;
        }
        bool below;
        if (pair(ea, exit_edge, below)) return true;
        // This crossing below the best bounds the rest of the walk with v.
        if (below && rest_below_best(ea, fe, v)) {
          ++ts_.pruned_crossings;
          ++ts_.pruned_rest;
          return false;
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
          end_h = this->template height<true>(fe, end_vertex);
          have_end_h = true;
        }
        if (this->template cmp<true>(fe, v, this->template height<true>(fe, v), end_vertex, end_h) == 0)
          return false;
      }
      // Otherwise the path leaves through a corner.
      v = corner(ea, v, forward);
      if (v < 0) return fallback(ea);
      entry = -1;
    }
    return fallback(ea);
  }

  // The start region when the arc's start n(f0) lies on a region boundary
  // (and so does its end): the lexicographic minimum of (height over f0,
  // height over f1) over B, which is the region the path enters, reached by
  // descending over f1 inside the tie set of f0.  -1 when the path
  // runs along a boundary arc from the start (two regions qualify).
  int lex_start(int f0, int f1, int v) {
    ++ts_.lex_starts;
    Separation<T> h0 = this->template height<true>(f0, v), h1 = this->template height<true>(f1, v);
    for (int budget = wb_.vertex_count() + 1; budget > 0; --budget) {
      bool moved = false, flat_tie = false;
      for (int i = wb_.adj_begin(v); i < wb_.adj_end(v); ++i) {
        const int u = wb_.adj_vertex(i);
        const Separation<T> u0 = this->template height<true>(f0, u);
        if (this->template cmp<true>(f0, u, u0, v, h0) != 0) continue;
        const Separation<T> u1 = this->template height<true>(f1, u);
        const int c = this->template cmp<true>(f1, u, u1, v, h1);
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
  // exit corner is not unique.  The path passes a face g of B whose normal
  // lies on the arc (e.g. boxes against boxes): no fan arc is strictly
  // crossed; the exit corner is the face g of v with sign(n_g . eA) == 0
  // whose two fan arcs both have the rest of the path on the far side (or on
  // the arc's plane, when the path runs along an arc).  The region entered is
  // the vertex of g lowest along the path's tangent; the sign of the tangent
  // against each edge of g is the ArcSigns sign of the arc's end normal
  // (valid because the corner lies strictly inside the arc).  The
  // Minkowski-face test is not strict for g's edges, exactly as in
  // sat::gauss_map, so no pair is reported there.
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
};

}  // namespace sepax::sat::detail
