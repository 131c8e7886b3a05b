// sepax/robust/cgal_adapters.hpp
//
// ConvexPolyhedron<T>  <->  CGAL polygon meshes (CGAL::Surface_mesh<Point_3> and
// CGAL::Polyhedron_3<K>), both directions, faces kept as polygons (no
// triangulation), for any sepax number type T and any CGAL kernel K:
//   to_cgal_mesh<Mesh>(P)      P's vertices and faces, in P's order;
//   from_cgal_mesh<T>(mesh)    ConvexPolyhedron<T>::from_faces (validated);
//   convert_number<To>(x)      exact where the target can hold the value:
//                              float/double -> anything, exact -> exact (through
//                              GMP mpq, never through double); exact -> float /
//                              double rounds to nearest.
// A flat ConvexPolyhedron (double-sided polygon) becomes a two-face closed mesh
// (the polygon and its reverse), which both CGAL meshes represent.
#pragma once

#include <CGAL/Gmpq.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <gmpxx.h>

#include <map>
#include <type_traits>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/robust/number_types.hpp>

namespace sepax::cgal {

namespace detail {
template <class X>
struct is_lazy : std::false_type {};
template <class ET>
struct is_lazy<CGAL::Lazy_exact_nt<ET>> : std::true_type {};

template <class X>
constexpr bool is_floating_v = std::is_same_v<X, float> || std::is_same_v<X, double>;

template <class X>
constexpr bool is_rational_v =
    std::is_same_v<X, mpq_class> || std::is_same_v<X, CGAL::Gmpq> || is_lazy<X>::value;
}  // namespace detail

/// The exact rational value of x.
template <class X>
mpq_class to_mpq(const X& x) {
  if constexpr (std::is_same_v<X, mpq_class>) {
    return x;
  } else if constexpr (std::is_same_v<X, CGAL::Gmpq>) {
    return mpq_class(x.mpq());
  } else if constexpr (detail::is_lazy<X>::value) {
    return to_mpq(CGAL::exact(x));
  } else if constexpr (detail::is_floating_v<X>) {
    return mpq_class(static_cast<double>(x));
  } else if constexpr (requires { mpq_class(x.backend().data()); }) {
    // boost::multiprecision::mpq_rational (Epeck's exact type when CGAL is
    // configured without gmpxx)
    return mpq_class(x.backend().data());
  } else {
    static_assert(detail::is_rational_v<X>, "to_mpq: not a rational number type");
  }
}

/// The rational q as a To (exact for exact To).
template <class To>
To from_mpq(const mpq_class& q) {
  if constexpr (std::is_same_v<To, mpq_class>) {
    return q;
  } else if constexpr (std::is_same_v<To, CGAL::Gmpq>) {
    return CGAL::Gmpq(q.get_mpq_t());
  } else if constexpr (detail::is_lazy<To>::value) {
    using ET = typename To::Exact_type;
    return To(from_mpq<ET>(q));
  } else if constexpr (detail::is_floating_v<To>) {
    return static_cast<To>(q.get_d());  // rounds: exact -> float is documented as rounding
  } else if constexpr (requires(To t) { mpq_set(t.backend().data(), q.get_mpq_t()); }) {
    To t;  // boost::multiprecision::mpq_rational
    mpq_set(t.backend().data(), q.get_mpq_t());
    return t;
  } else {
    static_assert(detail::is_rational_v<To>, "from_mpq: not a supported number type");
  }
}

/// x as a To:
///   * float/double -> anything: exact (every double is a rational);
///   * exact -> exact (mpq_class, CGAL::Gmpq, CGAL::Lazy_exact_nt<ET> e.g.
///     Epeck::FT, in any combination): exact, through the rational value
///     (GMP mpq), never through double;
///   * exact -> float/double: rounds to nearest (CGAL::to_double), so that an
///     exact mesh can be brought to a float ConvexPolyhedron, which is then
///     validated in float with the tolerances of tolerances.hpp.
template <class To, class From>
To convert_number(const From& x) {
  if constexpr (std::is_same_v<To, From>) {
    return x;
  } else if constexpr (detail::is_floating_v<From>) {
    if constexpr (detail::is_floating_v<To>) {
      return static_cast<To>(x);
    } else {
      return To(static_cast<double>(x));  // exact: every double is a rational
    }
  } else if constexpr (detail::is_floating_v<To>) {
    return static_cast<To>(CGAL::to_double(x));
  } else {
    return from_mpq<To>(to_mpq(x));
  }
}

template <class Mesh>
using mesh_point_t = typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type;

/// ConvexPolyhedron<T> -> Mesh (Surface_mesh<K::Point_3> or Polyhedron_3<K>):
/// P's vertices in P's order and one polygon per face of P, in P's face order
/// and loop order.
template <class Mesh, Number T>
Mesh to_cgal_mesh(const ConvexPolyhedron<T>& p) {
  using Point = mesh_point_t<Mesh>;
  using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
  using vd = typename boost::graph_traits<Mesh>::vertex_descriptor;
  Mesh m;
  std::vector<vd> vs;
  vs.reserve(static_cast<std::size_t>(p.vertex_count()));
  auto vpm = get(CGAL::vertex_point, m);
  for (const auto& v : p.vertices()) {
    const vd d = add_vertex(m);
    put(vpm, d, Point(convert_number<FT>(v[0]), convert_number<FT>(v[1]), convert_number<FT>(v[2])));
    vs.push_back(d);
  }
  for (int f = 0; f < p.face_count(); ++f) {
    std::vector<vd> loop;
    for (int v : p.face_vertices(f)) loop.push_back(vs[static_cast<std::size_t>(v)]);
    if (CGAL::Euler::add_face(loop, m) == boost::graph_traits<Mesh>::null_face()) {
      throw InvalidInput(ErrorCode::NotManifold,
                         "to_cgal_mesh: CGAL refused face " + std::to_string(f) + " (not a 2-manifold)");
    }
  }
  return m;
}

/// Mesh -> ConvexPolyhedron<T>, validated (throws InvalidInput): a mesh that
/// is not a convex polyhedron with maximal faces (e.g. a triangulated hull
/// with coplanar neighbours: use cgal_hull.hpp) gets InvalidInput naming the
/// problem.  Vertices in
/// the mesh's vertex order, faces in its face order, loops as in the mesh.
template <Number T, class Mesh>
ConvexPolyhedron<T> from_cgal_mesh(const Mesh& m) {
  using vd = typename boost::graph_traits<Mesh>::vertex_descriptor;
  std::map<vd, int> index;
  std::vector<Vec3<T>> pts;
  const auto vpm = get(CGAL::vertex_point, m);
  for (const vd v : vertices(m)) {
    const auto& q = get(vpm, v);
    index.emplace(v, static_cast<int>(pts.size()));
    pts.push_back(Vec3<T>(convert_number<T>(q.x()), convert_number<T>(q.y()), convert_number<T>(q.z())));
  }
  std::vector<std::vector<int>> faces_;
  for (const auto f : faces(m)) {
    std::vector<int> loop;
    for (const vd v : CGAL::vertices_around_face(halfedge(f, m), m)) loop.push_back(index.at(v));
    faces_.push_back(std::move(loop));
  }
  return ConvexPolyhedron<T>::from_faces(std::move(pts), faces_);
}

}  // namespace sepax::cgal
