// sepax/convex_polyhedron.hpp
//
// ConvexPolyhedron<T>: a validated convex polyhedron as a half-edge mesh, and
// the records it is made of (HalfEdge, FaceLoop; its planes: plane.hpp).
// The class declares everything here, with the public accessors; its larger
// steps are defined in one header per concept, included at the end:
//   convex_polyhedron_topology.hpp    face lists to half-edges, vertex fans and
//                                     plane triples (build_topology());
//   convex_polyhedron_derived.hpp     planes, per-edge arrays, SIMD lanes,
//                                     bounds, normal_conditioning();
//   convex_polyhedron_validation.hpp  coordinates, range, topology and
//                                     convexity checks (validate_geometry());
//   convex_polyhedron_rigid.hpp       the rigid image a posed query decides
//                                     on (posing.hpp documents it).
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "error.hpp"
#include "plane.hpp"
#include "number_traits.hpp"
#include "tolerances.hpp"
#include "simd_ops.hpp"
#include "vec3.hpp"

namespace sepax {

struct HalfEdge {
  int origin = -1;  // vertex this half-edge starts at
  int face = -1;    // face on its left (seen from outside)
  int next = -1;    // next half-edge around that face
  int prev = -1;    // previous half-edge around that face
};

struct FaceLoop {
  int edge = -1;                        // first half-edge of the loop
  int count = 0;                        // number of vertices (= half-edges)
  std::array<int, 3> plane_vertices{};  // the plane triple (i, j, k)
};

namespace detail {

/// The combinatorics of a ConvexPolyhedron (its half-edges, face loops with
/// their plane triples and vertex fans; the class comment gives the layout).
/// It does not depend on the number type or on the vertex positions, so a
/// copy, a rigid image (with_vertices, the posed queries' images) and a
/// conversion to another number type (convert_from) all share one instance.
struct PolyhedronTopology {
  std::vector<HalfEdge> half_edges;
  std::vector<FaceLoop> faces;
  std::vector<int> fan_start;  // per vertex v, its fan is fan[fan_start[v], fan_start[v + 1])
  std::vector<int> fan;
};

/// A shared, read-only PolyhedronTopology: copies share it (one reference
/// count increment, no array copy), so moving a shape between polyhedra costs
/// the same for any size.  edit() gives write access to a topology only this
/// holder refers to (copying it first otherwise), for the builder of a new
/// polyhedron, which calls refresh() when it is done.  Never null: a default
/// or moved-from holder refers to one shared empty topology.  The arrays'
/// data pointers and sizes are kept beside the pointer, so the accessors of
/// the hot loops load one pointer, as from a vector member.
class SharedTopology {
 public:
  SharedTopology() noexcept : p_(empty()) { refresh(); }
  SharedTopology(const SharedTopology&) noexcept = default;
  SharedTopology& operator=(const SharedTopology&) noexcept = default;
  SharedTopology(SharedTopology&& o) noexcept : SharedTopology(static_cast<const SharedTopology&>(o)) {
    o.reset();
  }
  SharedTopology& operator=(SharedTopology&& o) noexcept {
    if (this != &o) {
      *this = static_cast<const SharedTopology&>(o);
      o.reset();
    }
    return *this;
  }
  const PolyhedronTopology& get() const noexcept { return *p_; }
  const PolyhedronTopology* operator->() const noexcept { return p_.get(); }
  const HalfEdge* half_edges() const noexcept { return half_edges_; }
  const FaceLoop* faces() const noexcept { return faces_; }
  const int* fan_start() const noexcept { return fan_start_; }
  const int* fan() const noexcept { return fan_; }
  int half_edge_count() const noexcept { return half_edge_count_; }
  int face_count() const noexcept { return face_count_; }
  /// Write access for building: a topology no other holder refers to.  The
  /// data pointers above are stale once an array is resized, until refresh().
  PolyhedronTopology& edit() {
    if (p_.use_count() != 1) {
      p_ = std::make_shared<PolyhedronTopology>(*p_);
      refresh();
    }
    return *p_;
  }
  /// After edit(): the data pointers and sizes of the arrays as they are now.
  void refresh() noexcept {
    half_edges_ = p_->half_edges.data();
    faces_ = p_->faces.data();
    fan_start_ = p_->fan_start.data();
    fan_ = p_->fan.data();
    half_edge_count_ = static_cast<int>(p_->half_edges.size());
    face_count_ = static_cast<int>(p_->faces.size());
  }
  /// Whether both refer to the same topology.
  bool same_as(const SharedTopology& o) const noexcept { return p_ == o.p_; }

