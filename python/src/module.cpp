// python/src/module.cpp
//
// The Python module `sepax` (docs/python.md): shapes from numpy arrays,
// prepared once per number type; posed queries (traversal, Gauss map, brute
// force; float/double with the robust or the plain policy, or exact GMP
// rationals), margins, per-pair caches, contact manifolds, and a batch query
// over arrays of poses.  Python objects are made and read with the GIL held;
// queries, hulls and batches run with it released (query_core.hpp).
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sepax/convex_hull.hpp>
#include <sepax/shapes.hpp>
#include <sepax/version.hpp>

#include "io/convex_mesh.hpp"
#include "query_core.hpp"
#ifdef SEPAX_PYTHON_TOOLS
#include "tools.hpp"
#endif

namespace py = pybind11;

namespace sepax::python {
namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// ---- errors ---------------------------------------------------------------

py::object& invalid_input_type() {
  static py::object type;  // set once in the module init (kept alive by the module)
  return type;
}

[[noreturn]] void usage_error(const std::string& message) { throw py::value_error(message); }

std::string shape_string(const py::array& a) {
  std::ostringstream s;
  s << "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s << (i ? ", " : "") << a.shape(i);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

// ---- shapes -----------------------------------------------------------------

/// The polyhedron of a face list: validated as given (ConvexPolyhedron::from_faces); or, when validation
/// refuses it for its shape (coplanar neighbours, a split face: a triangulated cube) and it is a closed
/// convex mesh, the polyhedron it bounds, as the sepax program reads a mesh file (src/io/convex_mesh.hpp:
/// the hull of its vertices, accepted only when the faces tile the hull's boundary once).  Otherwise
/// validation's error.
ConvexPolyhedron<double> polyhedron_from_faces(std::vector<Vec3<double>> v,
                                               const std::vector<std::vector<int>>& faces) {
  try {
    return ConvexPolyhedron<double>::from_faces(v, faces);
  } catch (const InvalidInput& e) {
    if (!cli::io::may_be_convex_mesh(e.code()) || faces.size() < 4) throw;
    cli::io::ShapeData mesh;
    mesh.name = "Shape";
    mesh.vertices = v;
    mesh.faces = faces;
    try {
      return cli::io::convex_mesh<double>(mesh, v);
    } catch (const InvalidInput&) {
      throw e;  // (the face list as given is what the caller wrote: its error names the problem)
    }
  }
}

/// A validated convex hull (double), prepared for each number type on first use.
struct Shape {
  std::shared_ptr<const PreparedShape<double>> d;
  std::shared_ptr<const PreparedShape<float>> f;  // lazily (the GIL guards it)
  std::shared_ptr<const ExactShape> q;            // lazily

  explicit Shape(ConvexPolyhedron<double> p)
      : d(std::make_shared<const PreparedShape<double>>(std::move(p))) {}

  const ConvexPolyhedron<double>& poly() const { return d->polyhedron(); }
  const PreparedShape<float>& as_float() {
    if (!f) f = std::make_shared<const PreparedShape<float>>(ConvexPolyhedron<float>::convert_from(poly()));
    return *f;
  }
  const ExactShape& as_exact() {
    if (!q) q = make_exact_shape(poly());
    return *q;
  }
};

std::vector<Vec3<double>> points_from(const py::handle& obj, const char* what) {
  const DoubleArray a = DoubleArray::ensure(obj);
  if (!a) usage_error(std::string(what) + " must be an array-like of numbers of shape (N, 3)");
  if (a.ndim() != 2 || a.shape(1) != 3) {
    usage_error(std::string(what) + " must have shape (N, 3), not " + shape_string(a));
  }
  std::vector<Vec3<double>> out;
  out.reserve(static_cast<std::size_t>(a.shape(0)));
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) out.emplace_back(r(i, 0), r(i, 1), r(i, 2));
  return out;
}

py::array_t<double> vec_rows(const std::vector<Vec3<double>>& v) {
  py::array_t<double> out({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  auto w = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (int j = 0; j < 3; ++j) w(static_cast<py::ssize_t>(i), j) = v[i][j];
  }
  return out;
}

py::array_t<double> array3(const std::array<double, 3>& a) {
  py::array_t<double> out(3);
  for (py::ssize_t j = 0; j < 3; ++j) out.mutable_at(j) = a[static_cast<std::size_t>(j)];
  return out;
}

// ---- poses ------------------------------------------------------------------

void check_finite(double x, const std::string& what) {
  if (!std::isfinite(x))
    throw InvalidInput(ErrorCode::NonFinite, what + " is not finite (" + format_number(x) + ")");
}

/// R (3,3) and t (3,) from rows i of stacked arrays (or the single ones).
PoseD pose_from_parts(const double* r, const double* t, const std::string& what) {
  PoseD p;
  for (std::size_t k = 0; k < 9; ++k) {
    check_finite(r[k],
                 what + ": rotation entry (" + std::to_string(k / 3) + ", " + std::to_string(k % 3) + ")");
    p.r[k] = r[k];
  }
  for (std::size_t k = 0; k < 3; ++k) {
    check_finite(t[k], what + ": translation entry " + std::to_string(k));
    p.t[k] = t[k];
  }
  return p;
}

PoseD pose_from_matrix(const double* m, const std::string& what) {
  const double r[9] = {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]};
  const double t[3] = {m[3], m[7], m[11]};
  PoseD p = pose_from_parts(r, t, what);
  if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1) {
    throw InvalidInput(ErrorCode::BadScale, what + ": the last row of a 4x4 pose is (" +
                                                format_number(m[12]) + ", " + format_number(m[13]) + ", " +
                                                format_number(m[14]) + ", " + format_number(m[15]) +
                                                "), not (0, 0, 0, 1)");
  }
  return p;
}

/// Poses from None (identity), a (4,4) matrix, a (3,) translation, an
/// (R, t) pair, or stacks of them: (K,4,4), (R (K,3,3), t (K,3)).
/// `batch` allows the stacked forms; the result has 1 or K entries.
std::vector<PoseD> poses_from(const py::handle& obj, const std::string& what, bool batch) {
  if (obj.is_none()) return {PoseD{}};
  if ((py::isinstance<py::tuple>(obj) || py::isinstance<py::list>(obj)) && py::len(obj) == 2) {
    const DoubleArray r = DoubleArray::ensure(obj[py::int_(0)]);
    const DoubleArray t = DoubleArray::ensure(obj[py::int_(1)]);
    if (!r || !t) usage_error(what + ": (R, t) must be arrays of numbers");
    const bool single =
        r.ndim() == 2 && r.shape(0) == 3 && r.shape(1) == 3 && t.ndim() == 1 && t.shape(0) == 3;
    const bool stacked = batch && r.ndim() == 3 && r.shape(1) == 3 && r.shape(2) == 3 && t.ndim() == 2 &&
                         t.shape(1) == 3 && r.shape(0) == t.shape(0);
    if (single) return {pose_from_parts(r.data(), t.data(), what)};
    if (!stacked) {
      usage_error(what + ": (R, t) must have shapes ((3, 3), (3,))" +
                  std::string(batch ? " or ((K, 3, 3), (K, 3))" : "") + ", not (" + shape_string(r) + ", " +
                  shape_string(t) + ")");
    }
    std::vector<PoseD> out;
    for (py::ssize_t k = 0; k < r.shape(0); ++k) {
      out.push_back(pose_from_parts(r.data(k, 0, 0), t.data(k, 0), what + "[" + std::to_string(k) + "]"));
    }
    return out;
  }
  const DoubleArray a = DoubleArray::ensure(obj);
  if (!a) usage_error(what + " must be None, a (4, 4) matrix, a (3,) translation or an (R, t) pair");
  if (a.ndim() == 1 && a.shape(0) == 3) {
    const double r[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    return {pose_from_parts(r, a.data(), what)};
  }
  if (a.ndim() == 2 && a.shape(0) == 4 && a.shape(1) == 4) return {pose_from_matrix(a.data(), what)};
  if (batch && a.ndim() == 3 && a.shape(1) == 4 && a.shape(2) == 4) {
    std::vector<PoseD> out;
    for (py::ssize_t k = 0; k < a.shape(0); ++k) {
      out.push_back(pose_from_matrix(a.data(k, 0, 0), what + "[" + std::to_string(k) + "]"));
    }
    return out;
  }
  usage_error(what + " must be None, a (4, 4) matrix, a (3,) translation or an (R, t) pair" +
              std::string(batch ? ", or stacks (K, 4, 4) / ((K, 3, 3), (K, 3))" : "") + "; got shape " +
              shape_string(a));
}

py::array_t<double> pose_matrix(const PoseD& p) {
  py::array_t<double> out({py::ssize_t{4}, py::ssize_t{4}});
  auto w = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < 4; ++i) {
    for (py::ssize_t j = 0; j < 4; ++j) {
      const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
      w(i, j) = i == 3 ? (j == 3 ? 1.0 : 0.0) : (j == 3 ? p.t[ui] : p.r[3 * ui + uj]);
    }
  }
  return out;
}

