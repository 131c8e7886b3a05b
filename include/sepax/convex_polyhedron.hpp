// sepax/convex_polyhedron.hpp
//
// ConvexPolyhedron<T>: a validated convex polyhedron as a half-edge mesh.
//
// Layout (flat arrays, indices are int):
//   vertices     V points
//   half-edges   2E records, stored in twin pairs: half-edge 2k and 2k+1 are
//                the two sides of undirected edge k (twin(h) == h ^ 1).  A
//                half-edge runs from its origin to the origin of its twin, and
//                belongs to the face on its left seen from outside (faces are
//                counter-clockwise seen from outside).
//   faces        F loops, each with a plane and the three vertices that define
//                that plane (the "plane triple", see below).
//   vertex fans  for each vertex, its outgoing half-edges (CSR arrays).
//
// Edge k runs from tail(k) = origin(2k) to head(k) = origin(2k+1); its two faces
// are face(2k) and face(2k+1); its direction head - tail is a positive multiple
// of normal(face(2k)) x normal(face(2k+1)).  On the Gauss map, edge k is the arc
// between those two normals, and the plane of that arc has normal head - tail:
// this is what the Minkowski-face test uses, and it stays defined for a
// double-sided polygon, whose two face normals are opposite.
//
// Planes.  A face's plane is the plane through its plane triple (i, j, k):
//   N = (v_j - v_i) x (v_k - v_i),   offset = N . v_i.
// For number types that normalise (float, double, CORE::Expr) the stored normal
// is N/|N| and the offset is taken with that unit normal; for rationals the
// stored normal is N itself, exactly.  Defining planes by vertex triples makes
// every plane a function of the vertex coordinates alone, so the exact image of
// a float polyhedron (convert_from) has exactly defined planes, and the robust
// predicates can decide the sign of any plane test from the vertices.
//
// Flat shapes.  A convex polygon is a polyhedron with two faces, the polygon and
// its reverse (a double-sided polygon); its two plane triples are the same
// three vertices in opposite order, so its two normals are exactly opposite for
// every T.  is_flat() says which case a polyhedron is.
//
// Validation (from_faces) throws InvalidInput naming the broken rule and the
// offending vertex/face/edge.  See validate() for the list.  Tolerances for
// float and double are in tolerances.hpp; for exact T every check is exact.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "error.hpp"
#include "number_traits.hpp"
#include "tolerances.hpp"
#include "vec3.hpp"

namespace sepax {

struct HalfEdge {
  int origin = -1;  // vertex this half-edge starts at
  int face = -1;    // face on its left (seen from outside)
  int next = -1;    // next half-edge around that face
  int prev = -1;    // previous half-edge around that face
};

struct FaceLoop {
  int edge = -1;                          // first half-edge of the loop
  int count = 0;                          // number of vertices (= half-edges)
  std::array<int, 3> plane_vertices{};    // the plane triple (i, j, k)
};

template <class T>
struct Plane {
  Vec3<T> normal;  // outward; unit length iff number_traits<T>::normalizes
  T offset;        // normal . x == offset on the plane
};

namespace detail {

/// Float and double: |N| / L^2 for N = (b - a) x (c - a) and L the longest
/// side of triangle abc, i.e. its height over its longest side (computed on the
/// sides scaled by a power of two, so at any scale; 0 for a zero or
/// non-finite side).  Rounding alone gives collinear points an aspect up to
/// about 14u; ConvexPolyhedron refuses faces whose plane triangle has an
/// aspect not above Tolerances::sliver (and the hull builder checks 2x that).
template <class T>
double triangle_aspect(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  static_assert(std::is_floating_point_v<T>);
  Vec3<T> u(b - a), w(c - a);
  const T m = max_abs2(u, w);
  if (!(m > T(0)) || !(m <= std::numeric_limits<T>::max())) return 0;
  const int e = pow2_exponent(m);
  u = scale_pow2(u, e);
  w = scale_pow2(w, e);
  const double n = std::sqrt(static_cast<double>(squared_norm(cross(u, w))));
  const double l2 = static_cast<double>(
      std::max({squared_norm(u), squared_norm(w), squared_norm(Vec3<T>(w - u))}));
  return n / l2;
}

/// A double computed on demand and kept: NaN means "not computed yet".  A
/// relaxed atomic, so concurrent readers of a const shape may all compute it
/// and store the same value; copies carry the value (or NaN) over.  noexcept
/// copies, so that ConvexPolyhedron stays nothrow-movable (containers of
/// shapes move rather than copy when they grow).
class LazyDouble {
 public:
  LazyDouble() = default;
  LazyDouble(const LazyDouble& o) noexcept : v_(o.load()) {}
  LazyDouble& operator=(const LazyDouble& o) noexcept {
    store(o.load());
    return *this;
  }
  double load() const noexcept { return v_.load(std::memory_order_relaxed); }
  void store(double x) const noexcept { v_.store(x, std::memory_order_relaxed); }
  void reset() const noexcept { store(std::numeric_limits<double>::quiet_NaN()); }

 private:
  mutable std::atomic<double> v_{std::numeric_limits<double>::quiet_NaN()};
};

}  // namespace detail

/// Plane through three points, normalised when T normalises.
///
/// For float and double the unit normal is scale-safe (scaled_cross in
/// vec3.hpp): when |N|^2 of N = (b - a) x (c - a) would overflow or underflow
/// (coordinates beyond about 1e+-77 for double, 1e+-9 for float), N is taken
/// from b - a and c - a scaled by a power of two.  Wherever the unscaled
/// formula neither overflows nor underflows the normal is bit for bit the one
/// it gives -- the same planes as before, and the robust kernel's error bound
/// on them (robust_kernel.hpp, normal_error; normal_conditioning() here)
/// still holds.  If b - a or c - a themselves overflow, the normal is not
/// finite; ConvexPolyhedron reports that as BadScale.
template <Number T>
inline Plane<T> plane_through_cross(const Vec3<T>& a, const Vec3<T>& e1, const Vec3<T>& e2, const Vec3<T>& c);
template <Number T>
inline Plane<T> plane_through(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  const Vec3<T> e1(b - a), e2(c - a);
  return plane_through_cross(a, e1, e2, Vec3<T>(cross(e1, e2)));
}
/// plane_through(a, a + e1, a + e2) given e1 = b - a, e2 = c - a (as T
/// computes them) and c = cross(e1, e2), computed by the caller.
template <Number T>
inline Plane<T> plane_through_cross(const Vec3<T>& a, const Vec3<T>& e1, const Vec3<T>& e2, const Vec3<T>& c) {
  Vec3<T> n = scaled_cross(e1, e2, c);
  if constexpr (number_traits<T>::normalizes) {
    const T len = number_traits<T>::sqrt(squared_norm(n));
    if (len > T(0)) n = Vec3<T>(n[0] / len, n[1] / len, n[2] / len);
  }
  const T off = dot(n, a);
  return Plane<T>{n, off};
}

namespace hull::detail {
template <class T>
struct HullPolyhedron;  // the hull builder's construction (hull/to_polyhedron.hpp)
}  // namespace hull::detail

template <Number T>
class ConvexPolyhedron {
 public:
  using Scalar = T;

  ConvexPolyhedron() = default;

  /// Build from vertices and faces (each face a list of vertex indices,
  /// counter-clockwise seen from outside), and validate.  A flat shape is given
  /// as two faces: the polygon and the same polygon reversed.
  static ConvexPolyhedron from_faces(std::vector<Vec3<T>> vertices,
                                     const std::vector<std::vector<int>>& faces) {
    ConvexPolyhedron p;
    p.vertices_ = std::move(vertices);
    p.check_coordinates();
    p.build_topology(faces);
    p.choose_plane_triples();
    p.compute_derived();
    p.validate_geometry();
    return p;
  }