 private:
  static const std::shared_ptr<PolyhedronTopology>& empty() noexcept {
    static const std::shared_ptr<PolyhedronTopology> e = std::make_shared<PolyhedronTopology>();
    return e;
  }
  void reset() noexcept {
    p_ = empty();
    refresh();
  }
  std::shared_ptr<PolyhedronTopology> p_;
  const HalfEdge* half_edges_ = nullptr;
  const FaceLoop* faces_ = nullptr;
  const int* fan_start_ = nullptr;
  const int* fan_ = nullptr;
  int half_edge_count_ = 0;
  int face_count_ = 0;
};

}  // namespace detail

namespace detail {

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

namespace hull::detail {
template <class T>
struct HullPolyhedron;  // the hull builder's construction (hull/to_polyhedron.hpp)
}  // namespace hull::detail

/// ConvexPolyhedron<T>: a validated convex polyhedron as a half-edge mesh.
///
/// Layout (flat arrays, indices are int):
///   vertices     V points
///   half-edges   2E records, stored in twin pairs: half-edge 2k and 2k+1 are
///                the two sides of undirected edge k (twin(h) == h ^ 1).  A
///                half-edge runs from its origin to the origin of its twin, and
///                belongs to the face on its left seen from outside (faces are
///                counter-clockwise seen from outside).
///   faces        F loops, each with a plane and the three vertices that define
///                that plane (the "plane triple", see below).
///   vertex fans  for each vertex, its outgoing half-edges (CSR arrays).
///
/// Edge k runs from tail(k) = origin(2k) to head(k) = origin(2k+1); its two faces
/// are face(2k) and face(2k+1); its direction head - tail is a positive multiple
/// of normal(face(2k)) x normal(face(2k+1)).  On the Gauss map, edge k is the arc
/// between those two normals, and the plane of that arc has normal head - tail:
/// this is what the Minkowski-face test uses, and it stays defined for a
/// double-sided polygon, whose two face normals are opposite.
///
/// Planes.  A face's plane is the plane through its plane triple (i, j, k):
///   N = (v_j - v_i) x (v_k - v_i),   offset = N . v_i.
/// For number types that normalise (float, double, CORE::Expr) the stored normal
/// is N/|N| and the offset is taken with that unit normal; for rationals the
/// stored normal is N itself, exactly.  Defining planes by vertex triples makes
/// every plane a function of the vertex coordinates alone, so the exact image of
/// a float polyhedron (convert_from) has exactly defined planes, and the robust
/// predicates can decide the sign of any plane test from the vertices.
///
/// Flat shapes.  A convex polygon is a polyhedron with two faces, the polygon and
/// its reverse (a double-sided polygon); its two plane triples are the same
/// three vertices in opposite order, so its two normals are exactly opposite for
/// every T.  is_flat() says which case a polyhedron is.
///
/// Validation (from_faces) throws InvalidInput naming the broken rule and the
/// offending vertex/face/edge (convex_polyhedron_validation.hpp).  Tolerances for
/// float and double are in tolerances.hpp; for exact T every check is exact.
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
          throw coordinate_beyond_range(c, "vertex", p.vertices_.size() - 1,
                                        number_traits<U>::to_double(v[c]), number_traits<T>::name);
        }
      }
    }
    p.topology_ = other.topology_;
    p.check_coordinates();
    p.compute_derived();
    if (!(p.extent_ > 0) && other.extent() > 0) {
      // (check_new_range would say the vertices coincide: they do only after the conversion)
      const std::string t(number_traits<T>::name), u(number_traits<U>::name);
      fail(ErrorCode::BadScale, "converted to " + t + ", every vertex of the shape (extent " +
                                    num_str(other.extent()) + " in " + u +
                                    ") rounds to the same point: below " + t + "'s range");
    }
    p.check_new_range();
    return p;
  }

  /// Same topology with new vertex positions (for rigid motions: the caller
  /// guarantees the new positions are a rigid image of the old ones).
  /// Throws InvalidInput: NonFinite (a NaN or infinite coordinate), BadScale
  /// (float/double: coordinates beyond the range check_range() documents;
  /// any T: a face whose plane triple is collinear at the new coordinates,
  /// check_plane_normals).
  ConvexPolyhedron with_vertices(std::vector<Vec3<T>> vertices) const {
    ConvexPolyhedron p = *this;
    p.vertices_ = std::move(vertices);
    if (p.vertices_.size() != vertices_.size()) {
      fail(ErrorCode::BadIndex, "with_vertices: " + std::to_string(p.vertices_.size()) +
                                    " vertices for a shape of " + std::to_string(vertices_.size()));
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
  /// planes, edge arrays, lanes and bounds), in one pass over the vertices,
  /// one over the faces and one over the edges (assign_rigid_vertices,
  /// finish_rigid_image), with normal_conditioning() computed along with the
  /// planes (the robust kernel asks for it on every posed query).  The topology is src's, shared
  /// (detail::SharedTopology), never copied.  Reuses the capacity
  /// of *this: no allocation once it has held a shape at least as large.
  /// Throws as with_vertices does (NonFinite, BadScale, a face without a plane).
  template <class Point>
  void assign_rigid_image(const ConvexPolyhedron& src, Point&& point) {
    assign_rigid_vertices(src, point);
    finish_rigid_image();
  }

  /// assign_rigid_image in two steps, for the posed queries' checks that
  /// need only a few of B's planes (posing.hpp, "Staged posing").  Step 1:
  /// the topology (shared with src), the vertices point(v), the bounds,
  /// centroid, extent and max |coordinate| (the values assign_rigid_image
  /// gives), and the range checks on them (NonFinite, BadScale).  The result
  /// is a *partial* image: planes, per-edge arrays and edge lanes are not
  /// set (lanes_bounded() is false, normal_conditioning() +infinity) until
  /// derive_rigid_part (some of them) or finish_rigid_image (all of them).
  /// Float/double: one pass over the vertices computes each image point,
  /// writes it and its vertex lanes, and adds it to the bounds, the sum and
  /// the finiteness test (the values compute_bounds and compute_lanes give,
  /// bit for bit: the same sequential sum, the same comparisons).  With
  /// point_lanes (not nullptr), the vertices come W at a time from src's
  /// vertex lanes: point_lanes(x, y, z) maps simd::Lanes<T> vectors of
  /// coordinates to their images in place, lane by lane bit for bit what
  /// point gives (point takes the remainder); the sum then runs over the
  /// written lanes in index order.
  template <class Point, class PointLanes = std::nullptr_t>
  void assign_rigid_vertices(const ConvexPolyhedron& src, Point&& point, PointLanes&& point_lanes = nullptr);

  /// Step 2 of a partial image (after assign_rigid_vertices): the planes of
  /// `faces` (both faces of a flat shape) and the per-edge entries of
  /// `edges` (each edge's two faces must be among `faces`), computed as
  /// finish_rigid_image computes them, and normal_conditioning() the scan
  /// over those faces only (for float/double; the robust kernel's δ_B is
  /// then a bound for exactly those planes).  Still a partial image: valid
  /// only for the kernel queries that read these planes and edges (the
  /// other planes, edges and the lanes are stale).
  void derive_rigid_part(std::span<const int> faces, std::span<const int> edges);

  /// Step 2 of assign_rigid_image after assign_rigid_vertices: every plane,
  /// per-edge array, lane and normal_conditioning(), and the plane checks;
  /// *this is then bit for bit what assign_rigid_image gives.  Float/double:
  /// one pass over the faces (plane, conditioning scan, range of the normals
  /// and offsets) and one over the edges (per-edge arrays and their edge
  /// lanes, range of the directions).  edge_lanes = false leaves the 9 edge
  /// lane arrays unwritten (only sat::gauss_map's batched arc test reads
  /// them, simd::arc_candidates) and everything else, lanes_bounded()
  /// included, as with them; finish_rigid_edge_lanes() writes them later.
  void finish_rigid_image(bool edge_lanes = true);

  /// After finish_rigid_image(false): the edge lane arrays, as
  /// finish_rigid_image(true) writes them.
  void finish_rigid_edge_lanes() {
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) write_edge_lanes();
  }

  // ---- sizes ----
  int vertex_count() const { return static_cast<int>(vertices_.size()); }
  int half_edge_count() const { return topology_.half_edge_count(); }
  int edge_count() const { return half_edge_count() / 2; }
  int face_count() const { return topology_.face_count(); }
  bool empty() const { return vertices_.empty(); }
  /// A double-sided polygon (two faces with opposite normals).
  bool is_flat() const { return topology_.face_count() == 2; }

  // ---- vertices ----
  const Vec3<T>& vertex(int v) const { return vertices_[static_cast<std::size_t>(v)]; }
  const std::vector<Vec3<T>>& vertices() const { return vertices_; }
  /// Outgoing half-edges of vertex v.
  std::span<const int> vertex_half_edges(int v) const {
    const auto b = static_cast<std::size_t>(topology_.fan_start()[static_cast<std::size_t>(v)]);
    const auto e = static_cast<std::size_t>(topology_.fan_start()[static_cast<std::size_t>(v) + 1]);
    return std::span<const int>(topology_.fan() + b, e - b);
  }

  // ---- half-edges and edges ----
  static int twin(int h) { return h ^ 1; }
  const HalfEdge& half_edge(int h) const { return topology_.half_edges()[static_cast<std::size_t>(h)]; }
  const std::vector<HalfEdge>& half_edges() const { return topology_->half_edges; }
  int edge_tail(int e) const { return half_edge(2 * e).origin; }
  int edge_head(int e) const { return half_edge(2 * e + 1).origin; }
  /// side 0: the face of half-edge 2e; side 1: the face of half-edge 2e+1.
  int edge_face(int e, int side) const { return half_edge(2 * e + side).face; }

  // ---- per-edge data for the Minkowski-face test (structure of arrays) ----
  // Recomputed with the planes (from_faces, convert_from, with_vertices), one
  // entry per undirected edge e, in edge order:
  //   edge_directions()[e]   head - tail (one subtraction per coordinate in
  //                          T), parallel to normal(edge_face(e, 0)) x
  //                          normal(edge_face(e, 1));
  //   edge_normal(e, s)      plane(edge_face(e, s)).normal, read from the
  //                          plane (no copy per edge: a posed image would
  //                          copy every normal per query to save an
  //                          indirection per read).
  // A contiguous array, so the Gauss map's edge-pair loop streams through
  // B's edge directions without the half-edge indirections.
  std::span<const Vec3<T>> edge_directions() const { return edge_dirs_; }
  /// edge_directions()[e] == vertex(edge_head(e)) - vertex(edge_tail(e)),
  /// parallel to normal(edge_face(e, 0)) x normal(edge_face(e, 1)).
  const Vec3<T>& edge_direction(int e) const { return edge_dirs_[static_cast<std::size_t>(e)]; }
  /// plane(edge_face(e, side)).normal, side 0 (face of half-edge 2e) or 1 (2e + 1).
  const Vec3<T>& edge_normal(int e, int side) const {
    return planes_[static_cast<std::size_t>(edge_face(e, side))].normal;
  }

  // ---- lane arrays: one array per coordinate (float and double only) ----
  // The values above again, split by coordinate for SIMD scans (simd_lanes.hpp):
  //   lane_edge(k)[e], k = 0..2: edge_normal(e, 0) x, y, z;
  //                    3..5: -edge_normal(e, 1) (negated: exact, and the arc
  //                          test then wants all four products of one sign);
  //                    6..8: edge_direction(e)          (the Gauss map's arc test)
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
  /// What the support scans (simd::support_scan) need of a shape: its vertex
  /// lanes hold every vertex, each coordinate finite with |x| <= 2^60, and
  /// every plane normal a query may read has |n_i| <= 2^60.  Equal to
  /// lanes_bounded() on a complete shape; on a partial rigid image
  /// (assign_rigid_vertices) it covers the vertices and the planes derived
  /// so far (derive_rigid_part), whose edge lanes are not written yet, so
  /// that the early-out checks on it scan B's vertices in lanes too.
  bool support_lanes_bounded() const { return support_lanes_bounded_; }
  int lane_edge_stride() const { return lane_edge_stride_; }
  const T* lane_edge(int k) const { return lanes_.data() + static_cast<std::size_t>(k * lane_edge_stride_); }
  int lane_vertex_stride() const { return lane_vertex_stride_; }
  const T* lane_vertex(int c) const {
    return lanes_.data() + static_cast<std::size_t>(9 * lane_edge_stride_ + c * lane_vertex_stride_);
  }

  // ---- faces ----
  const FaceLoop& face(int f) const { return topology_.faces()[static_cast<std::size_t>(f)]; }
  const std::vector<FaceLoop>& faces() const { return topology_->faces; }
  const Plane<T>& plane(int f) const { return planes_[static_cast<std::size_t>(f)]; }
  const std::vector<Plane<T>>& planes() const { return planes_; }
  /// The face's vertex indices in loop order.
  std::vector<int> face_vertices(int f) const {
    std::vector<int> out;
    face_vertices(f, out);
    return out;
  }
  /// The face's vertex indices in loop order, into out (cleared first; its capacity is reused, so a loop
  /// over the faces allocates only while the buffer grows).
  void face_vertices(int f, std::vector<int>& out) const {
    out.clear();
    out.reserve(static_cast<std::size_t>(face(f).count));
    int h = face(f).edge;
    for (int i = 0; i < face(f).count; ++i) {
      out.push_back(half_edge(h).origin);
      h = half_edge(h).next;
    }
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
    if constexpr (std::is_floating_point_v<T>)
      return static_cast<double>(std::numeric_limits<T>::min()) * 0x1p40;
    else
      return 0.0;
  }();

  // raw arrays, for converters and serialisers
  const std::vector<int>& fan_start() const { return topology_->fan_start; }
  const std::vector<int>& fan() const { return topology_->fan; }

 private:
  template <Number U>
  friend class ConvexPolyhedron;

  template <class>
  friend struct hull::detail::HullPolyhedron;

  [[noreturn]] static void fail(ErrorCode code, const std::string& what) { throw InvalidInput(code, what); }

  // Topology (convex_polyhedron_topology.hpp): the half-edge mesh from the
  // face lists, and each face's plane triple.
  void build_topology(const std::vector<std::vector<int>>& faces);
  static T triangle_area2(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c);
  void choose_plane_triples();

  // Derived data (convex_polyhedron_derived.hpp): planes, per-edge arrays,
  // lanes, bounds and normal_conditioning() from the vertices and topology.
  void compute_derived(bool eager_conditioning = false, bool with_bounds = true);
  struct PlanesInRange {
    bool normals_bounded = false;  // every normal non-zero, every component |x| <= 2^60
    bool offsets_finite = false;
  };
  PlanesInRange compute_planes(bool eager_conditioning);
  void compute_edge_data();
  void compute_bounds();
  void finish_bounds(const Vec3<T>& sum);
  void size_lanes();
  bool write_edge_lanes();
  // The per-edge arrays of a rigid image (finish_rigid_image) from its
  // vertices and planes, and with kLanes their edge lanes (lanes_ sized);
  // returns whether every direction component has |x| <= 2^60.  With every
  // vertex coordinate within 2^59 (max_abs_) each component of a difference
  // is within 2^60 (rounding is monotone and 2^60 is a float and a double),
  // so the per-edge test runs only otherwise (kCheck).
  template <bool kLanes>
  bool derive_rigid_edges() {
    return max_abs_ <= 0x1p59 ? derive_rigid_edges<kLanes, false>() : derive_rigid_edges<kLanes, true>();
  }
  template <bool kLanes, bool kCheck>
  bool derive_rigid_edges();
  // assign_rigid_vertices' groups: vertices [0, k W) of src (W =
  // simd::Lanes<T>::width, k W the largest multiple of W up to the vertex
  // count; 0 without SIMD) mapped by point_lanes from src's vertex lanes,
  // written to the vertex lanes and vertices_, with the bounds (lo, hi:
  // the per-lane minima and maxima of the image folded in), their
  // sequential sum s (from zero, in index order) and the finiteness test
  // (every |coordinate| <= max).  Returns k W.
  template <class PointLanes>
  std::size_t rigid_vertex_groups(const ConvexPolyhedron& src, PointLanes& point_lanes, T& lo0, T& lo1,
                                  T& lo2, T& hi0, T& hi1, T& hi2, T& s0, T& s1, T& s2, bool& finite);
  double compute_normal_conditioning() const;
  struct NormalConditioningScan;
  Plane<T> plane_of_triple(int f, NormalConditioningScan* scan) const;
  // planes_[f] = plane_of_triple(f, scan)'s values, written into the
  // plane's existing numbers for exact T (assign_plane_through).
  void derive_plane(int f, NormalConditioningScan* scan);
  // edge_dirs_[e] = head - tail (assign_difference: exact T's own route).
  void derive_edge_direction(std::size_t e);
  std::size_t plane_groups(NormalConditioningScan* scan, bool& nb, bool& of);
  static void planes_in_range(const Plane<T>& pl, bool& nb, bool& of);
  void compute_lanes();
  T height(int f, const Vec3<T>& p) const;
  T height_tolerance(double rel) const;

  // Validation (convex_polyhedron_validation.hpp): every check from_faces,
  // convert_from and with_vertices make, each failing with InvalidInput.
  void check_coordinates();
  static std::string num_str(double x);
  void check_range(bool planes = true);
  // check_range(false)'s two tests, inline: true iff it passes (float/double)
  bool coordinates_in_range() const;
  double triple_aspect(int f) const;
  void check_new_range();
  void check_plane_normals() const;
  void local_convexity_witnesses(int f, std::vector<int>& out) const;
  bool vertex_windings_once() const;
  void validate_geometry(double scan_pairs = kConvexityScanPairs);

  std::vector<Vec3<T>> vertices_;
  detail::SharedTopology topology_;  // half-edges, face loops, fans: shared by copies and images
  std::vector<Plane<T>> planes_;
  std::vector<Vec3<T>> edge_dirs_;  // per edge: head - tail
  std::vector<T> lanes_;            // lane arrays (float/double): 9 edge, then 3 vertex arrays
  int lane_edge_stride_ = 0, lane_vertex_stride_ = 0;
  bool lanes_bounded_ = false;
  bool support_lanes_bounded_ = false;
  Vec3<T> centroid_ = Vec3<T>(T(0), T(0), T(0));
  Vec3<T> bmin_ = Vec3<T>(T(0), T(0), T(0));
  Vec3<T> bmax_ = Vec3<T>(T(0), T(0), T(0));
  double extent_ = 0;
  double max_abs_ = 0;
  detail::LazyDouble normal_conditioning_;  // NaN until normal_conditioning() computes it
};

}  // namespace sepax

#include "convex_polyhedron_derived.hpp"
#include "convex_polyhedron_rigid.hpp"
#include "convex_polyhedron_topology.hpp"
#include "convex_polyhedron_validation.hpp"