// ---- options ----------------------------------------------------------------

enum class NumberKind { Float, Double, Exact };

NumberKind parse_number(const std::string& s) {
  if (s == "float") return NumberKind::Float;
  if (s == "double") return NumberKind::Double;
  if (s == "exact") return NumberKind::Exact;
  usage_error("number must be \"float\", \"double\" or \"exact\", not \"" + s + "\"");
}

SatAlgorithm parse_algorithm(const std::string& s) {
  if (s == "traversal") return SatAlgorithm::traversal;
  if (s == "gauss_map" || s == "gauss") return SatAlgorithm::gauss_map;
  if (s == "brute_force" || s == "brute") return SatAlgorithm::brute_force;
  usage_error("algorithm must be \"traversal\", \"gauss_map\" or \"brute_force\", not \"" + s + "\"");
}

/// A per-pair warm-start cache; one SatCache per number type, a mutex so that
/// a cache shared between threads is used by one query at a time.
struct Cache {
  std::mutex mutex;
  SatCache<float> f;
  SatCache<double> d;
  std::unique_ptr<ExactCache, void (*)(ExactCache*)> q{nullptr, [](ExactCache*) {}};

  ExactCache& exact() {
    if (!q) q = make_exact_cache();
    return *q;
  }
  std::int64_t hits() const { return f.hits + d.hits + (q ? exact_cache_hits(*q) : 0); }
  std::int64_t misses() const { return f.misses + d.misses + (q ? exact_cache_misses(*q) : 0); }
  void reset() {
    f.reset();
    d.reset();
    if (q) reset_exact_cache(*q);
  }
};

struct Request {
  QueryOptions opt;
  NumberKind number = NumberKind::Double;
  std::string number_name, algorithm_name;
};

Request make_request(const std::string& number, bool robust, const std::string& algorithm, double margin,
                     bool early_out, bool manifold, const Cache* cache) {
  Request q;
  q.number = parse_number(number);
  q.opt.algorithm = parse_algorithm(algorithm);
  q.opt.robust = robust && q.number != NumberKind::Exact;
  q.opt.margin = margin;
  q.opt.early_out = early_out;
  q.opt.manifold = manifold;
  q.number_name = number;
  q.algorithm_name = to_string(q.opt.algorithm);
  if (cache && q.number != NumberKind::Exact && !q.opt.robust && q.opt.algorithm == SatAlgorithm::traversal) {
    usage_error(
        "a cache cannot warm-start the plain float/double traversal (its climb is in rounding arithmetic): "
        "use robust=True, another algorithm, or no cache");
  }
  return q;
}

/// Prepares what the request needs with the GIL held, then runs `fn(a, b,
/// cache)` with the GIL released and the cache locked.
template <class Fn>
void dispatch(const Request& q, Shape& a, Shape& b, Cache* cache, Fn&& fn) {
  switch (q.number) {
    case NumberKind::Float: {
      const PreparedShape<float>& pa = a.as_float();
      const PreparedShape<float>& pb = b.as_float();
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock;
      if (cache) lock = std::unique_lock<std::mutex>(cache->mutex);
      fn(pa, pb, cache ? &cache->f : nullptr);
      return;
    }
    case NumberKind::Double: {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock;
      if (cache) lock = std::unique_lock<std::mutex>(cache->mutex);
      fn(*a.d, *b.d, cache ? &cache->d : nullptr);
      return;
    }
    case NumberKind::Exact: {
      const ExactShape& pa = a.as_exact();
      const ExactShape& pb = b.as_exact();
      ExactCache* qc = cache ? &cache->exact() : nullptr;
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock;
      if (cache) lock = std::unique_lock<std::mutex>(cache->mutex);
      fn(pa, pb, qc);
      return;
    }
  }
}

// ---- results ------------------------------------------------------------------

/// Results are values: their arrays are read-only (a result's attribute returns the same array each
/// time, so a write would change the result; np.array(r.axis) is a writable copy).
void freeze(const py::array& a) { a.attr("flags").attr("writeable") = false; }

struct Manifold {
  std::string kind;
  py::array_t<double> normal, points, points_a, points_b, separations;
  py::array_t<std::int32_t> ids;
  py::array_t<std::uint64_t> id_keys;
  std::vector<std::string> id_names;
  int reference_shape = -1, reference_face = -1, incident_face = -1;
};

struct Result {
  bool overlap = false, early_out = false, robust = false;
  double separation = 0;
  py::array_t<double> axis;
  Feature feature;
  py::dict stats;
  py::object separation_exact = py::none();
  py::object manifold = py::none();
  std::string number, algorithm;
};

Manifold make_manifold(const QueryOut& o) {
  Manifold m;
  m.kind = to_string(o.kind);
  m.normal = array3(o.normal);
  const auto n = static_cast<py::ssize_t>(o.points.size());
  m.points = py::array_t<double>({n, py::ssize_t{3}});
  m.points_a = py::array_t<double>({n, py::ssize_t{3}});
  m.points_b = py::array_t<double>({n, py::ssize_t{3}});
  m.separations = py::array_t<double>(n);
  m.ids = py::array_t<std::int32_t>({n, py::ssize_t{4}});
  m.id_keys = py::array_t<std::uint64_t>(n);
  auto wp = m.points.mutable_unchecked<2>();
  auto wa = m.points_a.mutable_unchecked<2>();
  auto wb = m.points_b.mutable_unchecked<2>();
  auto ws = m.separations.mutable_unchecked<1>();
  auto wi = m.ids.mutable_unchecked<2>();
  auto wk = m.id_keys.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const PointOut& p = o.points[static_cast<std::size_t>(i)];
    for (py::ssize_t j = 0; j < 3; ++j) {
      const auto uj = static_cast<std::size_t>(j);
      wp(i, j) = p.position[uj];
      wa(i, j) = p.point_a[uj];
      wb(i, j) = p.point_b[uj];
    }
    ws(i) = p.separation;
    wi(i, 0) = static_cast<std::int32_t>(p.id.a.kind);
    wi(i, 1) = p.id.a.index;
    wi(i, 2) = static_cast<std::int32_t>(p.id.b.kind);
    wi(i, 3) = p.id.b.index;
    wk(i) = p.id.key();
    m.id_names.push_back(to_string(p.id));
  }
  m.reference_shape = o.reference_shape;
  m.reference_face = o.reference_face;
  m.incident_face = o.incident_face;
  for (const py::array& a :
       {py::array(m.normal), py::array(m.points), py::array(m.points_a), py::array(m.points_b),
        py::array(m.separations), py::array(m.ids), py::array(m.id_keys)})
    freeze(a);
  return m;
}