  /// A double-sided convex polygon from its vertices in order (either
  /// orientation); the first face's normal follows the right-hand rule.
  static ConvexPolyhedron polygon(std::vector<Vec3<T>> loop) {
    std::vector<int> front(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i) front[i] = static_cast<int>(i);
    std::vector<int> back(front.rbegin(), front.rend());
    return from_faces(std::move(loop), {front, back});
  }

  /// The same combinatorics and plane triples with the vertices converted from
  /// another number type U (float or double) to T.  Planes and the centroid
  /// are recomputed in T.  No geometric re-validation: the exact image of a
  /// float polyhedron may have faces that are planar only up to float rounding,
  /// and sepax defines each face's plane by its plane triple exactly so that
  /// float and exact runs see "the same inputs".  The range is checked as for
  /// from_faces (a double shape beyond float's range is BadScale, not
  /// infinities).
  template <Number U>
  static ConvexPolyhedron convert_from(const ConvexPolyhedron<U>& other) {
    ConvexPolyhedron p;
    p.vertices_.reserve(other.vertex_count());
    for (const auto& v : other.vertices()) {
      p.vertices_.push_back(vec_cast<T>(v));
      for (int c = 0; c < 3; ++c) {
        if (!number_traits<T>::is_finite(p.vertices_.back()[c]) && number_traits<U>::is_finite(v[c])) {
          throw coordinate_beyond_range(c, "vertex", p.vertices_.size() - 1, number_traits<U>::to_double(v[c]),
                                        number_traits<T>::name);
        }
      }
    }
    p.half_edges_ = other.half_edges();
    p.faces_ = other.faces();
    p.fan_start_ = other.fan_start();
    p.fan_ = other.fan();
    p.check_coordinates();
    p.compute_derived();
    p.check_new_range();
    return p;
  }

  /// Same topology with new vertex positions (for rigid motions: the caller
  /// guarantees the new positions are a rigid image of the old ones).
  /// Throws InvalidInput: NonFinite (a NaN or infinite coordinate), BadScale
  /// (float/double: coordinates beyond the range check_range() documents).
  ConvexPolyhedron with_vertices(std::vector<Vec3<T>> vertices) const {
    ConvexPolyhedron p = *this;
    p.vertices_ = std::move(vertices);
    if (p.vertices_.size() != vertices_.size()) {
      fail(ErrorCode::BadIndex, "with_vertices: " + std::to_string(p.vertices_.size()) + " vertices for a shape of " +
                                    std::to_string(vertices_.size()));
    }
    p.check_coordinates();
    p.compute_derived();
    p.check_new_range();
    return p;
  }

  /// Make *this the rigid image of src (posing.hpp is the documented entry
  /// point and states the formula): src's topology and plane triples, the
  /// vertices point(v) for every vertex of src, and everything else
  /// recomputed from them exactly as with_vertices does (bit for bit the same
  /// planes, edge arrays, lanes and bounds), in one pass per array, with
  /// normal_conditioning() computed along with the planes (the robust kernel
  /// asks for it on every posed query).  The topology is copied from src
  /// unless same_topology says *this already holds it.  Reuses the capacity
  /// of *this: no allocation once it has held a shape at least as large.
  /// Throws as with_vertices does (NonFinite, BadScale).
  template <class Point>
  void assign_rigid_image(const ConvexPolyhedron& src, bool same_topology, Point&& point) {
    assign_rigid_vertices(src, same_topology, point);
    finish_rigid_image();
  }

  /// assign_rigid_image in two steps, for the posed queries' checks that
  /// need only a few of B's planes (posing.hpp, "Staged posing").  Step 1:
  /// the topology (unless same_topology), the vertices point(v), the bounds,
  /// centroid, extent and max |coordinate| (the values assign_rigid_image
  /// gives), and the range checks on them (NonFinite, BadScale).  The result
  /// is a *partial* image: planes, per-edge arrays and lanes are not set
  /// (lanes_bounded() is false, normal_conditioning() +infinity) until
  /// derive_rigid_part (some of them) or finish_rigid_image (all of them).
  template <class Point>
  void assign_rigid_vertices(const ConvexPolyhedron& src, bool same_topology, Point&& point) {
    if (!same_topology) {
      half_edges_ = src.half_edges_;
      faces_ = src.faces_;
      fan_start_ = src.fan_start_;
      fan_ = src.fan_;
    }
    vertices_.resize(src.vertices_.size());
    for (std::size_t i = 0; i < vertices_.size(); ++i) vertices_[i] = point(src.vertices_[i]);
    check_coordinates();
    planes_.resize(faces_.size());
    const auto ne = static_cast<std::size_t>(edge_count());
    edge_dirs_.resize(ne);
    edge_n0_.resize(ne);
    edge_n1_.resize(ne);
    lanes_bounded_ = false;
    normal_conditioning_.store(std::numeric_limits<double>::infinity());
    compute_bounds();
    if constexpr (!number_traits<T>::is_exact) {
      if (!(extent_ > 0)) fail(ErrorCode::BadScale, "all vertices coincide: the shape has no extent");
      check_range(false);
    }
  }

