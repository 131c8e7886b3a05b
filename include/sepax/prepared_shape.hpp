// sepax/prepared_shape.hpp
//
// PreparedShape<T>: a convex hull in its own local frame together with
// everything the SATs precompute for it (contents and posing: on the class),
// built once, immutable, queried at any pose from any number of threads.
// This header also brings the queries on prepared shapes (posed_queries.hpp):
//
//   const PreparedShape<float> a(hull_a), b(hull_b);      // once per hull
//   SatCache<float> cache;                                 // once per pair
//   SatOptions opt;  opt.early_out = true;  opt.margin = 0.02;
//   // every step, every pair (poses: world = R local + t):
//   const auto r = sat::traversal<policy::Robust>(a, pose_a, b, pose_b, opt, &cache);
//   if (!r.early_out) {
//     const auto m = contact_manifold(a, pose_a, b, pose_b, r, opt);  // world coordinates
//   }
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "gauss_map_walk.hpp"
#include "posing.hpp"
#include "simd_lanes.hpp"
#include "transform.hpp"

namespace sepax {

namespace detail {

/// The per-thread scratch a posed query moves B into (see the header).
template <Number T>
struct PoseScratch {
  // kNoEdgeLanes: all of B' but its edge lane arrays (finish_rigid_image(false))
  enum Stage { kNone, kVertices, kNoEdgeLanes, kFull };
  ConvexPolyhedron<T> poly;
  std::uint64_t serial = 0;  // PreparedShape::serial() of the shape poly holds (0: none)
  Stage stage = kNone;       // poly is that shape at pose x: its vertices (a partial image), or all of it
  RigidTransform<T> x;
  // float/double, with from_poses: x = relative_pose(pose_a, pose_b)
  // (PreparedShape::posed_scratch_from / posed_scratch_between)
  bool from_poses = false;
  RigidTransform<T> pose_a, pose_b;
};

template <Number T>
PoseScratch<T>& pose_scratch() {
  thread_local PoseScratch<T> s;
  return s;
}

template <Number T>
bool same_pose(const RigidTransform<T>& p, const RigidTransform<T>& q) {
  if constexpr (std::is_floating_point_v<T>) {
    // bit-identical (the posed vertices are then bit-identical too): the
    // rotation's nine and the translation's three values, compared as bytes
    // (the object is those twelve values and nothing else: no padding)
    static_assert(sizeof(typename RigidTransform<T>::Matrix3) == 9 * sizeof(T) &&
                  sizeof(Vec3<T>) == 3 * sizeof(T) && sizeof(RigidTransform<T>) == 12 * sizeof(T));
    return simd::equal_bytes<sizeof(RigidTransform<T>)>(&p, &q);
  } else {
    return p.rotation == q.rotation && p.translation == q.translation;
  }
}

inline std::uint64_t next_shape_serial() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

}  // namespace detail

/// Contents: the validated ConvexPolyhedron (planes, per-edge arrays, SIMD
/// lanes, bounds), its GaussMapWalk (the traversal's walk data and probe
/// vertices).  Immutable after construction, so one
/// PreparedShape may be queried from any number of threads at once.
///
/// Posing (posing.hpp defines the input exactly): a posed query moves B into
/// A's frame, B' = posed(B, inverse(pose_a) * pose_b), into per-thread scratch
/// that keeps its arrays between queries (no heap allocation once a thread
/// has posed a shape at least as large; B' shares B's topology, so posing
/// another shape copies no half-edges), and reuses B' as long as the same shape
/// is asked at bit-identical relative pose (a manifold right after its SAT
/// query poses nothing).
template <Number T>
class PreparedShape {
 public:
  /// Prepare a hull given in its local frame (any validated polyhedron:
  /// ConvexPolyhedron::from_faces, convex_hull, shapes.hpp).  Throws
  /// InvalidInput (TooFewPoints) for an empty polyhedron.
  explicit PreparedShape(ConvexPolyhedron<T> local)
      : poly_(std::move(local)), walk_(poly_), serial_(detail::next_shape_serial()) {
    if (poly_.empty()) throw InvalidInput(ErrorCode::TooFewPoints, "PreparedShape: the polyhedron is empty");
    prepare_faces();
  }

  // Copies share the serial (same content: the scratch may keep a posed image);
  // a moved-from shape gets a fresh one and is empty (queries refuse it).
  PreparedShape(const PreparedShape&) = default;
  PreparedShape& operator=(const PreparedShape&) = default;
  PreparedShape(PreparedShape&& o) noexcept
      : poly_(std::move(o.poly_)),
        walk_(std::move(o.walk_)),
        face_lanes_(std::move(o.face_lanes_)),
        face_stride_(o.face_stride_),
        inner_radius_(o.inner_radius_),
        serial_(o.serial_) {
    o.poly_ = ConvexPolyhedron<T>();
    o.serial_ = detail::next_shape_serial();
  }
  PreparedShape& operator=(PreparedShape&& o) noexcept {
    if (this != &o) {
      poly_ = std::move(o.poly_);
      walk_ = std::move(o.walk_);
      face_lanes_ = std::move(o.face_lanes_);
      face_stride_ = o.face_stride_;
      inner_radius_ = o.inner_radius_;
      serial_ = o.serial_;
      o.poly_ = ConvexPolyhedron<T>();
      o.serial_ = detail::next_shape_serial();
    }
    return *this;
  }