Result make_result(const QueryOut& o, const Request& q) {
  Result r;
  r.overlap = o.overlap;
  r.early_out = o.early_out;
  r.robust = q.opt.robust;
  r.separation = o.separation;
  r.axis = array3(o.axis);
  freeze(r.axis);
  r.feature = o.feature;
  r.stats["face_axes"] = o.stats.face_axes;
  r.stats["edge_pairs"] = o.stats.edge_pairs;
  r.stats["minkowski_faces"] = o.stats.minkowski_faces;
  r.stats["side_axes"] = o.stats.side_axes;
  r.stats["exact_fallbacks"] = o.stats.exact_fallbacks;
  if (q.number == NumberKind::Exact) {
    const py::object fraction = py::module_::import("fractions").attr("Fraction");
    r.separation_exact = py::make_tuple(fraction(o.separation_num), fraction(o.separation_norm2));
  }
  if (o.has_manifold) r.manifold = py::cast(make_manifold(o));
  r.number = q.number_name;
  r.algorithm = q.algorithm_name;
  return r;
}

/// The posed query's rigidity check (check_rigid, posing.hpp, in the request's number type), run
/// before the query so that its refusal names the argument: "pose_b: the rotation is ...".
void check_poses(NumberKind number, const std::vector<PoseD>& poses, const std::string& what) {
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const std::string name = poses.size() > 1 ? what + "[" + std::to_string(k) + "]" : what;
    if (number == NumberKind::Float) {  // (finite in double, checked when read)
      for (std::size_t i = 0; i < 3; ++i) {
        if (std::fabs(poses[k].t[i]) > std::numeric_limits<float>::max())
          throw InvalidInput(ErrorCode::BadScale, name + ": translation entry " + std::to_string(i) + " (" +
                                                      format_number(poses[k].t[i]) +
                                                      ") is beyond the range of float");
      }
    }
    try {
      switch (number) {
        case NumberKind::Float:
          detail::check_rigid(to_transform<float>(poses[k]));
          break;
        case NumberKind::Double:
          detail::check_rigid(to_transform<double>(poses[k]));
          break;
        case NumberKind::Exact:
          check_rigid_exact(poses[k]);
          break;
      }
    } catch (const InvalidInput& e) {
      std::string message = e.what();
      const std::string generic = "pose: ";
      if (message.compare(0, generic.size(), generic) == 0) message.erase(0, generic.size());
      throw InvalidInput(e.code(), name + ": " + message);
    }
  }
}

/// One pose argument, read and checked (check_poses).
PoseD checked_pose(NumberKind number, const py::handle& obj, const std::string& what) {
  const std::vector<PoseD> p = poses_from(obj, what, false);
  check_poses(number, p, what);
  return p.front();
}

QueryOut run_request(const Request& q, Shape& a, Shape& b, const PoseD& pa, const PoseD& pb, Cache* cache) {
  QueryOut out;
  dispatch(q, a, b, cache, [&](const auto& sa, const auto& sb, auto* c) {
    using S = std::decay_t<decltype(sa)>;
    if constexpr (std::is_same_v<S, ExactShape>) {
      run_query_exact(q.opt, sa, pa, sb, pb, c, out);
    } else {
      run_query(q.opt, sa, pa, sb, pb, c, out);
    }
  });
  return out;
}

Result query(Shape& a, Shape& b, const py::object& pose_a, const py::object& pose_b,
             const std::string& number, bool robust, const std::string& algorithm, double margin,
             bool early_out, Cache* cache, bool manifold) {
  const Request q = make_request(number, robust, algorithm, margin, early_out, manifold, cache);
  const PoseD pa = checked_pose(q.number, pose_a, "pose_a");
  const PoseD pb = checked_pose(q.number, pose_b, "pose_b");
  return make_result(run_request(q, a, b, pa, pb, cache), q);
}

struct BatchResult {
  py::array_t<bool> overlap, early_out;
  py::array_t<double> separation, axis;
  py::array_t<std::int8_t> feature_type;
  py::array_t<std::int32_t> feature;
  py::array_t<std::int64_t> exact_fallbacks;
  py::object contact_count = py::none(), contact_points = py::none(), contact_separations = py::none(),
             contact_ids = py::none();
  std::string number, algorithm;
  bool robust = false;
  std::size_t size = 0;
};

BatchResult query_batch(Shape& a, Shape& b, const py::object& poses_a, const py::object& poses_b,
                        const std::string& number, bool robust, const std::string& algorithm, double margin,
                        bool early_out, Cache* cache, bool manifold) {
  const Request q = make_request(number, robust, algorithm, margin, early_out, manifold, cache);
  const std::vector<PoseD> pa = poses_from(poses_a, "poses_a", true);
  const std::vector<PoseD> pb = poses_from(poses_b, "poses_b", true);
  check_poses(q.number, pa, "poses_a");
  check_poses(q.number, pb, "poses_b");
  // K: the larger count, or 0 when either side holds no pose (an empty batch: empty columns)
  const std::size_t rows = pa.empty() || pb.empty() ? 0 : std::max(pa.size(), pb.size());
  BatchPoses poses{pa.data(), pa.size(), pb.data(), pb.size(), rows};
  if ((pa.size() != 1 && pa.size() != poses.k) || (pb.size() != 1 && pb.size() != poses.k)) {
    usage_error("poses_a and poses_b hold " + std::to_string(pa.size()) + " and " +
                std::to_string(pb.size()) + " poses: each must hold K or 1");
  }
  const auto k = static_cast<py::ssize_t>(poses.k);
  BatchResult r;
  r.size = poses.k;
  r.number = q.number_name;
  r.algorithm = q.algorithm_name;
  r.robust = q.opt.robust;
  r.overlap = py::array_t<bool>(k);
  r.early_out = py::array_t<bool>(k);
  r.separation = py::array_t<double>(k);
  r.axis = py::array_t<double>({k, py::ssize_t{3}});
  r.feature_type = py::array_t<std::int8_t>(k);
  r.feature = py::array_t<std::int32_t>({k, py::ssize_t{2}});
  r.exact_fallbacks = py::array_t<std::int64_t>(k);
  BatchColumns c;
  c.overlap = r.overlap.mutable_data();
  c.early_out = r.early_out.mutable_data();
  c.separation = r.separation.mutable_data();
  c.axis = r.axis.mutable_data();
  c.feature_type = r.feature_type.mutable_data();
  c.feature = r.feature.mutable_data();
  c.exact_fallbacks = r.exact_fallbacks.mutable_data();
  if (manifold) {
    const py::ssize_t np = kBatchPoints;
    py::array_t<std::int32_t> count(k);
    py::array_t<double> points({k, np, py::ssize_t{3}});
    py::array_t<double> seps({k, np});
    py::array_t<std::int32_t> ids({k, np, py::ssize_t{4}});
    c.contact_count = count.mutable_data();
    c.contact_points = points.mutable_data();
    c.contact_separations = seps.mutable_data();
    c.contact_ids = ids.mutable_data();
    r.contact_count = count;
    r.contact_points = points;
    r.contact_separations = seps;
    r.contact_ids = ids;
  }
  dispatch(q, a, b, cache, [&](const auto& sa, const auto& sb, auto* cc) {
    using S = std::decay_t<decltype(sa)>;
    if constexpr (std::is_same_v<S, ExactShape>) {
      run_batch_exact(q.opt, sa, sb, poses, cc, c);
    } else {
      run_batch(q.opt, sa, sb, poses, cc, c);
    }
  });
  for (const py::array& x :
       {py::array(r.overlap), py::array(r.early_out), py::array(r.separation), py::array(r.axis),
        py::array(r.feature_type), py::array(r.feature), py::array(r.exact_fallbacks)})
    freeze(x);
  for (const py::object& x : {r.contact_count, r.contact_points, r.contact_separations, r.contact_ids})
    if (!x.is_none()) freeze(py::array(x));
  return r;
}

