// sepax's float and double rows (rows.hpp names them).
#include <cstdio>
#include <memory>

#include <sepax/contact_manifold.hpp>
#include <sepax/transform.hpp>
#include <sepax/robust/robust_kernel.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_cache.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>

#include "rows.hpp"

namespace bench {

using namespace sepax;

std::size_t g_contact_points = 0;

namespace {

template <class R>
Out from_sat(const R& r) {
  Out o{r.overlap, r.separation_as_double(), false};
  o.feature = {static_cast<int>(r.feature.type), r.feature.a, r.feature.b};
  o.exact_fallbacks = r.stats.exact_fallbacks;
  return o;
}

const ConvexPolyhedron<double>& ad(const Cell& c, std::size_t i) {
  return c.pool->d[static_cast<std::size_t>(c.pairs[i].a)];
}
const GaussMapWalk& wa(const Cell& c, std::size_t i) {
  return c.pool->walk[static_cast<std::size_t>(c.pairs[i].a)];
}
const GaussMapWalk& wb(const Cell& c, std::size_t i) {
  return c.pool->walk[static_cast<std::size_t>(c.pairs[i].b)];
}

#if SEPAX_BENCH_PREPARED
const PreparedShape<float>& pa(const Cell& c, std::size_t i) {
  return *c.pool->prepared[static_cast<std::size_t>(c.pairs[i].a)];
}
const PreparedShape<float>& pb(const Cell& c, std::size_t i) {
  return *c.pool->prepared[static_cast<std::size_t>(c.pairs[i].b)];
}

SatOptions margin_options(const PairData& p) {
  SatOptions opt;
  opt.early_out = true;
  opt.margin = static_cast<decltype(opt.margin)>(p.margin);
  return opt;
}

// contact_manifold on prepared shapes at poses (world coordinates).
template <class S, class X, class R>
concept PosedManifold = requires(const S& s, const X& x, const R& r, const SatOptions& o) {
  contact_manifold(s, x, s, x, r, o);
};
constexpr bool kPosedManifold = PosedManifold<PreparedShape<float>, RigidTransform<float>, SatResult<float>>;

// The posed query of pair i, as an engine runs it: the robust traversal, then
// (with_manifold) the manifold unless the query stopped beyond the margin.
// (S is PreparedShape<float>: a template parameter so that the manifold call
// is only compiled where the posed contact_manifold exists.)
template <bool with_manifold, class S = PreparedShape<float>>
Out posed_query(const Cell& c, std::size_t i, const SatOptions& opt, SatCache<float>* cache) {
  const PairData& p = c.pairs[i];
  const S& a = pa(c, i);
  const S& b = pb(c, i);
  const auto r = sat::traversal<policy::Robust>(a, p.pose_a, b, p.pose_b, opt, cache);
  if constexpr (with_manifold && PosedManifold<S, RigidTransform<float>, SatResult<float>>) {
    if (!r.early_out) {
      const auto m = contact_manifold(a, p.pose_a, b, p.pose_b, r, opt);
      g_contact_points += static_cast<std::size_t>(m.size());
    }
  }
  return from_sat(r);
}

// The posed rows: with or without the margin and a per-trajectory cache; the
// manifold rows when the posed contact_manifold is there.
void add_posed_rows(Cell& c, std::vector<Row>& rows, bool with_margin, bool with_cache) {
  const Cell* cp = &c;
  auto add = [&](std::string name, std::function<Out(std::size_t)> f) {
    rows.push_back(Row{std::move(name), "sepax", std::move(f)});
  };
  if (!with_margin) {
    add("traversal float posed",
        [cp](std::size_t i) { return posed_query<false>(*cp, i, SatOptions{}, nullptr); });
    if (kPosedManifold)
      add("traversal+manifold float posed",
          [cp](std::size_t i) { return posed_query<true>(*cp, i, SatOptions{}, nullptr); });
    return;
  }
  add("traversal float posed margin",
      [cp](std::size_t i) { return posed_query<false>(*cp, i, margin_options(cp->pairs[i]), nullptr); });
  if (kPosedManifold)
    add("traversal+manifold float posed margin",
        [cp](std::size_t i) { return posed_query<true>(*cp, i, margin_options(cp->pairs[i]), nullptr); });
  if (!with_cache) return;
  // One cache per trajectory, reset at its first frame: every pass replays the
  // trajectories from a cold cache, then warm step to step.
  const auto frames = static_cast<std::size_t>(c.frames);
  auto caches = std::make_shared<std::vector<SatCache<float>>>(c.pairs.size() / frames);
  auto cache_of = [caches, frames](std::size_t i) -> SatCache<float>* {
    auto& k = (*caches)[i / frames];
    if (i % frames == 0) k = SatCache<float>{};
    return &k;
  };
  add("traversal float posed margin cached", [cp, cache_of](std::size_t i) {
    return posed_query<false>(*cp, i, margin_options(cp->pairs[i]), cache_of(i));
  });
  if (kPosedManifold)
    add("traversal+manifold float posed margin cached", [cp, cache_of](std::size_t i) {
      return posed_query<true>(*cp, i, margin_options(cp->pairs[i]), cache_of(i));
    });
}
#endif

}  // namespace

std::vector<Row> sepax_rows(Cell& c) {
  std::vector<Row> rows;
  Cell* cp = &c;
  const int n = c.n;
  const bool small = n <= 64;  // brute force: O(E^2 (V+F)), skipped beyond 64
  const bool trajectories = c.frames > 0;
  auto add = [&](std::string name, std::function<Out(std::size_t)> f) {
    rows.push_back(Row{std::move(name), "sepax", std::move(f)});
  };
  // pre-posed, robust (the baseline "traversal float" is in every cell)
  add("traversal float", [cp](std::size_t i) {
    return from_sat(sat::traversal<policy::Robust>(local_a(*cp, i), wa(*cp, i), cp->pairs[i].bf, wb(*cp, i)));
  });
  if (trajectories) {
#if SEPAX_BENCH_PREPARED
    add_posed_rows(c, rows, true, true);
#endif
    if (c.poses == "moving") {
      add("traversal float plain early-out", [cp](std::size_t i) {
        SatOptions opt;
        opt.early_out = true;
        return from_sat(sat::traversal(local_a(*cp, i), wa(*cp, i), cp->pairs[i].bf, wb(*cp, i), opt));
      });
    }
    return rows;
  }
  if (small)
    add("brute float", [cp](std::size_t i) {
      return from_sat(sat::brute_force<policy::Robust>(local_a(*cp, i), cp->pairs[i].bf));
    });
  add("gauss float", [cp](std::size_t i) {
    return from_sat(sat::gauss_map<policy::Robust>(local_a(*cp, i), cp->pairs[i].bf));
  });
  add("traversal+manifold float", [cp](std::size_t i) {
    const auto& a = local_a(*cp, i);
    const auto& b = cp->pairs[i].bf;
    const auto r = sat::traversal<policy::Robust>(a, wa(*cp, i), b, wb(*cp, i));
    const auto m = contact_manifold(a, b, r);
    g_contact_points += static_cast<std::size_t>(m.size());
    return from_sat(r);
  });
#if SEPAX_BENCH_PREPARED
  add_posed_rows(c, rows, false, false);
  add_posed_rows(c, rows, true, false);
#endif
  // pre-posed, plain
  if (small)
    add("brute float plain",
        [cp](std::size_t i) { return from_sat(sat::brute_force(local_a(*cp, i), cp->pairs[i].bf)); });
  add("gauss float plain",
      [cp](std::size_t i) { return from_sat(sat::gauss_map(local_a(*cp, i), cp->pairs[i].bf)); });
  add("traversal float plain", [cp](std::size_t i) {
    return from_sat(sat::traversal(local_a(*cp, i), wa(*cp, i), cp->pairs[i].bf, wb(*cp, i)));
  });
  // B's local shape posed inside the query by a transformed copy (allocation,
  // plane recomputation): what a query costs without prepared shapes
  add("traversal float plain +transformed copy", [cp](std::size_t i) {
    const auto& lb = local_b(*cp, i);
    const auto posed = lb.with_vertices(pose_vertices(lb, cp->pairs[i].rel));
    return from_sat(sat::traversal(local_a(*cp, i), wa(*cp, i), posed, wb(*cp, i)));
  });
  add("traversal+manifold float plain", [cp](std::size_t i) {
    const auto& a = local_a(*cp, i);
    const auto& b = cp->pairs[i].bf;
    const auto r = sat::traversal(a, wa(*cp, i), b, wb(*cp, i));
    const auto m = contact_manifold(a, b, r);
    g_contact_points += static_cast<std::size_t>(m.size());
    return from_sat(r);
  });
  // double, plain
  if (small)
    add("brute double plain",
        [cp](std::size_t i) { return from_sat(sat::brute_force(ad(*cp, i), cp->pairs[i].bd)); });
  add("gauss double plain",
      [cp](std::size_t i) { return from_sat(sat::gauss_map(ad(*cp, i), cp->pairs[i].bd)); });
  add("traversal double plain", [cp](std::size_t i) {
    return from_sat(sat::traversal(ad(*cp, i), wa(*cp, i), cp->pairs[i].bd, wb(*cp, i)));
  });
  return rows;
}

std::string traversal_counters(const Cell& c) {
  sat::TraversalStats sum;
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    sat::TraversalStats ts;
    kernel_t<policy::Plain, float> k(local_a(c, i), c.pairs[i].bf);
    (void)sat::traversal_with(k, wa(c, i), wb(c, i), SatOptions{}, &ts);
    sum.arc_tests += ts.arc_tests;
    sum.height_evals += ts.height_evals;
    sum.climb_steps += ts.climb_steps;
    sum.fallback_arcs += ts.fallback_arcs;
    sum.corner_passes += ts.corner_passes;
    sum.pruned_faces += ts.pruned_faces;
    sum.probe_checks += ts.probe_checks;
    sum.probe_pruned += ts.probe_pruned;
    sum.pruned_arcs += ts.pruned_arcs;
    sum.late_certified += ts.late_certified;
  }
  const double np = double(c.pairs.size());
  const auto& a0 = local_a(c, 0);
  char buf[600];
  std::snprintf(
      buf, sizeof buf,
      "  %-11s %-11s E_A=%-4d arc tests %9.1f  (E_A*E_B %d)  height evals %8.1f  climb %7.1f  "
      "fallback arcs %6.2f  corner passes %5.2f  pruned faces %6.1f (of %d; by a probe %5.1f of %5.1f)  "
      "pruned arcs %6.1f  late climbs %5.1f\n",
      c.workload.c_str(), c.poses.c_str(), a0.edge_count(), double(sum.arc_tests) / np,
      a0.edge_count() * c.pairs[0].bf.edge_count(), double(sum.height_evals) / np,
      double(sum.climb_steps) / np, double(sum.fallback_arcs) / np, double(sum.corner_passes) / np,
      double(sum.pruned_faces) / np, a0.face_count() + c.pairs[0].bf.face_count(),
      double(sum.probe_pruned) / np, double(sum.probe_checks) / np, double(sum.pruned_arcs) / np,
      double(sum.late_certified) / np);
  return buf;
}

}  // namespace bench
