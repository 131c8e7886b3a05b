// python/src/exact.cpp
//
// The module's exact number type, GMP rationals (mpq_class): prepared
// shapes, caches, queries and batches, in their own translation unit (the
// GMP/CGAL headers are slow to compile).  Every decision exact; poses are
// the exact values of the given doubles (query_core.hpp, to_transform).
#include <sepax/robust/number_types.hpp>

#include "query_core.hpp"

namespace sepax::python {

template <>
std::string exact_string<mpq_class>(const mpq_class& x) {
  return x.get_str();
}

struct ExactShape {
  PreparedShape<mpq_class> shape;
};

struct ExactCache {
  SatCache<mpq_class> cache;
};

std::shared_ptr<const ExactShape> make_exact_shape(const ConvexPolyhedron<double>& p) {
  return std::make_shared<const ExactShape>(
      ExactShape{PreparedShape<mpq_class>(ConvexPolyhedron<mpq_class>::convert_from(p))});
}

std::unique_ptr<ExactCache, void (*)(ExactCache*)> make_exact_cache() {
  return {new ExactCache, [](ExactCache* c) { delete c; }};
}

std::int64_t exact_cache_hits(const ExactCache& c) { return c.cache.hits; }
std::int64_t exact_cache_misses(const ExactCache& c) { return c.cache.misses; }
void reset_exact_cache(ExactCache& c) { c.cache.reset(); }

void run_query_exact(const QueryOptions& o, const ExactShape& a, const PoseD& pose_a, const ExactShape& b,
                     const PoseD& pose_b, ExactCache* cache, QueryOut& out) {
  run_query(o, a.shape, pose_a, b.shape, pose_b, cache ? &cache->cache : nullptr, out);
}

void check_rigid_exact(const PoseD& p) { detail::check_rigid(to_transform<mpq_class>(p)); }

namespace {
template <Number U>
void exact_sign_table_of(const ConvexPolyhedron<U>& a, const ConvexPolyhedron<U>& b, SignTable& t) {
  const auto qa = ConvexPolyhedron<mpq_class>::convert_from(a);
  const auto qb = ConvexPolyhedron<mpq_class>::convert_from(b);
  kernel_t<policy::Plain, mpq_class> k(qa, qb);
  fill_sign_table(k, qa.edge_count(), qb.edge_count(), t);
}
}  // namespace

void exact_sign_table(const ConvexPolyhedron<double>& a, const ConvexPolyhedron<double>& b, SignTable& t) {
  exact_sign_table_of(a, b, t);
}
void exact_sign_table(const ConvexPolyhedron<float>& a, const ConvexPolyhedron<float>& b, SignTable& t) {
  exact_sign_table_of(a, b, t);
}

void run_batch_exact(const QueryOptions& o, const ExactShape& a, const ExactShape& b, const BatchPoses& poses,
                     ExactCache* cache, const BatchColumns& c) {
  run_batch(o, a.shape, b.shape, poses, cache ? &cache->cache : nullptr, c);
}

}  // namespace sepax::python