/// audit(): the sign tables of the plain and the robust kernel in T on (A,
/// B'), and the exact one on their exact images, as numpy columns.
template <Number T>
py::dict audit_in(const PreparedShape<T>& a, const PoseD& pa, const PreparedShape<T>& b, const PoseD& pb) {
  SignTable plain, robust, exact;
  const int ea = a.polyhedron().edge_count(), eb = b.polyhedron().edge_count();
  {
    py::gil_scoped_release release;
    sign_table<policy::Plain>(a, pa, b, pb, plain);
    sign_table<policy::Robust>(a, pa, b, pb, robust);
    // B' again (the scratch holds it: same shape, same pose), its exact image
    const ConvexPolyhedron<T>& bp = b.posed_scratch(relative_pose(to_transform<T>(pa), to_transform<T>(pb)));
    exact_sign_table(a.polyhedron(), bp, exact);
  }
  const auto rows = static_cast<py::ssize_t>(plain.parallel.size());
  py::array_t<std::int32_t> edges({rows, py::ssize_t{2}});
  auto we = edges.mutable_unchecked<2>();
  py::ssize_t r = 0;
  for (int i = 0; i < ea; ++i) {
    for (int j = 0; j < eb; ++j, ++r) {
      we(r, 0) = i;
      we(r, 1) = j;
    }
  }
  const auto signs = [rows](const SignTable& t) {
    py::array_t<std::int8_t> out({rows, py::ssize_t{4}});
    std::copy(t.signs.begin(), t.signs.end(), out.mutable_data());
    return out;
  };
  const auto flags = [rows](const SignTable& t, bool parallel) {
    py::array_t<bool> out(rows);
    bool* w = out.mutable_data();
    for (std::size_t i = 0; i < t.parallel.size(); ++i) {
      const ArcSigns s{t.signs[4 * i], t.signs[4 * i + 1], t.signs[4 * i + 2], t.signs[4 * i + 3]};
      w[i] = parallel ? t.parallel[i] != 0 : s.minkowski_face();
    }
    return out;
  };
  py::dict d;
  d["edges"] = edges;
  d["plain"] = signs(plain);
  d["robust"] = signs(robust);
  d["exact"] = signs(exact);
  d["minkowski_plain"] = flags(plain, false);
  d["minkowski_robust"] = flags(robust, false);
  d["minkowski_exact"] = flags(exact, false);
  d["parallel_plain"] = flags(plain, true);
  d["parallel_robust"] = flags(robust, true);
  d["parallel_exact"] = flags(exact, true);
  return d;
}

py::object audit_report_object(Shape& a, Shape& b, const PoseD& pa, const PoseD& pb, bool use_double,
                               const std::string& report);

py::object audit(Shape& a, Shape& b, const py::object& pose_a, const py::object& pose_b,
                 const std::string& number, const py::object& report) {
  const NumberKind n = parse_number(number);
  if (n == NumberKind::Exact) {
    usage_error("audit compares float or double against exact: number must be \"float\" or \"double\"");
  }
  const PoseD pa = checked_pose(n, pose_a, "pose_a");
  const PoseD pb = checked_pose(n, pose_b, "pose_b");
  if (!report.is_none()) {
    if (!py::isinstance<py::str>(report)) usage_error("report must be None, \"text\" or \"json\"");
    return audit_report_object(a, b, pa, pb, n == NumberKind::Double, report.cast<std::string>());
  }
  return n == NumberKind::Float ? audit_in(a.as_float(), pa, b.as_float(), pb) : audit_in(*a.d, pa, *b.d, pb);
}

#ifdef SEPAX_PYTHON_TOOLS
// ---- tools: the program's renderer and the fuzzer (tools.hpp) -------------------

/// audit(report="text"|"json"): the fuzzer's full audit (sepax audit).
py::object audit_report_object(Shape& a, Shape& b, const PoseD& pa, const PoseD& pb, bool use_double,
                               const std::string& report) {
  if (report != "text" && report != "json")
    usage_error("report must be None, \"text\" or \"json\", not \"" + report + "\"");
  AuditReport r;
  {
    py::gil_scoped_release release;
    r = audit_report(a.poly(), pa, b.poly(), pb, use_double, report == "json");
  }
  if (r.rounded > 0) {
    const std::string note =
        "sepax.audit: " + std::to_string(r.rounded) +
        " coordinates changed when rounded to float (the report audits the rounded shapes)";
    if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1) != 0) throw py::error_already_set();
  }
  if (report == "text") return py::str(r.text);
  return py::module_::import("json").attr("loads")(py::str(r.text));
}

std::string render_svg(Shape& a, Shape& b, const py::object& pose_a, const py::object& pose_b,
                       const std::string& number, bool robust, const std::string& algorithm, double margin,
                       const py::object& title) {
  const Request q = make_request(number, robust, algorithm, margin, false, true, nullptr);
  const PoseD pa = checked_pose(q.number, pose_a, "pose_a");
  const PoseD pb = checked_pose(q.number, pose_b, "pose_b");
  const QueryOut out = run_request(q, a, b, pa, pb, nullptr);
  std::string t;
  if (title.is_none()) {
    t = "sepax.query: " + q.number_name +
        (q.number == NumberKind::Exact ? ""
         : q.opt.robust                ? " robust"
                                       : " plain") +
        ", " + q.algorithm_name + (margin > 0 ? ", margin " + format_number(margin) : "");
  } else {
    t = title.cast<std::string>();
  }
  py::gil_scoped_release release;
  return render_query_svg(a.poly(), pa, b.poly(), pb, out, t);
}

/// sepax.fuzz.replay's answer.
struct CaseReportPy {
  py::object path = py::none();  // the path as os.fsdecode gives it
  std::string family, outcome, reject_reason;
  std::uint64_t seed = 0;
  bool valid = false;
  std::int64_t unexplained_count = 0;
  py::dict comparisons, by_config, skipped, details, maxima;
  py::list findings, configs_run;
  py::object a = py::none(), b = py::none();
};

py::dict counts_dict(const fuzz::Counts& c) {
  py::dict d;
  for (int k = 0; k < fuzz::kClassificationCount; ++k) {
    const auto cls = static_cast<fuzz::Classification>(k);
    d[fuzz::classification_name(cls)] = c[cls];
  }
  return d;
}

py::dict counts_map(const std::map<std::string, fuzz::Counts>& m) {
  py::dict d;
  for (const auto& [key, c] : m) d[py::str(key)] = counts_dict(c);
  return d;
}

py::tuple spec_tuple(const fuzz::ShapeSpec& s) { return py::make_tuple(vec_rows(s.vertices), s.faces); }

