// sepax/traversal_climb.hpp
//
// Support vertices for the traversal (sat_traversal.hpp): the deepest vertex
// of the other shape below a face, without a scan of every vertex.
//   * climb(): hill climbing on the other shape's vertex graph from a seed.
//     A linear function on a convex polytope has no local minimum that is not
//     global, so the climb ends at a deepest vertex; a tie (an edge or face
//     exactly deepest) is searched for its lowest index (lowest_tied_with()),
//     the tie-break every SAT uses.  It stops early at a vertex below the best
//     (the cutoff), and certify() resumes it when the vertex is needed;
//   * the support order it climbs on (support_order()): the kernel's filtered
//     comparison of projections (support_cmp()) or its heights and compare();
//   * deepest_probe() and probe_below_best(): the deepest of a fixed list of
//     probe vertices, which seeds step 0 and prunes most faces before a climb;
//   * scan(): the full support scan, only when rounding makes a climb cycle.
// Built on traversal_pruning.hpp; traversal_arc_walk.hpp builds on it.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

#include "simd_lanes.hpp"
#include "traversal_pruning.hpp"

namespace sepax::sat::detail {

template <SatKernel K>
class TraversalClimb : public TraversalPruning<K> {
  using Base = TraversalPruning<K>;

 protected:
  using Base::Base;
  using Base::best_;
  using Base::k_;
  using Base::kCertified;
  using Base::kFast;
  using Base::kTie;
  using Base::probes_a_;
  using Base::probes_b_;
  using Base::ts_;
  using Base::wa_;
  using Base::wb_;
  using typename Base::ProbeLanes;
  using typename Base::T;

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
    TraversalClimb& t;
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
    TraversalClimb& t;
    int f;
    Key key(int x) const { return OfA ? t.k_.face_separation_a(f, x) : t.k_.face_separation_b(f, x); }
    int cmp(int u, const Key& ku, int v, const Key& kv) const { return t.template cmp<OfA>(f, u, ku, v, kv); }
    bool below_best(int v, const Key& kv) const {
      return t.below_best(kv, TraversalClimb::template face_feature<OfA>(f, v));
    }
  };
  template <bool OfA>
  auto support_order(int f) {
    if constexpr (kFast) {
      const Plane<T>& pl = (OfA ? k_.a() : k_.b()).plane(f);
      return FilteredOrder<OfA>{*this,     f,         (OfA ? k_.b() : k_.a()).vertices().data(),
                                pl.normal, pl.offset, filter<OfA>()};
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
    return this->template face_below_best<OfA>(f, p) ? p : -1;
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
      Separation<T> hm = this->template height<OfA>(f, m);
      for (std::size_t c = 1; c < ids.size(); ++c) {
        const int u = ids[c];
        const Separation<T> hu = this->template height<OfA>(f, u);
        if (this->template cmp<OfA>(f, u, hu, m, hm) < 0) {
          m = u;
          hm = hu;
        }
      }
      return m;
    }
  }

  // The support state of face f of A, climbed to the support vertex if the
  // cutoff stopped it.
  int certify(FaceScratch& states, int f) {
    int s = states[f];
    if (!(s & kCertified)) {
      ++ts_.late_certified;
      s = climb<true>(f, s >> 2, false);
      states[f] = s;
    }
    return s;
  }
};

}  // namespace sepax::sat::detail