  /// Step 2 of a partial image (after assign_rigid_vertices): the planes of
  /// `faces` (both faces of a flat shape) and the per-edge entries of
  /// `edges` (each edge's two faces must be among `faces`), computed as
  /// finish_rigid_image computes them, and normal_conditioning() the scan
  /// over those faces only (for float/double; the robust kernel's δ_B is
  /// then a bound for exactly those planes).  Still a partial image: valid
  /// only for the kernel queries that read these planes and edges (the
  /// other planes, edges and the lanes are stale).
  void derive_rigid_part(std::span<const int> faces, std::span<const int> edges) {
    [[maybe_unused]] NormalConditioningScan scan;
    auto derive = [&](int f) {
      const auto& t = faces_[static_cast<std::size_t>(f)].plane_vertices;
      const Vec3<T>& v0 = vertex(t[0]);
      const Vec3<T> e1(vertex(t[1]) - v0), e2(vertex(t[2]) - v0);
      const Vec3<T> c(cross(e1, e2));
      planes_[static_cast<std::size_t>(f)] = plane_through_cross(v0, e1, e2, c);
      if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) scan.add(e1, e2, c);
    };
    if (is_flat()) {
      derive(0);  // the back face: the front one negated (compute_derived)
      planes_[1] = Plane<T>{Vec3<T>(-planes_[0].normal), T(-planes_[0].offset)};
    } else {
      for (const int f : faces) derive(f);
    }
    for (const int e : edges) {
      const auto k = static_cast<std::size_t>(e);
      const HalfEdge& h0 = half_edges_[2 * k];
      const HalfEdge& h1 = half_edges_[2 * k + 1];
      edge_dirs_[k] = Vec3<T>(vertex(h1.origin) - vertex(h0.origin));
      edge_n0_[k] = planes_[static_cast<std::size_t>(h0.face)].normal;
      edge_n1_[k] = planes_[static_cast<std::size_t>(h1.face)].normal;
    }
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) normal_conditioning_.store(scan.result());
  }

  /// Step 2 of assign_rigid_image after assign_rigid_vertices: every plane,
  /// per-edge array, lane and normal_conditioning(), and the plane checks;
  /// *this is then bit for bit what assign_rigid_image gives.
  void finish_rigid_image() {
    compute_derived(true, false);
    check_new_range();
  }

  // ---- sizes ----
  int vertex_count() const { return static_cast<int>(vertices_.size()); }
  int half_edge_count() const { return static_cast<int>(half_edges_.size()); }
  int edge_count() const { return half_edge_count() / 2; }
  int face_count() const { return static_cast<int>(faces_.size()); }
  bool empty() const { return vertices_.empty(); }
  /// A double-sided polygon (two faces with opposite normals).
  bool is_flat() const { return faces_.size() == 2; }

  // ---- vertices ----
  const Vec3<T>& vertex(int v) const { return vertices_[static_cast<std::size_t>(v)]; }
  const std::vector<Vec3<T>>& vertices() const { return vertices_; }
  /// Outgoing half-edges of vertex v.
  std::span<const int> vertex_half_edges(int v) const {
    const auto b = static_cast<std::size_t>(fan_start_[static_cast<std::size_t>(v)]);
    const auto e = static_cast<std::size_t>(fan_start_[static_cast<std::size_t>(v) + 1]);
    return std::span<const int>(fan_.data() + b, e - b);
  }

  // ---- half-edges and edges ----
  static int twin(int h) { return h ^ 1; }
  const HalfEdge& half_edge(int h) const { return half_edges_[static_cast<std::size_t>(h)]; }
  const std::vector<HalfEdge>& half_edges() const { return half_edges_; }
  int edge_tail(int e) const { return half_edge(2 * e).origin; }
  int edge_head(int e) const { return half_edge(2 * e + 1).origin; }
  /// side 0: the face of half-edge 2e; side 1: the face of half-edge 2e+1.
  int edge_face(int e, int side) const { return half_edge(2 * e + side).face; }
  /// head - tail; parallel to normal(edge_face(e,0)) x normal(edge_face(e,1)).
  Vec3<T> edge_direction(int e) const {
    return Vec3<T>(vertex(edge_head(e)) - vertex(edge_tail(e)));
  }

  // ---- per-edge data for the Minkowski-face test (structure of arrays) ----
  // Recomputed with the planes (from_faces, convert_from, with_vertices), one
  // entry per undirected edge e, in edge order:
  //   edge_directions()[e]   head - tail, the same value edge_direction(e)
  //                          computes (one subtraction per coordinate in T);
  //   edge_normals(s)[e]     plane(edge_face(e, s)).normal, copied.
  // Contiguous arrays, so the Gauss map's edge-pair loop streams through B's
  // edges without the half-edge and face indirections.  Vec3<T> for every T,
  // exact types included: the values are exactly those of the accessors above.
  std::span<const Vec3<T>> edge_directions() const { return edge_dirs_; }
  /// Normals of the faces on side 0 (face of half-edge 2e) or side 1 (2e+1).
  std::span<const Vec3<T>> edge_normals(int side) const {
    return side == 0 ? std::span<const Vec3<T>>(edge_n0_) : std::span<const Vec3<T>>(edge_n1_);
  }
  /// edge_directions()[e].
  const Vec3<T>& edge_dir(int e) const { return edge_dirs_[static_cast<std::size_t>(e)]; }
  /// edge_normals(side)[e] == plane(edge_face(e, side)).normal.
  const Vec3<T>& edge_normal(int e, int side) const {
    return (side == 0 ? edge_n0_ : edge_n1_)[static_cast<std::size_t>(e)];
  }

  // ---- lane arrays: one array per coordinate (float and double only) ----
  // The values above again, split by coordinate for SIMD scans (simd_lanes.hpp):
  //   lane_edge(k)[e], k = 0..2: edge_normal(e, 0) x, y, z;
  //                    3..5: -edge_normal(e, 1) (negated: exact, and the arc
  //                          test then wants all four products of one sign);
  //                    6..8: edge_dir(e)                (the Gauss map's arc test)
  //   lane_vertex(c)[v], c = 0..2: vertex(v)[c]          (support scans)
  // Copies (or exact negations), not recomputations.  Each array is padded to
  // a multiple of kLanePad entries (the padding holds zeros and is masked out
  // by every scan).  Empty for exact T.
  // lanes_bounded(): every value above (normals, directions, vertices, plane
  // normals) is finite with magnitude <= 2^60, so no dot product of a normal
  // with a direction or a vertex can overflow or be NaN: the SIMD scans rely
  // on it, and callers fall back to scalar code when it is false.
  static constexpr int kLanePad = 8;
  bool lanes_bounded() const { return lanes_bounded_; }
  int lane_edge_stride() const { return lane_edge_stride_; }
  const T* lane_edge(int k) const { return lanes_.data() + static_cast<std::size_t>(k * lane_edge_stride_); }
  int lane_vertex_stride() const { return lane_vertex_stride_; }
  const T* lane_vertex(int c) const {
    return lanes_.data() + static_cast<std::size_t>(9 * lane_edge_stride_ + c * lane_vertex_stride_);
  }

  // ---- faces ----
  const FaceLoop& face(int f) const { return faces_[static_cast<std::size_t>(f)]; }
  const std::vector<FaceLoop>& faces() const { return faces_; }
  const Plane<T>& plane(int f) const { return planes_[static_cast<std::size_t>(f)]; }
  const std::vector<Plane<T>>& planes() const { return planes_; }
  /// The face's vertex indices in loop order.
  std::vector<int> face_vertices(int f) const {
    std::vector<int> out;
    out.reserve(static_cast<std::size_t>(face(f).count));
    int h = face(f).edge;
    for (int i = 0; i < face(f).count; ++i) {
      out.push_back(half_edge(h).origin);
      h = half_edge(h).next;
    }
    return out;
  }
  /// The face's plane triple as points.
  std::array<Vec3<T>, 3> plane_points(int f) const {
    const auto& t = face(f).plane_vertices;
    return {vertex(t[0]), vertex(t[1]), vertex(t[2])};
  }

  // ---- derived geometry ----
  /// Average of the vertices: strictly inside a solid, strictly inside the
  /// polygon of a flat shape (rounded to T for float types).
  const Vec3<T>& centroid() const { return centroid_; }
  const Vec3<T>& bounds_min() const { return bmin_; }
  const Vec3<T>& bounds_max() const { return bmax_; }
  /// Length of the bounding-box diagonal, as a double: the scale every
  /// tolerance is relative to.  (For exact T it is used for reporting only.)
  double extent() const { return extent_; }
  /// max |coordinate| over all vertices, as a double (for filter bounds).
  double max_abs_coordinate() const { return max_abs_; }
  /// Float and double: ρ_P = max over the faces of |ẽ1||ẽ2| / |Ñ|, ẽ1, ẽ2 the
  /// plane triple's differences and Ñ their cross product, all rounded to T
  /// (the values the stored normals come from), evaluated in double; +infinity
  /// ("no bound") when some Ñ is tiny or something overflows.  A shape-only
  /// term of the robust kernel's normal error bound δ_P (robust/error_bounds.hpp,
  /// ErrorConstants::normal_error): computed on the first call after the vertices were set
  /// (from_faces, convert_from, with_vertices) and kept, so robust queries
  /// pay for it once per shape and plain ones never.  Thread-safe (a relaxed
  /// atomic; concurrent first calls compute and store the same value).
  /// +infinity for other T.
  double normal_conditioning() const {
    double r = normal_conditioning_.load();
    if (std::isnan(r)) [[unlikely]] {
      r = compute_normal_conditioning();
      normal_conditioning_.store(r);
    }
    return r;
  }
  /// |Ñ|^2 at or below this counts as tiny in normal_conditioning().
  static constexpr double kNormalTinySquared = [] {
    if constexpr (std::is_floating_point_v<T>) return static_cast<double>(std::numeric_limits<T>::min()) * 0x1p40;
    else return 0.0;
  }();

  // raw arrays, for converters and serialisers
  const std::vector<int>& fan_start() const { return fan_start_; }
  const std::vector<int>& fan() const { return fan_; }

 private:
  template <Number U>
  friend class ConvexPolyhedron;

  template <class>
  friend struct hull::detail::HullPolyhedron;

  [[noreturn]] static void fail(ErrorCode code, const std::string& what) {
    throw InvalidInput(code, what);
  }

  void check_coordinates() {
    for (std::size_t i = 0; i < vertices_.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        if (!number_traits<T>::is_finite(vertices_[i][c])) {
          std::ostringstream s;
          s << "vertex " << i << " has a non-finite coordinate (NaN or infinity)";
          fail(ErrorCode::NonFinite, s.str());
        }
      }
    }
    if (vertices_.size() < 3) {
      fail(ErrorCode::TooFewPoints, "a polyhedron needs at least 3 vertices, got " +
                                        std::to_string(vertices_.size()));
    }
  }

  void build_topology(const std::vector<std::vector<int>>& faces) {
    const int nv = vertex_count();
    if (faces.size() < 2) fail(ErrorCode::NotManifold, "a closed polyhedron needs at least 2 faces");
    // The directed edges leaving each vertex, in the order the loops list
    // them (out_[out_start[u] ..]), each with its half-edge once assigned:
    // (u, v) was seen before iff one of u's assigned slots heads to v.
    struct OutEdge {
      int head, half_edge;
    };
    std::vector<int> out_start(static_cast<std::size_t>(nv) + 1, 0);
    for (const auto& loop : faces)
      for (int u : loop)
        if (u >= 0 && u < nv) ++out_start[static_cast<std::size_t>(u) + 1];
    for (int v = 0; v < nv; ++v)
      out_start[static_cast<std::size_t>(v) + 1] += out_start[static_cast<std::size_t>(v)];
    std::vector<OutEdge> out(static_cast<std::size_t>(out_start.back()));
    std::vector<int> out_next(out_start.begin(), out_start.end() - 1);  // u's first unassigned slot
    auto seen = [&](int u, int v) {  // the half-edge of an earlier u -> v, or -1
      for (int k = out_start[static_cast<std::size_t>(u)]; k < out_next[static_cast<std::size_t>(u)]; ++k)
        if (out[static_cast<std::size_t>(k)].head == v) return out[static_cast<std::size_t>(k)].half_edge;
      return -1;
    };
    half_edges_.clear();
    faces_.clear();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const auto& loop = faces[f];
      const std::string fname = "face " + std::to_string(f);
      if (loop.size() < 3) fail(ErrorCode::DegenerateFace, fname + " has fewer than 3 vertices");
      for (std::size_t i = 0; i < loop.size(); ++i) {
        if (loop[i] < 0 || loop[i] >= nv) {
          fail(ErrorCode::BadIndex, fname + " refers to vertex " + std::to_string(loop[i]) +
                                        ", but there are only " + std::to_string(nv) + " vertices");
        }
        for (std::size_t j = 0; j < i; ++j) {
          if (loop[i] == loop[j]) {
            fail(ErrorCode::DegenerateFace,
                 fname + " uses vertex " + std::to_string(loop[i]) + " twice");
          }
        }
      }
      FaceLoop fl;
      fl.count = static_cast<int>(loop.size());
      std::vector<int> loop_edges;
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const int u = loop[i];
        const int v = loop[(i + 1) % loop.size()];
        if (seen(u, v) >= 0) {
          fail(ErrorCode::NotManifold,
               "edge " + std::to_string(u) + "->" + std::to_string(v) +
                   " is used twice in the same direction (second time in " + fname +
                   "): faces are inconsistently oriented or the surface is not a 2-manifold");
        }
        const auto key = std::minmax(u, v);
        int h;
        const int twin = seen(v, u);
        if (twin < 0) {
          const int e = static_cast<int>(half_edges_.size() / 2);
          half_edges_.push_back(HalfEdge{});
          half_edges_.push_back(HalfEdge{});
          h = 2 * e;
        } else {
          h = 2 * (twin / 2) + 1;
          if (half_edges_[static_cast<std::size_t>(h)].face != -1) {
            fail(ErrorCode::NotManifold, "edge " + std::to_string(key.first) + "-" +
                                             std::to_string(key.second) +
                                             " is shared by more than two faces");
          }
        }
        out[static_cast<std::size_t>(out_next[static_cast<std::size_t>(u)]++)] = OutEdge{v, h};
        half_edges_[static_cast<std::size_t>(h)].origin = u;
        half_edges_[static_cast<std::size_t>(h)].face = static_cast<int>(f);
        loop_edges.push_back(h);
      }
      for (std::size_t i = 0; i < loop_edges.size(); ++i) {
        auto& he = half_edges_[static_cast<std::size_t>(loop_edges[i])];
        he.next = loop_edges[(i + 1) % loop_edges.size()];
        he.prev = loop_edges[(i + loop_edges.size() - 1) % loop_edges.size()];
      }
      fl.edge = loop_edges[0];
      faces_.push_back(fl);
    }
    for (std::size_t h = 0; h < half_edges_.size(); ++h) {
      if (half_edges_[h].face == -1) {
        const auto& o = half_edges_[h ^ 1];
        const int u = o.origin;
        const int v = half_edges_[static_cast<std::size_t>(o.next)].origin;
        fail(ErrorCode::NotManifold, "edge " + std::to_string(u) + "-" + std::to_string(v) +
                                         " has only one face: the surface is not closed");
      }
    }
    // vertex fans
    std::vector<int> degree(static_cast<std::size_t>(nv), 0);
    for (const auto& he : half_edges_) ++degree[static_cast<std::size_t>(he.origin)];
    for (int v = 0; v < nv; ++v) {
      if (degree[static_cast<std::size_t>(v)] == 0) {
        fail(ErrorCode::UnusedVertex, "vertex " + std::to_string(v) + " is on no face");
      }
    }
    fan_start_.assign(static_cast<std::size_t>(nv) + 1, 0);
    for (int v = 0; v < nv; ++v)
      fan_start_[static_cast<std::size_t>(v) + 1] =
          fan_start_[static_cast<std::size_t>(v)] + degree[static_cast<std::size_t>(v)];
    fan_.assign(half_edges_.size(), -1);
    std::vector<int> fill(fan_start_.begin(), fan_start_.end() - 1);
    for (std::size_t h = 0; h < half_edges_.size(); ++h) {
      const auto o = static_cast<std::size_t>(half_edges_[h].origin);
      fan_[static_cast<std::size_t>(fill[o]++)] = static_cast<int>(h);
    }
    const long euler = static_cast<long>(nv) - static_cast<long>(edge_count()) +
                       static_cast<long>(face_count());
    if (euler != 2) {
      fail(ErrorCode::BadEuler, "V - E + F = " + std::to_string(nv) + " - " +
                                    std::to_string(edge_count()) + " + " +
                                    std::to_string(face_count()) + " = " + std::to_string(euler) +
                                    ", not 2: the surface is not a topological sphere");
    }
  }

  // Plane triple: the best-conditioned triangle (0, j, k) of the face loop
  // (largest |cross| in T) for faces of up to 16 vertices; (0, n/3, 2n/3) for
  // larger ones.  For the back face of a flat shape, the front face's triple
  // reversed, so the two normals are exactly opposite.
  // |(b-a) x (c-a)|^2, for choosing plane triples.  For float T every product
  // is rounded on its own (volatile stores), so no a*b+c can be fused into an
  // FMA: the choice -- which the exact images inherit through convert_from --
  // is then the same with and without -march=native -ffp-contract=fast (ties
  // between equally good triangles are common in symmetric faces).  Without
  // contraction the values are exactly those of cross() and squared_norm().
  static T triangle_area2(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
    const Vec3<T> u(b - a), w(c - a);
    if constexpr (number_traits<T>::is_exact) {
      return squared_norm(cross(u, w));
    } else {
      const auto mul = [](T x, T y) {
        volatile T r = x * y;
        return static_cast<T>(r);
      };
      const T x = T(mul(u[1], w[2]) - mul(u[2], w[1]));
      const T y = T(mul(u[2], w[0]) - mul(u[0], w[2]));
      const T z = T(mul(u[0], w[1]) - mul(u[1], w[0]));
      T s = mul(x, x);
      s = s + mul(y, y);
      s = s + mul(z, z);
      return s;
    }
  }

  // For float T the areas are compared on the face's vertices relative to
  // loop[0], scaled by one power of two per face (largest |component| in
  // [1, 2)): the squared areas then neither overflow nor underflow at any
  // scale, and since the scaling is exact and commutes with rounding, every
  // comparison -- hence the chosen triple -- is the same as unscaled wherever
  // the unscaled squares stayed in range.
  void choose_plane_triples() {
    for (int f = 0; f < face_count(); ++f) {
      const auto loop = face_vertices(f);
      const int n = static_cast<int>(loop.size());
      std::array<int, 3> best{loop[0], loop[1], loop[2]};
      if (n <= 16) {
        std::vector<Vec3<T>> rel;  // loop vertices relative to loop[0] (scaled for float)
        rel.reserve(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) rel.push_back(Vec3<T>(vertex(loop[i]) - vertex(loop[0])));
        if constexpr (std::is_floating_point_v<T>) {
          T m(0);
          for (const auto& r : rel) m = std::max(m, detail::max_abs2(r, r));
          if (m > T(0) && m <= std::numeric_limits<T>::max()) {
            const int e = detail::pow2_exponent(m);
            for (auto& r : rel) r = detail::scale_pow2(r, e);
          }
        }
        const Vec3<T> origin(T(0), T(0), T(0));
        T best_area(-1);
        for (int j = 1; j + 1 < n; ++j) {
          for (int k = j + 1; k < n; ++k) {
            const T a = triangle_area2(origin, rel[static_cast<std::size_t>(j)],
                                       rel[static_cast<std::size_t>(k)]);
            if (a > best_area) {
              best_area = a;
              best = {loop[0], loop[j], loop[k]};
            }
          }
        }
      } else {
        best = {loop[0], loop[n / 3], loop[(2 * n) / 3]};
      }
      faces_[static_cast<std::size_t>(f)].plane_vertices = best;
    }
    if (face_count() == 2) {
      const auto& t = faces_[0].plane_vertices;
      faces_[1].plane_vertices = {t[0], t[2], t[1]};
    }
  }

  // The planes from the plane triples, then everything after them.  With
  // eager_conditioning (float/double), normal_conditioning() is computed in
  // the same pass from the plane triples' differences and cross products
  // (the value compute_normal_conditioning() gives, bit for bit: the same
  // expressions and the same scan, NormalConditioningScan).
  void compute_derived(bool eager_conditioning = false, bool with_bounds = true) {
    const auto nf = faces_.size();
    planes_.resize(nf);
    [[maybe_unused]] NormalConditioningScan scan;
    [[maybe_unused]] const bool cond = eager_conditioning && (std::is_same_v<T, float> || std::is_same_v<T, double>);
    for (std::size_t f = 0; f < nf; ++f) {
      if (f == 1 && nf == 2) {
        // Flat shape: the back face's plane is exactly the front one negated.
        // That is what plane_through on the reversed triple gives in exact
        // arithmetic and in plain IEEE arithmetic (a*b - c*d is antisymmetric);
        // under FMA contraction (-march=native -ffp-contract=fast) it is not,
        // and the "exactly opposite normals" invariant broke (tests/fma).
        planes_[1] = Plane<T>{Vec3<T>(-planes_[0].normal), T(-planes_[0].offset)};
        continue;
      }
      const auto& t = faces_[f].plane_vertices;
      const Vec3<T>& v0 = vertex(t[0]);
      const Vec3<T> e1(vertex(t[1]) - v0), e2(vertex(t[2]) - v0);
      const Vec3<T> c(cross(e1, e2));
      planes_[f] = plane_through_cross(v0, e1, e2, c);
      if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
        if (cond) scan.add(e1, e2, c);
      }
    }
    normal_conditioning_.reset();  // new coordinates: computed again on first use
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
      if (cond) normal_conditioning_.store(scan.result());
    }
    compute_edge_data();
    if (with_bounds) compute_bounds();
  }

  // Everything after the planes: per-edge arrays and lanes.  Reuses the
  // arrays' capacity.
  void compute_edge_data() {
    // per-edge arrays (after the planes: the normals are copies of theirs)
    const auto ne = static_cast<std::size_t>(edge_count());
    edge_dirs_.resize(ne);
    edge_n0_.resize(ne);
    edge_n1_.resize(ne);
    for (std::size_t e = 0; e < ne; ++e) {
      const HalfEdge& h0 = half_edges_[2 * e];
      const HalfEdge& h1 = half_edges_[2 * e + 1];
      edge_dirs_[e] = Vec3<T>(vertex(h1.origin) - vertex(h0.origin));  // edge_direction(e)
      edge_n0_[e] = planes_[static_cast<std::size_t>(h0.face)].normal;
      edge_n1_[e] = planes_[static_cast<std::size_t>(h1.face)].normal;
    }
    compute_lanes();
  }

  // From the vertices alone: bounds, centroid, extent, max |coordinate|.
  void compute_bounds() {
    Vec3<T> sum(T(0), T(0), T(0));
    bmin_ = bmax_ = vertices_.empty() ? sum : vertices_[0];
    for (const auto& v : vertices_) {
      sum = Vec3<T>(sum + v);
      for (int c = 0; c < 3; ++c) {
        if (v[c] < bmin_[c]) bmin_[c] = v[c];
        if (v[c] > bmax_[c]) bmax_[c] = v[c];
      }
    }
    const T n = from_double<T>(static_cast<double>(vertices_.size()));  // exact for any count < 2^53
    if (!vertices_.empty()) centroid_ = Vec3<T>(sum[0] / n, sum[1] / n, sum[2] / n);
    double d2 = 0;
    max_abs_ = 0;
    std::array<double, 3> w{};
    for (int c = 0; c < 3; ++c) {
      w[static_cast<std::size_t>(c)] = to_double(T(bmax_[c] - bmin_[c]));
      d2 += w[static_cast<std::size_t>(c)] * w[static_cast<std::size_t>(c)];
      max_abs_ = std::max({max_abs_, std::abs(to_double(bmin_[c])), std::abs(to_double(bmax_[c]))});
    }
    extent_ = std::sqrt(d2);
    if (!detail::safe_squared_norm(d2)) {
      // Widths beyond about 1e+-154 (double T): the same diagonal through
      // widths scaled by a power of two (bit for bit the unscaled value where
      // that does not overflow or underflow).  Stays infinite if a width is.
      const double m = std::max({w[0], w[1], w[2]});
      if (m > 0 && m <= std::numeric_limits<double>::max()) {
        const int e = std::ilogb(m);
        double s2 = 0;
        for (const double wc : w) s2 += std::ldexp(wc, -e) * std::ldexp(wc, -e);
        extent_ = std::ldexp(std::sqrt(s2), e);
      }
    }
    if constexpr (std::is_floating_point_v<T>) {
      // The vertex sum overflows long before the coordinates do (n vertices
      // near max/n): then the centroid is the sum of the vertices scaled by a
      // power of two, divided by n and scaled back -- bit for bit the plain
      // formula's value wherever that one does not overflow.
      if (!vertices_.empty() && !(sum.cwiseAbs().maxCoeff() <= std::numeric_limits<T>::max())) {
        const int e = detail::pow2_exponent(static_cast<T>(max_abs_));
        Vec3<T> s(T(0), T(0), T(0));
        for (const auto& v : vertices_) s = Vec3<T>(s + detail::scale_pow2(v, e));
        centroid_ = detail::scale_pow2(Vec3<T>(s[0] / n, s[1] / n, s[2] / n), -e);
      }
    }
  }

  // ρ_P of normal_conditioning(), for the robust kernel's δ_P (derivation in
  // robust/error_bounds.hpp, unit_error_from_ratio: δ_f = γ_4 + 2q/(|Ñ| - q) with
  // q/|Ñ| = γ_4 √2 ρ_f/(1-u)^2 per face, so the worst face is the one with the
  // largest ρ_f = |ẽ1||ẽ2|/|Ñ|).  ẽ1 = fl(v_j - v_i), ẽ2 = fl(v_k - v_i),
  // Ñ = fl(ẽ1 x ẽ2) in T, as plane_through computes them (see there for the
  // range where it rescales).  The bound only uses |Ñ| to bound the exact |N|
  // from below (|N| >= |Ñ| - q), so any evaluation of the cross product with
  // |Ñ - N| <= q will do, contracted or not.  "Tiny": |Ñ|^2 <=
  // kNormalTinySquared = 2^40 min(T) (normalisation underflow; the kernel's
  // margin covers what remains above it, see robust_kernel.hpp).  The back
  // face of a flat shape is skipped: its normal is exactly the front one
  // negated (compute_derived) and its exact N is -N_front, so its δ is the
  // front face's.  This is the loop RobustKernel ran over every face of both
  // shapes on every query (normal_error) until it moved here.
  double compute_normal_conditioning() const {
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
      NormalConditioningScan scan;
      const int nf = is_flat() ? 1 : face_count();
      for (int f = 0; f < nf; ++f) {
        const auto& t = face(f).plane_vertices;
        const Vec3<T>& v0 = vertex(t[0]);
        const Vec3<T> e1(vertex(t[1]) - v0), e2(vertex(t[2]) - v0);
        scan.add(e1, e2, Vec3<T>(cross(e1, e2)));
      }
      return scan.result();
    } else {
      return std::numeric_limits<double>::infinity();
    }
  }

  // The scan of compute_normal_conditioning() over the plane triples (v0, v1,
  // v2), one face at a time, given ẽ1 = fl(v1 - v0), ẽ2 = fl(v2 - v0) and
  // Ñ = fl(ẽ1 x ẽ2) in T (cross()); their squares in double.
  struct NormalConditioningScan {
    // float: the maximum of r2 = |ẽ1|^2 |ẽ2|^2 / |Ñ|^2 without a division or
    // a finiteness test per face: the maximum fraction num/den is tracked by
    // cross multiplication.  Every factor is a double square of a float
    // (<= 3 * 2^256), so num * den < 2^1024 cannot overflow; an infinite or
    // NaN difference or cross product, or a tiny |Ñ|, sets `bad`.  The one
    // division and sqrt at the end round once each (relative 2^-53, inside
    // the kernel's margin).
    // double: the squares can overflow, so one ratio per face, infinite when
    // not finite (never NaN, which a maximum would skip).
    double wnum = 0, wden = 1, worst = 0;
    bool bad = false;

    void add(const Vec3<T>& e1, const Vec3<T>& e2, const Vec3<T>& n) {
      auto sq = [](const Vec3<T>& v) {
        const double x = v[0], y = v[1], z = v[2];
        return x * x + y * y + z * z;
      };
      const double nc2 = sq(n);
      if constexpr (std::is_same_v<T, float>) {
        const double num = sq(e1) * sq(e2);
        bad |= !(nc2 > kNormalTinySquared && nc2 <= std::numeric_limits<double>::max() &&
                 num <= std::numeric_limits<double>::max());
        const bool larger = num * wden > wnum * nc2;
        wnum = larger ? num : wnum;
        wden = larger ? nc2 : wden;
      } else {
        double r2 = std::numeric_limits<double>::infinity();
        if (nc2 > kNormalTinySquared && std::isfinite(nc2)) {
          r2 = sq(e1) / nc2 * sq(e2);
          if (!std::isfinite(r2)) r2 = std::numeric_limits<double>::infinity();
        }
        if (r2 > worst) worst = r2;
      }
    }
    double result() const {
      if constexpr (std::is_same_v<T, float>) {
        if (bad) return std::numeric_limits<double>::infinity();
        return std::sqrt(wnum / wden);
      } else {
        return std::sqrt(worst);
      }
    }
  };

  // The lane arrays from the per-edge arrays and the vertices, each value
  // written once (only the padding is zeroed).  lanes_bounded_: every lane
  // value and every plane normal has |x| <= 2^60 (false for NaN).  The edge
  // normal lanes are copies (or negations) of plane normals and the padding
  // is zero, so that is: every plane normal, edge direction and vertex
  // coordinate; tested without a branch per value.
  void compute_lanes() {
    lane_edge_stride_ = lane_vertex_stride_ = 0;
    lanes_bounded_ = false;
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
      auto padded = [](int n) { return (n + kLanePad - 1) / kLanePad * kLanePad; };
      lane_edge_stride_ = padded(edge_count());
      lane_vertex_stride_ = padded(vertex_count());
      const auto es = static_cast<std::size_t>(lane_edge_stride_);
      const auto vs = static_cast<std::size_t>(lane_vertex_stride_);
      const auto ne = static_cast<std::size_t>(edge_count());
      const auto nv = static_cast<std::size_t>(vertex_count());
      lanes_.resize(9 * es + 3 * vs);
      T* const l = lanes_.data();
      const T big = T(0x1p60);
      bool ok = true;
      for (std::size_t e = 0; e < ne; ++e) {
        const Vec3<T>& n0 = edge_n0_[e];
        const Vec3<T>& n1 = edge_n1_[e];
        const Vec3<T>& d = edge_dirs_[e];
        for (std::size_t c = 0; c < 3; ++c) {
          l[c * es + e] = n0[static_cast<int>(c)];
          l[(3 + c) * es + e] = T(-n1[static_cast<int>(c)]);
          l[(6 + c) * es + e] = d[static_cast<int>(c)];
          ok &= std::abs(d[static_cast<int>(c)]) <= big;
        }
      }
      for (std::size_t k = 0; k < 9; ++k) std::fill(l + k * es + ne, l + (k + 1) * es, T(0));
      T* const lv = l + 9 * es;
      for (std::size_t v = 0; v < nv; ++v) {
        for (std::size_t c = 0; c < 3; ++c) {
          const T x = vertices_[v][static_cast<int>(c)];
          lv[c * vs + v] = x;
          ok &= std::abs(x) <= big;
        }
      }
      for (std::size_t c = 0; c < 3; ++c) std::fill(lv + c * vs + nv, lv + (c + 1) * vs, T(0));
      for (const auto& pl : planes_) {
        for (int c = 0; c < 3; ++c) ok &= std::abs(pl.normal[c]) <= big;
      }
      lanes_bounded_ = ok;
    } else {
      lanes_.clear();
    }
  }

  // Signed distance-like value of p above plane f: exact N.(p - v_i) for exact
  // T; the Euclidean signed distance for normalising T.
  T height(int f, const Vec3<T>& p) const {
    const auto& pl = plane(f);
    return T(dot(pl.normal, p) - pl.offset);
  }

  // Tolerance in height() units for a relative tolerance rel.
  T height_tolerance(double rel) const {
    if constexpr (number_traits<T>::is_exact) {
      (void)rel;
      return T(0);
    } else {
      return static_cast<T>(rel * extent_);
    }
  }

  static std::string num_str(double x) {
    std::ostringstream s;
    s.precision(3);
    s << x;
    return s.str();
  }

  // Float and double work at any scale (planes, normals, extent and centroid
  // are computed scale-safely, see plane_through and scaled_cross) within
  //   |coordinate| <= max(T)/16   (so that sums and differences of a few
  //                               coordinates -- edges, plane offsets, the
  //                               SATs' projections and distances between two
  //                               such shapes -- stay finite), and
  //   coplanar/4 * extent >= min(T), the smallest normal number (so that the
  //                               relative tolerances are not subnormal, where
  //                               rounding is no longer small against them).
  // Out of range is refused here with BadScale, naming the quantity that does
  // not fit, before any geometric check can misreport it.
  void check_range(bool planes = true) {
    const std::string tname(number_traits<T>::name);
    const double limit = static_cast<double>(std::numeric_limits<T>::max()) / 16;
    if (!(max_abs_ <= limit)) {
      fail(ErrorCode::BadScale, "coordinates up to " + num_str(max_abs_) +
                                    " are out of range for " + tname + ": sepax needs |coordinate| <= " +
                                    num_str(limit) +
                                    " (max/16) so that edges, plane offsets and projections stay finite");
    }
    const double smallest_tol = Tolerances<T>::coplanar / 4 * extent_;
    if (!(smallest_tol >= static_cast<double>(std::numeric_limits<T>::min()))) {
      fail(ErrorCode::BadScale, "extent " + num_str(extent_) + " is too small for " + tname +
                                    ": the validation tolerances (relative to the extent) fall "
                                    "into its subnormal range");
    }
    if (!planes) return;
    // (cannot fail within the range above)  One pass without a branch per
    // value; the face is looked for only when some plane is not finite.
    bool all_finite = true;
    const T tmax = std::numeric_limits<T>::max();
    for (const auto& pl : planes_) {
      all_finite &= std::abs(pl.offset) <= tmax;  // false for NaN and infinities
      for (int c = 0; c < 3; ++c) all_finite &= std::abs(pl.normal[c]) <= tmax;
    }
    if (all_finite) [[likely]] return;
    for (int f = 0; f < face_count(); ++f) {
      const auto& pl = plane(f);
      bool finite = number_traits<T>::is_finite(pl.offset);
      for (int c = 0; c < 3; ++c) finite = finite && number_traits<T>::is_finite(pl.normal[c]);
      if (!finite) {
        fail(ErrorCode::BadScale, "face " + std::to_string(f) + ": its plane overflows " + tname +
                                      "; coordinates reach " + num_str(max_abs_));
      }
    }
  }

  // Float and double: the plane triangle's height over its longest side
  // (detail::triangle_aspect); not above Tolerances::sliver means zero area up
  // to rounding.
  double triple_aspect(int f) const {
    const auto& t = face(f).plane_vertices;
    return detail::triangle_aspect(vertex(t[0]), vertex(t[1]), vertex(t[2]));
  }

  // convert_from and with_vertices: no geometric re-validation, but the new
  // coordinates must be finite (check_coordinates, before the planes) and, for
  // float/double, within check_range()'s range, or the planes and every SAT
  // on them would be infinities and NaN.
  void check_new_range() {
    if constexpr (!number_traits<T>::is_exact) {
      if (!(extent_ > 0)) fail(ErrorCode::BadScale, "all vertices coincide: the shape has no extent");
      check_range();
    }
  }

  // The local convexity certificate of a large closed shape (validate_geometry
  // uses it instead of every vertex against every face plane when
  // faces x vertices > kConvexityScanPairs): face f's witnesses are, across
  // each of its edges, the two vertices of the neighbouring face next to that
  // edge.  Every edge convex (those witnesses below f's plane) and every vertex
  // wound once (vertex_windings_once) on a closed, consistently oriented
  // genus-0 surface make the surface convex (docs/hull.md, "Validation").
  void local_convexity_witnesses(int f, std::vector<int>& out) const {
    out.clear();
    int h = face(f).edge;
    for (int i = 0; i < face(f).count; ++i, h = half_edge(h).next) {
      const HalfEdge& t = half_edge(twin(h));
      out.push_back(half_edge(half_edge(t.next).next).origin);
      out.push_back(half_edge(t.prev).origin);
    }
  }

  // Every vertex of a large solid is wound once: its neighbours, projected on
  // the plane normal to the sum of its faces' normals (inside the normal cone
  // of a convex corner), turn once around it (a ray-crossing count; exact for
  // exact T).  A star wound twice has convex edges but is not convex.
  // Returns false at the first vertex that is not wound once.  For float and
  // double the count is taken on rounded projections with no tolerance, while
  // the edges are convex only within Tolerances::convexity: a corner whose
  // faces are convex within that tolerance can count 0.  The certificate is
  // sufficient, not necessary, so validate_geometry then decides by the full
  // scan of every vertex against every face plane.
  bool vertex_windings_once() const {
    for (int v = 0; v < vertex_count(); ++v) {
      const auto fan = vertex_half_edges(v);
      Vec3<T> m(T(0), T(0), T(0));
      for (int h : fan) m = Vec3<T>(m + plane(half_edge(h).face).normal);
      int k = 0;
      for (int c = 1; c < 3; ++c)
        if (abs_of(m[c]) < abs_of(m[k])) k = c;
      Vec3<T> axis(T(0), T(0), T(0));
      axis[k] = T(1);
      const Vec3<T> a = cross(m, axis), b = cross(m, a);
      // neighbours in order around v: the head of each outgoing half-edge h,
      // the next one twin(prev(h))
      std::vector<std::array<T, 2>> ring;
      int h = fan[0];
      do {
        const Vec3<T> d(vertex(half_edge(twin(h)).origin) - vertex(v));
        ring.push_back({dot(a, d), dot(b, d)});
        h = twin(half_edge(h).prev);
      } while (h != fan[0] && ring.size() <= fan.size());
      int wind = 0;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const auto& p = ring[i];
        const auto& q = ring[(i + 1) % ring.size()];
        const T side = T(p[0] * q[1] - p[1] * q[0]);
        if (p[1] <= T(0) && q[1] > T(0) && side > T(0)) ++wind;
        if (q[1] <= T(0) && p[1] > T(0) && side < T(0)) --wind;
      }
      if (wind != 1 && wind != -1) return false;
    }
    return true;
  }

  void validate_geometry(double scan_pairs = kConvexityScanPairs) {
    if (!(extent_ > 0)) fail(ErrorCode::BadScale, "all vertices coincide: the shape has no extent");
    if constexpr (!number_traits<T>::is_exact) check_range();
    const T plan_tol = height_tolerance(Tolerances<T>::planarity);
    const T conv_tol = height_tolerance(Tolerances<T>::convexity);
    // faces: non-zero area, planar, convex loops
    for (int f = 0; f < face_count(); ++f) {
      const auto& pl = plane(f);
      if constexpr (number_traits<T>::is_exact) {
        if (is_zero(pl.normal)) {
          fail(ErrorCode::DegenerateFace, "face " + std::to_string(f) +
                                              " has zero area (its vertices are collinear)");
        }
      } else {
        const double aspect = triple_aspect(f);
        if (!(aspect > Tolerances<T>::sliver)) {
          const auto& t = face(f).plane_vertices;
          fail(ErrorCode::DegenerateFace,
               "face " + std::to_string(f) + " has zero area up to rounding: its widest triangle (vertices " +
                   std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                   ") is only " + num_str(aspect) +
                   " times as high as its longest side (Tolerances::sliver = " +
                   num_str(Tolerances<T>::sliver) + "); its normal would be rounding noise");
        }
      }
      const auto loop = face_vertices(f);
      const int n = static_cast<int>(loop.size());
      for (int i = 0; i < n; ++i) {
        const T h = height(f, vertex(loop[static_cast<std::size_t>(i)]));
        if (abs_of(h) > plan_tol) {
          fail(ErrorCode::NonPlanarFace,
               "face " + std::to_string(f) + " is not planar: vertex " + std::to_string(loop[i]) +
                   " is " + std::to_string(to_double(h)) + " off the face's plane");
        }
      }
      for (int i = 0; i < n; ++i) {
        const Vec3<T>& a = vertex(loop[static_cast<std::size_t>((i + n - 1) % n)]);
        const Vec3<T>& b = vertex(loop[static_cast<std::size_t>(i)]);
        const Vec3<T>& c = vertex(loop[static_cast<std::size_t>((i + 1) % n)]);
        Vec3<T> ab(b - a);
        Vec3<T> bc(c - b);
        bool bad;
        if constexpr (number_traits<T>::is_exact) {
          bad = !(dot(pl.normal, cross(ab, bc)) > T(0));
        } else {
          // turn/|ab| is the distance of c from the line a-b (times |n| = 1).
          // ab, bc and the tolerance scaled by one power of two (largest
          // |component| in [1, 2)) so that the cross product and |ab|^2 stay
          // in range at any scale; exact, so the same decision as unscaled
          // wherever that stays in range.
          T tol = conv_tol;
          const T m = detail::max_abs2(ab, bc);
          if (m > T(0) && m <= std::numeric_limits<T>::max()) {
            const int e = detail::pow2_exponent(m);
            ab = detail::scale_pow2(ab, e);
            bc = detail::scale_pow2(bc, e);
            tol = std::ldexp(tol, -e);
          }
          const T turn = dot(pl.normal, cross(ab, bc));
          const T lab = number_traits<T>::sqrt(squared_norm(ab));
          bad = !(lab > T(0)) || turn < -(tol * lab);
        }
        if (bad) {
          fail(ErrorCode::NonConvexFace,
               "face " + std::to_string(f) + " is not convex at vertex " +
                   std::to_string(loop[static_cast<std::size_t>(i)]) +
                   (number_traits<T>::is_exact ? " (reflex or collinear corner)" : " (reflex corner)"));
        }
      }
    }
    if (is_flat()) {
      // (normals compared for exact opposition, not by a cross product: under
      // FMA contraction cross(n, -n) need not be exactly 0)
      if (!(plane(1).normal == Vec3<T>(-plane(0).normal)) ||
          !(dot(plane(0).normal, plane(1).normal) < T(0))) {
        fail(ErrorCode::NotConvex, "a two-face shape must be a polygon and its reverse");
      }
      return;
    }
    // solids: every vertex has degree >= 3
    for (int v = 0; v < vertex_count(); ++v) {
      if (vertex_half_edges(v).size() < 3) {
        fail(ErrorCode::NotConvex, "vertex " + std::to_string(v) +
                                       " has only two edges (it lies in the middle of an edge)");
      }
    }
    // global convexity and orientation: every vertex against every face
    // plane, or on large shapes the local certificate (local_convexity_witnesses)
    const bool scan = static_cast<double>(face_count()) * static_cast<double>(vertex_count()) <= scan_pairs ||
                      !vertex_windings_once();
    int faces_all_above = 0;
    int first_bad_face = -1, first_bad_vertex = -1;
    double first_bad_height = 0;
    std::vector<int> witnesses;
    for (int f = 0; f < face_count(); ++f) {
      bool any_below = false, any_above = false;
      if (!scan) local_convexity_witnesses(f, witnesses);
      const int count = scan ? vertex_count() : static_cast<int>(witnesses.size());
      for (int i = 0; i < count; ++i) {
        const int v = scan ? i : witnesses[static_cast<std::size_t>(i)];
        const T h = height(f, vertex(v));
        if (h < -conv_tol) any_below = true;
        if (h > conv_tol) {
          any_above = true;
          if (first_bad_face < 0) {
            first_bad_face = f;
            first_bad_vertex = v;
            first_bad_height = to_double(h);
          }
        }
      }
      if (any_above && !any_below) ++faces_all_above;
    }
    if (faces_all_above == face_count()) {
      fail(ErrorCode::InwardFaces,
           "all faces point inward: list each face counter-clockwise seen from outside");
    }
    if (first_bad_face >= 0) {
      fail(ErrorCode::NotConvex, "not convex: vertex " + std::to_string(first_bad_vertex) +
                                     " is " + std::to_string(first_bad_height) +
                                     " above the plane of face " + std::to_string(first_bad_face));
    }
    // adjacent faces must not be coplanar (they must be merged)
    for (int e = 0; e < edge_count(); ++e) {
      const int f = edge_face(e, 0), g = edge_face(e, 1);
      bool coplanar;
      if constexpr (number_traits<T>::is_exact) {
        coplanar = is_zero(cross(plane(f).normal, plane(g).normal));
      } else {
        const T tol = height_tolerance(Tolerances<T>::coplanar / 4);
        coplanar = true;
        int h = face(g).edge;
        for (int i = 0; i < face(g).count && coplanar; ++i, h = half_edge(h).next)
          coplanar = !(abs_of(height(f, vertex(half_edge(h).origin))) > tol);
      }
      if (coplanar) {
        fail(ErrorCode::NotConvex, "faces " + std::to_string(f) + " and " + std::to_string(g) +
                                       " are adjacent and coplanar: merge them into one face");
      }
    }
  }

  std::vector<Vec3<T>> vertices_;
  std::vector<HalfEdge> half_edges_;
  std::vector<FaceLoop> faces_;
  std::vector<Plane<T>> planes_;
  std::vector<int> fan_start_;
  std::vector<int> fan_;
  std::vector<Vec3<T>> edge_dirs_;  // per edge: head - tail
  std::vector<Vec3<T>> edge_n0_;    // per edge: normal of edge_face(e, 0)
  std::vector<Vec3<T>> edge_n1_;    // per edge: normal of edge_face(e, 1)
  std::vector<T> lanes_;            // lane arrays (float/double): 9 edge, then 3 vertex arrays
  int lane_edge_stride_ = 0, lane_vertex_stride_ = 0;
  bool lanes_bounded_ = false;
  Vec3<T> centroid_ = Vec3<T>(T(0), T(0), T(0));
  Vec3<T> bmin_ = Vec3<T>(T(0), T(0), T(0));
  Vec3<T> bmax_ = Vec3<T>(T(0), T(0), T(0));
  double extent_ = 0;
  double max_abs_ = 0;
  detail::LazyDouble normal_conditioning_;  // NaN until normal_conditioning() computes it
};

}  // namespace sepax