// An OSError subclass (FileNotFoundError, IsADirectoryError) with errno, message and the path as given.
[[noreturn]] void raise_os_error(const char* type, const char* errno_name, const char* message,
                                 const py::object& path) {
  const py::object err = py::module_::import("builtins").attr(type);
  const py::object code = py::module_::import("errno").attr(errno_name);
  PyErr_SetObject(err.ptr(), py::make_tuple(code, message, path).ptr());
  throw py::error_already_set();
}

CaseReportPy replay(const py::object& path_like, bool bytes) {
  // str, bytes or os.PathLike; the file system's bytes for the C++ side, the decoded name for messages
  const py::module_ os = py::module_::import("os");
  const py::object fs_path = os.attr("fspath")(path_like);
  const std::string path = os.attr("fsencode")(fs_path).cast<std::string>();
  const py::object shown = os.attr("fsdecode")(fs_path);
  if (!os.attr("path").attr("exists")(fs_path).cast<bool>())
    raise_os_error("FileNotFoundError", "ENOENT",
                   "sepax.fuzz.replay: no such file (a fuzzer reproducer, .case)", shown);
  if (os.attr("path").attr("isdir")(fs_path).cast<bool>())
    raise_os_error("IsADirectoryError", "EISDIR",
                   "sepax.fuzz.replay: a directory (replay takes one file; `sepax fuzz --replay DIR` takes "
                   "a directory)",
                   shown);
  Replayed rp;
  {
    py::gil_scoped_release release;
    rp = replay_case(path, bytes);
  }
  const fuzz::CaseReport& r = rp.r;
  CaseReportPy o;
  o.path = shown;
  o.family = rp.c.family;
  o.seed = rp.c.seed;
  o.valid = r.valid;
  o.reject_reason = r.reject_reason;
  o.unexplained_count = r.unexplained_count;
  o.outcome = !r.valid ? "rejected" : r.unexplained_count ? "unexplained" : "ok";
  o.comparisons = counts_map(r.by_comparison);
  o.by_config = counts_map(r.by_config);
  o.details = counts_map(r.details);
  for (const auto& [k, n] : r.skipped) o.skipped[py::str(k)] = n;
  for (const auto& [k, x] : r.maxima) o.maxima[py::str(k)] = x;
  for (const auto& f : r.unexplained) {
    py::dict d;
    d["comparison"] = f.comparison;
    d["config"] = f.config;
    d["sat"] = f.sat;
    d["detail"] = f.detail;
    o.findings.append(d);
  }
  for (const auto& c : r.configs_run) o.configs_run.append(c);
  o.a = spec_tuple(rp.c.a);
  o.b = spec_tuple(rp.c.b);
  return o;
}

void add_tools(py::module_& m) {
  m.def("render_svg", &render_svg, py::arg("a"), py::arg("b"), py::arg("pose_a") = py::none(),
        py::arg("pose_b") = py::none(), py::kw_only(), py::arg("number") = "double",
        py::arg("robust").none(false) = true, py::arg("algorithm") = "traversal", py::arg("margin") = 0.0,
        py::arg("title") = py::none(),
        R"(render_svg(a, b, pose_a=None, pose_b=None, *, number="double", robust=True,
           algorithm="traversal", margin=0.0, title=None) -> str

The SVG picture of sepax.query(a, b, pose_a, pose_b, ...) (the renderer of `sepax render`):
left, both shapes in world coordinates (A blue, B red) with the manifold's contact points and
normal; right, the Gauss maps of A and -B with the Minkowski edge-edge faces and the chosen
axis.  The header line gives the verdict, separation, feature and contact count of the query.)");

  py::module_ fz = m.def_submodule("fuzz", "The differential fuzzer's reproducers (fuzz/, docs/fuzz.md).");
  // `import sepax.fuzz` and `from sepax.fuzz import replay` find it too
  py::module_::import("sys").attr("modules")["sepax.fuzz"] = fz;
  py::class_<CaseReportPy>(fz, "CaseReport",
                           "The check of one fuzzer case (sepax/fuzz/check.hpp): every configuration "
                           "(float/double, plain/robust, exact) and SAT against the exact reference, every "
                           "disagreement classified.")
      .def_readonly("path", &CaseReportPy::path)
      .def_readonly("family", &CaseReportPy::family, "generator family of the case")
      .def_readonly("seed", &CaseReportPy::seed, "generator seed of the case (informational)")
      .def_readonly("outcome", &CaseReportPy::outcome,
                    "'ok' (no unexplained disagreement), 'unexplained' or 'rejected' (invalid shapes)")
      .def_readonly("valid", &CaseReportPy::valid, "False: the shapes were rejected")
      .def_readonly("reject_reason", &CaseReportPy::reject_reason)
      .def_readonly("unexplained_count", &CaseReportPy::unexplained_count)
      .def_readonly("comparisons", &CaseReportPy::comparisons,
                    "{comparison: {class: count}}; classes agree, exact_zero, explained, tie, unexplained, "
                    "nonconvex")
      .def_readonly("by_config", &CaseReportPy::by_config, "{'comparison/config': {class: count}}")
      .def_readonly("details", &CaseReportPy::details, "sub-comparisons, e.g. 'manifold.points'")
      .def_readonly("maxima", &CaseReportPy::maxima, "largest error/bound ratios, e.g. 'manifold.depth'")
      .def_readonly("skipped", &CaseReportPy::skipped, "comparisons not made (size budgets): key -> count")
      .def_readonly("findings", &CaseReportPy::findings,
                    "the first unexplained findings: dicts comparison, config, sat, detail")
      .def_readonly("configs_run", &CaseReportPy::configs_run, "'config/sat' runs made")
      .def_readonly("a", &CaseReportPy::a, "shape A of the case: (vertices (N, 3), faces)")
      .def_readonly("b", &CaseReportPy::b, "shape B of the case: (vertices (N, 3), faces)")
      .def("__repr__", [](const CaseReportPy& r) {
        return "<sepax.fuzz.CaseReport: " + py::repr(r.path).cast<std::string>() + ": " + r.outcome + ">";
      });
  fz.def("replay", &replay, py::arg("path"), py::kw_only(), py::arg("bytes").none(false) = false,
         R"(replay(path, *, bytes=False) -> CaseReport

Check one fuzzer case as `sepax fuzz --replay path` does: read the .case file (bytes=True: a
libFuzzer input) and run it through every configuration and SAT against the exact reference.
path: str, bytes or os.PathLike.  Raises FileNotFoundError naming the path when there is no such
file, IsADirectoryError for a directory, sepax.InvalidInput (code
Parse, naming the file and line) when it cannot be parsed.  A case whose shapes are invalid is
not an error: its outcome is 'rejected', with reject_reason.  The GIL is released while it runs.)");
}
#else
py::object audit_report_object(Shape&, Shape&, const PoseD&, const PoseD&, bool, const std::string&) {
  usage_error(
      "audit reports need the fuzzer library: this module was built without it (SEPAX_BUILD_CLI=OFF)");
}
#endif

// ---- repr ---------------------------------------------------------------------

std::string feature_repr(const Feature& f) {
  return "Feature('" + std::string(type_name(f.type)) + "', " + std::to_string(f.a) + ", " +
         std::to_string(f.b) + ")";
}

std::string number_repr(double x) { return format_number(x); }

}  // namespace
}  // namespace sepax::python

using namespace sepax;
using namespace sepax::python;