  /// The hull in its local frame.
  const ConvexPolyhedron<T>& polyhedron() const { return poly_; }
  /// Its traversal walk data (gauss_map_walk.hpp).
  const GaussMapWalk& walk() const { return walk_; }
  /// Identifies the content (equal for copies).
  std::uint64_t serial() const { return serial_; }

  /// Radius of a ball around the centroid inside the shape (in its local
  /// frame): min over the faces of the centroid's distance to the face's
  /// plane, in double (0 for a flat shape and for exact T).  An estimate for
  /// the posed queries' margin pre-check, which only uses it to skip work.
  double inner_radius() const { return inner_radius_; }

  /// The face whose (local) normal has the largest dot product with dir,
  /// the lowest index among equal ones (float/double: over a copy of the
  /// normals by coordinate, a few faces at a time, simd_lanes.hpp; exact T:
  /// a scan).  For the posed queries' margin pre-check: a choice, not a
  /// decision.
  int most_aligned_face(const Vec3<T>& dir) const {
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
      using L = simd::Lanes<T>;
      using V = typename L::V;
      constexpr int W = L::width;
      const T* x = face_lanes_.data();
      const T* y = x + face_stride_;
      const T* z = y + face_stride_;
      const V dx = L::set1(dir[0]), dy = L::set1(dir[1]), dz = L::set1(dir[2]);
      V best = L::set1(-std::numeric_limits<T>::infinity());
      V idx = L::set1(T(0));
      V cur = L::iota(T(0));
      const V step = L::set1(T(W));
      for (int i = 0; i < face_stride_; i += W) {
        const V h = simd::dot3<L>(L::load(x + i), L::load(y + i), L::load(z + i), dx, dy, dz);
        idx = L::select(L::gt(h, best), cur, idx);  // strictly larger: the lane keeps its first maximum
        best = L::max_gt(h, best);
        cur = L::add(cur, step);
      }
      // the largest value over the lanes, then the lowest index holding it
      // (padding repeats face 0: never below a real index with that value)
      const V minus = L::set1(T(-1));
      const V top = L::mul(L::hmin(L::mul(best, minus)), minus);
      const V cand = L::select(L::eq(best, top), idx, L::set1(std::numeric_limits<T>::infinity()));
      const T first = L::first(L::hmin(cand));
      const int f = first < T(poly_.face_count()) ? static_cast<int>(first) : 0;  // NaN direction: 0
      return f;
    } else {
      int best = 0;
      T best_d = dot(poly_.plane(0).normal, dir);
      for (int f = 1; f < poly_.face_count(); ++f) {
        const T d = dot(poly_.plane(f).normal, dir);
        if (d > best_d) {
          best = f;
          best_d = d;
        }
      }
      return best;
    }
  }

  /// This shape moved by x (posing.hpp's posed(polyhedron(), x), bit for
  /// bit) in this thread's scratch; valid until the thread's next posed
  /// query or posed_scratch call.  edge_lanes = false: everything but the
  /// edge lane arrays, which only sat::gauss_map's batched arc test reads
  /// (ConvexPolyhedron::finish_rigid_image); the posed traversal, brute
  /// force and manifold ask for that.  No allocation once the thread's
  /// scratch has held a shape at least this large.  Throws InvalidInput for
  /// an empty (moved-from) shape or a non-rigid x (posing.hpp).
  const ConvexPolyhedron<T>& posed_scratch(const RigidTransform<T>& x, bool edge_lanes = true) const {
    auto& s = detail::pose_scratch<T>();
    if (!(s.serial == serial_ && s.stage != S::kNone && detail::same_pose(s.x, x))) pose_vertices(s, x);
    return finished(s, edge_lanes);
  }

  /// posed_scratch(x, edge_lanes) for x = relative_pose(pose_a, pose_b)
  /// (the posed queries), noting the poses with x (float/double) so that
  /// posed_scratch_between(pose_a, pose_b) at the same poses finds this
  /// image without computing x again.
  const ConvexPolyhedron<T>& posed_scratch_from(const RigidTransform<T>& x, const RigidTransform<T>& pose_a,
                                                const RigidTransform<T>& pose_b, bool edge_lanes) const {
    const ConvexPolyhedron<T>& bp = posed_scratch(x, edge_lanes);
    if constexpr (std::is_floating_point_v<T>) {
      auto& s = detail::pose_scratch<T>();
      s.pose_a = pose_a;
      s.pose_b = pose_b;
      s.from_poses = true;
    }
    return bp;
  }

