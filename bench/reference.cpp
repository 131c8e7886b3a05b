// The exact reference and sepax's rows in mpq_class.
#include "reference.hpp"

#include <memory>

#include <sepax/robust/number_types.hpp>

#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>

#include "rows.hpp"

namespace bench {

using namespace sepax;
using Q = mpq_class;

namespace {

// Exact rows run on this many pairs: they are slow.
constexpr std::size_t kExactPairs = 16;

struct ExactImages {
  std::vector<ConvexPolyhedron<Q>> a;  // per pool shape
  std::vector<ConvexPolyhedron<Q>> b;  // per pair (a prefix of the pairs)
};

std::shared_ptr<ExactImages> exact_images(const Cell& c, std::size_t pairs) {
  auto x = std::make_shared<ExactImages>();
  for (const auto& s : c.pool->shapes) x->a.push_back(ConvexPolyhedron<Q>::convert_from(s.f));
  for (std::size_t i = 0; i < std::min(pairs, c.pairs.size()); ++i)
    x->b.push_back(ConvexPolyhedron<Q>::convert_from(c.pairs[i].bf));
  return x;
}

template <class R>
Out exact_out(const R& r) {
  Out o{r.overlap, r.separation_as_double(), false};
  o.feature = {static_cast<int>(r.feature.type), r.feature.a, r.feature.b};
  return o;
}

}  // namespace

void compute_reference(Cell& c) {
  const auto x = exact_images(c, c.pairs.size());
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    auto& p = c.pairs[i];
    const auto ia = static_cast<std::size_t>(p.a), ib = static_cast<std::size_t>(p.b);
    const auto r = sat::traversal(x->a[ia], c.pool->walk[ia], x->b[i], c.pool->walk[ib]);
    p.ref_overlap = r.overlap;
    p.ref_sep = r.separation_as_double();
#if SEPAX_BENCH_PREPARED
    const auto bp =
        ConvexPolyhedron<Q>::convert_from(posed(c.pool->shapes[ib].f, relative_pose(p.pose_a, p.pose_b)));
    const auto rp = sat::traversal(x->a[ia], c.pool->walk[ia], bp, c.pool->walk[ib]);
    p.ref_posed_overlap = rp.overlap;
    p.ref_posed_sep = rp.separation_as_double();
#else
    p.ref_posed_overlap = p.ref_overlap;
    p.ref_posed_sep = p.ref_sep;
#endif
  }
}

std::vector<Row> exact_rows(Cell& c) {
  std::vector<Row> rows;
  if (c.frames > 0) return rows;
  const int n = c.n;
  const bool cyl = c.workload.rfind("cylinder", 0) == 0;
  const bool brute = (n == 0 && !cyl) || (n > 0 && n <= 8), gauss = n <= 16, traversal = n <= 64;
  if (!brute && !gauss && !traversal) return rows;
  const std::shared_ptr<const ExactImages> x = exact_images(c, kExactPairs);
  const Cell* cp = &c;
  auto add = [&](std::string name, auto query) {
    rows.push_back(Row{std::move(name), "sepax",
                       [cp, x, query](std::size_t i) { return exact_out(query(*cp, *x, i)); }, kExactPairs});
  };
  auto qa = [](const Cell& cc, const ExactImages& xi, std::size_t i) -> const ConvexPolyhedron<Q>& {
    return xi.a[static_cast<std::size_t>(cc.pairs[i].a)];
  };
  if (brute)
    add("brute mpq", [qa](const Cell& cc, const ExactImages& xi, std::size_t i) {
      return sat::brute_force(qa(cc, xi, i), xi.b[i]);
    });
  if (gauss)
    add("gauss mpq", [qa](const Cell& cc, const ExactImages& xi, std::size_t i) {
      return sat::gauss_map(qa(cc, xi, i), xi.b[i]);
    });
  if (traversal)
    add("traversal mpq", [qa](const Cell& cc, const ExactImages& xi, std::size_t i) {
      const auto& w = cc.pool->walk;
      return sat::traversal(qa(cc, xi, i), w[static_cast<std::size_t>(cc.pairs[i].a)], xi.b[i],
                            w[static_cast<std::size_t>(cc.pairs[i].b)]);
    });
  return rows;
}

}  // namespace bench