PYBIND11_MODULE(sepax, m) {
  m.doc() =
      "sepax: exact-predicate separating axis tests and contact manifolds for convex polyhedra.\n\n"
      "Shapes are convex hulls given as numpy (N, 3) float64 arrays; queries take poses (4x4 matrices,\n"
      "(R, t) pairs, (3,) translations or None) and answer in world coordinates.  See docs/python.md.";
  m.attr("__version__") = SEPAX_VERSION_STRING;

  // errors
  py::enum_<ErrorCode>(m, "ErrorCode", "Which rule an input broke (sepax/error.hpp).")
      .value("NonFinite", ErrorCode::NonFinite, "NaN or infinity in a coordinate")
      .value("TooFewPoints", ErrorCode::TooFewPoints,
             "fewer than 3 distinct points (or 4 for a solid face list)")
      .value("Collinear", ErrorCode::Collinear, "all points on one line")
      .value("BadIndex", ErrorCode::BadIndex, "a face refers to a vertex that does not exist")
      .value("DegenerateFace", ErrorCode::DegenerateFace,
             "a face with < 3 vertices, a repeated vertex, or zero area")
      .value("NotManifold", ErrorCode::NotManifold, "an edge not shared by exactly two faces")
      .value("BadEuler", ErrorCode::BadEuler, "V - E + F != 2")
      .value("UnusedVertex", ErrorCode::UnusedVertex, "a vertex on no face")
      .value("NonPlanarFace", ErrorCode::NonPlanarFace, "a face's vertices are not on one plane")
      .value("NonConvexFace", ErrorCode::NonConvexFace, "a face polygon that turns the wrong way")
      .value("NotConvex", ErrorCode::NotConvex, "a vertex above some face plane, or coplanar adjacent faces")
      .value("InwardFaces", ErrorCode::InwardFaces, "faces oriented inward")
      .value("BadScale", ErrorCode::BadScale,
             "zero extent, coordinates out of range, a non-rigid pose, a bad margin")
      .value("Parse", ErrorCode::Parse, "a malformed input file");
  {
    py::dict ns;
    ns["__name__"] = "sepax";
    py::exec(R"(
class InvalidInput(ValueError):
    """Bad input refused by sepax (a ValueError).

    Attributes: code (sepax.ErrorCode: which rule the input broke) and
    code_name (its short name, e.g. "non-finite"); str(e) names the
    offending element (vertex, face, pose entry)."""

    def __init__(self, message, code, code_name):
        super().__init__(message)
        self.code = code
        self.code_name = code_name

    def __reduce__(self):
        return (type(self), (self.args[0], self.code, self.code_name))
)",
             ns, ns);
    invalid_input_type() = ns["InvalidInput"];
    invalid_input_type().attr("__module__") = "sepax";
    m.attr("InvalidInput") = invalid_input_type();
  }
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      const py::object exc =
          invalid_input_type()(py::str(e.what()), py::cast(e.code()), sepax::to_string(e.code()));
      PyErr_SetObject(invalid_input_type().ptr(), exc.ptr());
    }
  });

  // shapes
  py::class_<Shape>(
      m, "Shape",
      "A convex polyhedron in its local frame, validated in double and prepared once per number "
      "type it is queried in (float: the vertices rounded to float; exact: their exact values; "
      "same faces and plane triples).  Immutable; may be queried from several threads.")
      .def(py::init([](const py::object& vertices, const std::vector<std::vector<int>>& faces) {
             std::vector<Vec3<double>> v = points_from(vertices, "vertices");
             py::gil_scoped_release release;
             return Shape(polyhedron_from_faces(std::move(v), faces));
           }),
           py::arg("vertices"), py::arg("faces"),
           "Shape(vertices, faces): vertices (N, 3); faces: lists of vertex indices, counter-clockwise seen "
           "from outside (a flat shape: the polygon and the same polygon reversed).  Validated; a closed "
           "convex mesh with coplanar neighbouring faces (a triangulated cube) is the polyhedron it bounds, "
           "with its faces merged and only its corners as vertices.  Raises sepax.InvalidInput naming the "
           "problem.")
      .def_property_readonly(
          "vertices", [](const Shape& s) { return vec_rows(s.poly().vertices()); },
          "(N, 3) float64 array of the vertices (a copy).")
      .def_property_readonly(
          "faces",
          [](const Shape& s) {
            std::vector<std::vector<int>> f;
            for (int i = 0; i < s.poly().face_count(); ++i) f.push_back(s.poly().face_vertices(i));
            return f;
          },
          "The faces as lists of vertex indices (counter-clockwise seen from outside).")
      .def_property_readonly(
          "normals",
          [](const Shape& s) {
            std::vector<Vec3<double>> n;
            for (const auto& p : s.poly().planes()) n.push_back(p.normal);
            return vec_rows(n);
          },
          "(F, 3) unit outward face normals.")
      .def_property_readonly(
          "offsets",
          [](const Shape& s) {
            py::array_t<double> o(s.poly().face_count());
            for (int i = 0; i < s.poly().face_count(); ++i) {
              o.mutable_at(i) = s.poly().planes()[static_cast<std::size_t>(i)].offset;
            }
            return o;
          },
          "(F,) plane offsets: normals[f] . x == offsets[f] on face f.")
      .def_property_readonly(
          "edges",
          [](const Shape& s) {
            const auto& he = s.poly().half_edges();
            py::array_t<std::int32_t> e({py::ssize_t{s.poly().edge_count()}, py::ssize_t{2}});
            auto w = e.mutable_unchecked<2>();
            for (py::ssize_t i = 0; i < s.poly().edge_count(); ++i) {
              w(i, 0) = he[static_cast<std::size_t>(2 * i)].origin;
              w(i, 1) = he[static_cast<std::size_t>(2 * i + 1)].origin;
            }
            return e;
          },
          "(E, 2) int32 vertex pairs; row e is undirected edge e (feature and contact ids).")
      .def_property_readonly("vertex_count", [](const Shape& s) { return s.poly().vertex_count(); })
      .def_property_readonly("edge_count", [](const Shape& s) { return s.poly().edge_count(); })
      .def_property_readonly("face_count", [](const Shape& s) { return s.poly().face_count(); })
      .def_property_readonly(
          "is_flat", [](const Shape& s) { return s.poly().is_flat(); },
          "True for a double-sided polygon (two opposite faces).")
      .def_property_readonly(
          "bounds",
          [](const Shape& s) {
            return vec_rows({s.poly().bounds_min(), s.poly().bounds_max()});
          },
          "(2, 3): the bounding box's min and max corners.")
      .def(py::pickle(
          [](const Shape& s) {
            std::vector<std::vector<int>> f;
            for (int i = 0; i < s.poly().face_count(); ++i) f.push_back(s.poly().face_vertices(i));
            return py::make_tuple(vec_rows(s.poly().vertices()), f);
          },
          [](const py::tuple& t) {
            if (t.size() != 2) usage_error("Shape: a pickled shape is (vertices, faces)");
            std::vector<Vec3<double>> v = points_from(t[0], "vertices");
            const auto f = t[1].cast<std::vector<std::vector<int>>>();
            py::gil_scoped_release release;
            return Shape(ConvexPolyhedron<double>::from_faces(std::move(v), f));
          }))
      .def("__repr__", [](const Shape& s) {
        return "<sepax.Shape: " + std::to_string(s.poly().vertex_count()) + " vertices, " +
               std::to_string(s.poly().edge_count()) + " edges, " + std::to_string(s.poly().face_count()) +
               " faces" + (s.poly().is_flat() ? ", flat" : "") + ">";
      });

  m.def(
      "convex_hull",
      [](const py::object& points) {
        std::vector<Vec3<double>> p = points_from(points, "points");
        py::gil_scoped_release release;
        return Shape(convex_hull<double>(p));
      },
      py::arg("points"),
      "convex_hull(points) -> Shape: the convex hull of an (N, 3) point array, built and validated in double "
      "(vertices are input points; coplanar points give a flat double-sided polygon).  Raises "
      "sepax.InvalidInput: NonFinite (NaN/inf, naming the point), TooFewPoints, Collinear, BadScale.");
  m.def(
      "convex_hull_local",
      [](const py::object& points) {
        std::vector<Vec3<double>> p = points_from(points, "points");
        LocalHull<double> h = [&] {
          py::gil_scoped_release release;
          return convex_hull_local<double>(p);
        }();
        py::array_t<double> origin(3);
        for (int c = 0; c < 3; ++c) origin.mutable_at(c) = h.origin[c];
        return py::make_tuple(Shape(std::move(h.shape)), origin);
      },
      py::arg("points"),
      "convex_hull_local(points) -> (Shape, origin): the hull in its own frame, for points far from the "
      "world origin (a small piece of a decomposition in world coordinates): shape is the hull of "
      "points - origin, origin (3,) chosen so that every subtraction is exact, and every vertex + origin is "
      "exactly an input point.  Query it at the pose (R, t + R @ origin) for a world pose (R, t).  Raises "
      "as convex_hull.");
  m.def(
      "box", [](double hx, double hy, double hz) { return Shape(shapes::box<double>(hx, hy, hz)); },
      py::arg("hx"), py::arg("hy"), py::arg("hz"),
      "box(hx, hy, hz) -> Shape: the axis-aligned box with these half extents.");
  m.def(
      "cube", [](double half) { return Shape(shapes::cube<double>(half)); }, py::arg("half") = 1.0,
      "cube(half=1.0) -> Shape: the cube [-half, half]^3.");
  m.def(
      "tetrahedron", [](double s) { return Shape(shapes::tetrahedron<double>(s)); }, py::arg("s") = 1.0,
      "tetrahedron(s=1.0) -> Shape: (s,s,s), (s,-s,-s), (-s,s,-s), (-s,-s,s).");
  m.def(
      "prism", [](int n, double r, double h) { return Shape(shapes::prism<double>(n, r, h)); }, py::arg("n"),
      py::arg("r") = 1.0, py::arg("h") = 1.0,
      "prism(n, r=1.0, h=1.0) -> Shape: the regular n-gon prism around z.");
  m.def(
      "polygon",
      [](const py::object& loop) {
        return Shape(ConvexPolyhedron<double>::polygon(points_from(loop, "loop")));
      },
      py::arg("loop"),
      "polygon(loop) -> Shape: the double-sided convex polygon with these (N, 3) vertices in order.");

  // poses
  m.def(
      "pose",
      [](const py::object& translation, const py::object& quaternion) {
        const DoubleArray t = DoubleArray::ensure(translation), qa = DoubleArray::ensure(quaternion);
        if (!t || t.ndim() != 1 || t.shape(0) != 3) usage_error("translation must have shape (3,)");
        if (!qa || qa.ndim() != 1 || qa.shape(0) != 4)
          usage_error("quaternion must have shape (4,) as (w, x, y, z)");
        const auto x = RigidTransform<double>::from_quaternion(qa.at(0), qa.at(1), qa.at(2), qa.at(3),
                                                               Vec3<double>(t.at(0), t.at(1), t.at(2)));
        PoseD p;
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) p.r[static_cast<std::size_t>(3 * i + j)] = x.rotation(i, j);
          p.t[static_cast<std::size_t>(i)] = x.translation[i];
        }
        return pose_matrix(pose_from_parts(p.r.data(), p.t.data(), "pose"));
      },
      py::arg("translation") = py::make_tuple(0.0, 0.0, 0.0),
      py::arg("quaternion") = py::make_tuple(1.0, 0.0, 0.0, 0.0),
      "pose(translation=(0,0,0), quaternion=(1,0,0,0)) -> (4, 4) array: rotation by the quaternion (w, x, y, "
      "z), "
      "normalised first, then translation; the same matrix as the CLI's --pose.");

  // features and caches
  py::class_<Feature>(m, "Feature",
                      "The SAT feature of a result: type 'faceA' (a = face of A, b = support vertex of B), "
                      "'faceB' (a = vertex of A, b = face of B), 'edges' (a = edge of A, b = edge of B), "
                      "'sideA'/'sideB' (flat shapes in one plane).")
      .def_property_readonly("type", [](const Feature& f) { return std::string(type_name(f.type)); })
      .def_readonly("a", &Feature::a)
      .def_readonly("b", &Feature::b)
      .def("__eq__", [](const Feature& x, const Feature& y) { return x == y; })
      .def("__hash__",
           [](const Feature& f) { return py::hash(py::make_tuple(static_cast<int>(f.type), f.a, f.b)); })
      .def("__repr__", &feature_repr);
  m.attr("FEATURE_TYPES") = py::make_tuple("faceA", "faceB", "edges", "sideA", "sideB");
  m.attr("VERTEX") = static_cast<int>(ShapeFeatureKind::Vertex);
  m.attr("EDGE") = static_cast<int>(ShapeFeatureKind::Edge);
  m.attr("FACE") = static_cast<int>(ShapeFeatureKind::Face);

  py::class_<Cache>(
      m, "Cache",
      "Per-pair warm-start cache (sepax/sat_cache.hpp): pass the same Cache for the same pair at "
      "every step.  A cached query returns the fresh query's verdict, feature and separation "
      "(with early_out: a separating axis beyond the margin, maybe found at once).  A foreign "
      "or stale cache costs one re-evaluation.  Thread-safe (one query at a time uses it).")
      .def(py::init<>())
      .def_property_readonly("hits", &Cache::hits, "early-out queries answered by the cached feature")
      .def_property_readonly("misses", &Cache::misses, "queries that ran the SAT")
      .def("reset", &Cache::reset, "forget the cached feature");

  py::class_<Manifold>(m, "Manifold",
                       "Contact manifold in world coordinates (docs/contacts.md).  At most 4 points; "
                       "separations < 0 are penetrations, > 0 only within the speculative margin.")
      .def_readonly("kind", &Manifold::kind, "'face', 'edge', 'side' or 'none'")
      .def_readonly("normal", &Manifold::normal, "(3,) unit normal from A to B")
      .def_readonly("points", &Manifold::points, "(M, 3) contact points (midpoints of points_a and points_b)")
      .def_readonly("points_a", &Manifold::points_a, "(M, 3) the points on A")
      .def_readonly("points_b", &Manifold::points_b, "(M, 3) the points on B")
      .def_readonly("separations", &Manifold::separations,
                    "(M,) signed separation of each point along normal")
      .def_property_readonly(
          "depths",
          [](const Manifold& mf) {
            return py::array_t<double>(
                py::reinterpret_steal<py::object>(PyNumber_Negative(mf.separations.ptr())));
          },
          "(M,) penetration depths: -separations")
      .def_readonly(
          "ids", &Manifold::ids,
          "(M, 4) int32 feature ids (kind A, index A, kind B, index B), kinds sepax.VERTEX/EDGE/FACE; "
          "stable while the same features stay in contact (warm starting)")
      .def_readonly("id_keys", &Manifold::id_keys, "(M,) uint64 keys of the ids (ContactFeatureId::key)")
      .def_readonly("id_names", &Manifold::id_names, "the ids as text, e.g. 'A:face 1/B:vertex 4'")
      .def_readonly("reference_shape", &Manifold::reference_shape,
                    "face contacts: 0 reference face on A, 1 on B")
      .def_readonly("reference_face", &Manifold::reference_face)
      .def_readonly("incident_face", &Manifold::incident_face)
      .def("__len__", [](const Manifold& mf) { return mf.id_names.size(); })
      .def("__repr__", [](const Manifold& mf) {
        return "<sepax.Manifold: " + mf.kind + ", " + std::to_string(mf.id_names.size()) + " points>";
      });

  py::class_<Result>(m, "Result", "The answer of sepax.query (world coordinates).")
      .def_readonly("overlap", &Result::overlap, "the shapes share a point (touching counts)")
      .def_readonly("separation", &Result::separation,
                    "signed separation along axis (> 0 apart, <= 0 overlapping); exact: the nearest double")
      .def_property_readonly(
          "depth", [](const Result& r) { return r.overlap ? -r.separation : 0.0; },
          "penetration depth (-separation when overlapping, else 0)")
      .def_readonly("axis", &Result::axis, "(3,) unit axis from A towards B (exact: normalised in double)")
      .def_readonly("feature", &Result::feature)
      .def_readonly("early_out", &Result::early_out, "the query stopped at a separation proven > margin")
      .def_readonly("stats", &Result::stats,
                    "face_axes, edge_pairs, minkowski_faces, side_axes, exact_fallbacks")
      .def_readonly(
          "separation_exact", &Result::separation_exact,
          "number='exact': (num, norm2) as fractions.Fraction, separation = num / sqrt(norm2); else None")
      .def_readonly("manifold", &Result::manifold, "the contact Manifold, or None (not asked, or early_out)")
      .def_readonly("number", &Result::number)
      .def_readonly("algorithm", &Result::algorithm)
      .def_readonly("robust", &Result::robust)
      .def("__repr__", [](const Result& r) {
        return std::string("<sepax.Result: ") + (r.overlap ? "overlap" : "separated") + ", separation " +
               number_repr(r.separation) + ", " + feature_repr(r.feature) + ">";
      });

  py::class_<BatchResult>(m, "BatchResult",
                          "The answers of sepax.query_batch as arrays (one row per pose pair).")
      .def_readonly("overlap", &BatchResult::overlap, "(K,) bool")
      .def_readonly("early_out", &BatchResult::early_out, "(K,) bool")
      .def_readonly("separation", &BatchResult::separation, "(K,) float64")
      .def_readonly("axis", &BatchResult::axis, "(K, 3) float64, unit, world")
      .def_readonly("feature_type", &BatchResult::feature_type, "(K,) int8 index into sepax.FEATURE_TYPES")
      .def_readonly("feature", &BatchResult::feature, "(K, 2) int32: the feature's a and b")
      .def_readonly("exact_fallbacks", &BatchResult::exact_fallbacks, "(K,) int64")
      .def_readonly("contact_count", &BatchResult::contact_count, "(K,) int32 or None (manifold=False)")
      .def_readonly("contact_points", &BatchResult::contact_points,
                    "(K, 4, 3) float64, unused rows NaN, or None")
      .def_readonly("contact_separations", &BatchResult::contact_separations,
                    "(K, 4) float64, unused NaN, or None")
      .def_readonly("contact_ids", &BatchResult::contact_ids,
                    "(K, 4, 4) int32 ids as Manifold.ids, unused -1, or None")
      .def_readonly("number", &BatchResult::number)
      .def_readonly("algorithm", &BatchResult::algorithm)
      .def_readonly("robust", &BatchResult::robust)
      .def("__len__", [](const BatchResult& r) { return r.size; })
      .def("__repr__",
           [](const BatchResult& r) { return "<sepax.BatchResult: " + std::to_string(r.size) + " rows>"; });

  m.def("query", &query, py::arg("a"), py::arg("b"), py::arg("pose_a") = py::none(),
        py::arg("pose_b") = py::none(), py::kw_only(), py::arg("number") = "double",
        py::arg("robust").none(false) = true, py::arg("algorithm") = "traversal", py::arg("margin") = 0.0,
        py::arg("early_out").none(false) = false, py::arg("cache") = nullptr,
        py::arg("manifold").none(false) = true,
        R"(query(a, b, pose_a=None, pose_b=None, *, number="double", robust=True, algorithm="traversal",
      margin=0.0, early_out=False, cache=None, manifold=True) -> Result