  /// posed_scratch(relative_pose(pose_a, pose_b), edge_lanes): the same
  /// image, bit for bit.  When this thread's scratch holds this shape posed
  /// at x = relative_pose of bit-identical poses (posed_scratch_from: a
  /// posed contact_manifold right after its query), x is that one
  /// (relative_pose is a function of the poses' bits) and is not computed
  /// again.
  const ConvexPolyhedron<T>& posed_scratch_between(const RigidTransform<T>& pose_a,
                                                   const RigidTransform<T>& pose_b, bool edge_lanes) const {
    if constexpr (std::is_floating_point_v<T>) {
      auto& s = detail::pose_scratch<T>();
      if (s.from_poses && s.serial == serial_ && s.stage != S::kNone && detail::same_pose(s.pose_a, pose_a) &&
          detail::same_pose(s.pose_b, pose_b))
        return finished(s, edge_lanes);
    }
    return posed_scratch(relative_pose(pose_a, pose_b), edge_lanes);
  }

  /// For the posed queries' early-out checks (posed_queries.hpp): this
  /// shape's vertices moved by x in this thread's scratch, with only the
  /// planes of `faces` and the per-edge entries of `edges` derived (a partial
  /// image: ConvexPolyhedron::derive_rigid_part; posing.hpp, "Staged
  /// posing"), or the full posed_scratch(x) if the scratch already holds it.
  /// Valid until the thread's next posed query or scratch call, and only for
  /// kernel queries that read those planes and edges; a later
  /// posed_scratch(x) at the same x derives the rest.  Throws as
  /// posed_scratch.
  const ConvexPolyhedron<T>& posed_part_scratch(const RigidTransform<T>& x, std::span<const int> faces,
                                                std::span<const int> edges) const {
    auto& s = detail::pose_scratch<T>();
    if (s.serial == serial_ && s.stage != S::kNone && detail::same_pose(s.x, x)) {
      if (s.stage == S::kFull || s.stage == S::kNoEdgeLanes)
        return s.poly;  // every plane is there (derive_rigid_part would narrow its bound)
    } else {
      pose_vertices(s, x);
    }
    if (!faces.empty() || !edges.empty()) s.poly.derive_rigid_part(faces, edges);
    return s.poly;
  }

 private:
  using S = detail::PoseScratch<T>;

  // s holds this shape at its x (some stage): the rest derived as edge_lanes
  // asks (posed_scratch).
  const ConvexPolyhedron<T>& finished(S& s, bool edge_lanes) const {
    // the vertices are there (a check of a posed query's, or this call): finish them
    if (s.stage == S::kVertices) {
      s.stage = S::kNone;
      s.poly.finish_rigid_image(edge_lanes);
      s.stage = edge_lanes ? S::kFull : S::kNoEdgeLanes;
    } else if (s.stage == S::kNoEdgeLanes && edge_lanes) {
      s.poly.finish_rigid_edge_lanes();
      s.stage = S::kFull;
    }
    return s.poly;
  }

  // s.poly = the partial image of this shape at x (stage kVertices).
  void pose_vertices(S& s, const RigidTransform<T>& x) const {
    if (poly_.empty())
      throw InvalidInput(ErrorCode::TooFewPoints, "PreparedShape: the shape is empty (moved from)");
    s.stage = S::kNone;
    s.serial = 0;  // until the posing below has finished (it may throw)
    s.from_poses = false;
    detail::pose_vertices_into(s.poly, poly_, x);
    s.serial = serial_;
    s.x = x;
    s.stage = S::kVertices;
  }

  // face_lanes_: the face normals by coordinate (x, y, z arrays of
  // face_stride_ entries, padded with face 0's normal); inner_radius_.
  void prepare_faces() {
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
      const int nf = poly_.face_count();
      constexpr int kPad = ConvexPolyhedron<T>::kLanePad;
      face_stride_ = (nf + kPad - 1) / kPad * kPad;
      face_lanes_.assign(3 * static_cast<std::size_t>(face_stride_), T(0));
      for (int f = 0; f < face_stride_; ++f) {
        const Vec3<T>& n = poly_.plane(f < nf ? f : 0).normal;
        for (int c = 0; c < 3; ++c) face_lanes_[static_cast<std::size_t>(c * face_stride_ + f)] = n[c];
      }
      double r = std::numeric_limits<double>::infinity();
      const Vec3<T>& c = poly_.centroid();
      for (int f = 0; f < nf; ++f) {
        const Plane<T>& pl = poly_.plane(f);
        const double h =
            static_cast<double>(pl.offset) - (static_cast<double>(pl.normal[0]) * static_cast<double>(c[0]) +
                                              static_cast<double>(pl.normal[1]) * static_cast<double>(c[1]) +
                                              static_cast<double>(pl.normal[2]) * static_cast<double>(c[2]));
        r = h < r ? h : r;
      }
      inner_radius_ = poly_.is_flat() || !(r > 0) ? 0.0 : r;
    }
  }

  ConvexPolyhedron<T> poly_;
  GaussMapWalk walk_;
  std::vector<T> face_lanes_;
  int face_stride_ = 0;
  double inner_radius_ = 0;
  std::uint64_t serial_ = 0;
};

}  // namespace sepax

#include "posed_queries.hpp"