Separating axis test of shapes a and b at their poses (world = R local + t).  A pose is None
(identity), a (4, 4) matrix, an (R (3, 3), t (3,)) pair or a (3,) translation.

number:    "double", "float" (the shapes' vertices rounded to float), or "exact" (GMP rationals:
           the exact values of the vertices and pose entries; every decision and value exact).
robust:    float/double: every decision an exact filtered predicate (policy::Robust).  False:
           plain rounding arithmetic.  Ignored for "exact".
algorithm: "traversal", "gauss_map" or "brute_force" (same answer, different speed).
margin:    speculative margin (>= 0): the manifold keeps points separated by at most margin;
           with early_out=True the query stops at an axis proven to separate by more.
cache:     a sepax.Cache for this pair (warm start).
manifold:  build the contact manifold (when the query did not stop early).

The GIL is released while the query runs.  Raises sepax.InvalidInput (a ValueError with .code)
for a non-finite or non-rigid pose or a bad margin, ValueError for malformed arguments.)");

  m.def("audit", &audit, py::arg("a"), py::arg("b"), py::arg("pose_a") = py::none(),
        py::arg("pose_b") = py::none(), py::kw_only(), py::arg("number") = "double",
        py::arg("report") = py::none(),
        R"(audit(a, b, pose_a=None, pose_b=None, *, number="double", report=None) -> dict | str

The per-edge-pair sign table of the Minkowski-face test on the input a posed query decides on
(A and B posed into A's frame in `number`, "float" or "double"), decided three ways: the plain
kernel (rounding arithmetic), the robust kernel (exact filtered predicates) and the exact kernel
on the exact images of the same two polyhedra.  Keys: "edges" (n, 2) int32 (edge of A, edge of
B; row ea * B.edge_count + eb); "plain", "robust", "exact" (n, 4) int8 signs (cba, dba, adc,
bdc: sepax/sat_kernel.hpp ArcSigns); "minkowski_*" (n,) bool (the pair is a face of A - B);
"parallel_*" (n,) bool.  The robust columns equal the exact ones by contract; the plain ones
may not (near-degenerate inputs).

report="text" or "json": instead the full audit of `sepax audit` (the fuzzer's: every triple
product with its exact sign, every candidate axis with its separation, error bound and exact
value, the features every configuration and SAT chose, the manifold float against exact, the
differential check), as text or as the parsed JSON object, of A and B posed into A's frame with
every coordinate rounded to float (a UserWarning says how many changed); number="double" audits
double arithmetic on that input.)");
#ifdef SEPAX_PYTHON_TOOLS
  add_tools(m);
#endif

  m.def("query_batch", &query_batch, py::arg("a"), py::arg("b"), py::arg("poses_a"), py::arg("poses_b"),
        py::kw_only(), py::arg("number") = "double", py::arg("robust").none(false) = true,
        py::arg("algorithm") = "traversal", py::arg("margin") = 0.0, py::arg("early_out").none(false) = false,
        py::arg("cache") = nullptr, py::arg("manifold").none(false) = false,
        R"(query_batch(a, b, poses_a, poses_b, *, number="double", robust=True, algorithm="traversal",
            margin=0.0, early_out=False, cache=None, manifold=False) -> BatchResult

sepax.query for K pose pairs in one call, answers as arrays.  poses_a / poses_b: (K, 4, 4), or
(R (K, 3, 3), t (K, 3)), or one pose of any form query takes (broadcast to every row).  Row i
equals query(a, b, poses_a[i], poses_b[i], ...) exactly; with a cache, the rows run in order
with the cache carried from one to the next (a trajectory).  The GIL is released for the whole
batch.)");
}
