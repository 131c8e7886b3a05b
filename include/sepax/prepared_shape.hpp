// sepax/prepared_shape.hpp
//
// PreparedShape<T>: a convex hull in its own local frame together with
// everything the SATs precompute for it, built once and then queried at any
// pose.  This header also brings the queries on prepared shapes
// (posed_queries.hpp):
//
//   const PreparedShape<float> a(hull_a), b(hull_b);      // once per hull
//   SatCache<float> cache;                                 // once per pair
//   SatOptions opt;  opt.early_out = true;  opt.margin = 0.02;
//   // every step, every pair (poses: world = R local + t):
//   const auto r = sat::traversal<policy::Robust>(a, pose_a, b, pose_b, opt, &cache);
//   if (!r.early_out) {
//     const auto m = contact_manifold(a, pose_a, b, pose_b, r, opt);  // world coordinates
//   }
//
// Contents: the validated ConvexPolyhedron (planes, per-edge arrays, SIMD
// lanes, bounds), its GaussMapWalk (the traversal's walk data and probe
// vertices).  Immutable after construction, so one
// PreparedShape may be queried from any number of threads at once.
//
// Posing (posing.hpp defines the input exactly): a posed query moves B into
// A's frame, B' = posed(B, inverse(pose_a) * pose_b), into per-thread scratch
// that keeps its arrays between queries (no heap allocation once a thread
// has posed a shape at least as large; the topology is copied only when the
// scratch last held another shape), and reuses B' as long as the same shape
// is asked at bit-identical relative pose (a manifold right after its SAT
// query poses nothing).
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <utility>

#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "gauss_map_walk.hpp"
#include "posing.hpp"
#include "transform.hpp"

namespace sepax {

namespace detail {

/// The per-thread scratch a posed query moves B into (see the header).
template <Number T>
struct PoseScratch {
  enum Stage { kNone, kVertices, kFull };
  ConvexPolyhedron<T> poly;
  std::uint64_t serial = 0;  // PreparedShape::serial() of the shape poly holds (0: none)
  Stage stage = kNone;       // poly is that shape at pose x: its vertices (a partial image), or all of it
  RigidTransform<T> x;
};

template <Number T>
PoseScratch<T>& pose_scratch() {
  thread_local PoseScratch<T> s;
  return s;
}

template <Number T>
bool same_pose(const RigidTransform<T>& p, const RigidTransform<T>& q) {
  if constexpr (std::is_floating_point_v<T>) {
    // bit-identical (the posed vertices are then bit-identical too)
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        if (std::memcmp(&p.rotation(i, j), &q.rotation(i, j), sizeof(T)) != 0) return false;
      }
      if (std::memcmp(&p.translation[i], &q.translation[i], sizeof(T)) != 0) return false;
    }
    return true;
  } else {
    return p.rotation == q.rotation && p.translation == q.translation;
  }
}

inline std::uint64_t next_shape_serial() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

}  // namespace detail

template <Number T>
class PreparedShape {
 public:
  /// Prepare a hull given in its local frame (any validated polyhedron:
  /// ConvexPolyhedron::from_faces, convex_hull, shapes.hpp).  Throws
  /// InvalidInput (TooFewPoints) for an empty polyhedron.
  explicit PreparedShape(ConvexPolyhedron<T> local)
      : poly_(std::move(local)), walk_(poly_), serial_(detail::next_shape_serial()) {
    if (poly_.empty()) throw InvalidInput(ErrorCode::TooFewPoints, "PreparedShape: the polyhedron is empty");
  }

  // Copies share the serial (same content: the scratch may keep the topology);
  // a moved-from shape gets a fresh one and is empty (queries refuse it).
  PreparedShape(const PreparedShape&) = default;
  PreparedShape& operator=(const PreparedShape&) = default;
  PreparedShape(PreparedShape&& o) noexcept
      : poly_(std::move(o.poly_)),
        walk_(std::move(o.walk_)),
        serial_(o.serial_) {
    o.poly_ = ConvexPolyhedron<T>();
    o.serial_ = detail::next_shape_serial();
  }
  PreparedShape& operator=(PreparedShape&& o) noexcept {
    if (this != &o) {
      poly_ = std::move(o.poly_);
      walk_ = std::move(o.walk_);
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

  /// This shape moved by x (posing.hpp's posed(polyhedron(), x), bit for
  /// bit) in this thread's scratch; valid until the thread's next posed
  /// query or posed_scratch call.  No allocation once the thread's scratch
  /// has held a shape at least this large.  Throws InvalidInput for an
  /// empty (moved-from) shape or a non-rigid x (posing.hpp).
  const ConvexPolyhedron<T>& posed_scratch(const RigidTransform<T>& x) const {
    auto& s = detail::pose_scratch<T>();
    if (s.serial == serial_ && s.stage != S::kNone && detail::same_pose(s.x, x)) {
      if (s.stage == S::kFull) return s.poly;
      // the vertices are there (a check of a posed query's): finish them
      s.stage = S::kNone;
      s.poly.finish_rigid_image();
      s.stage = S::kFull;
      return s.poly;
    }
    pose_vertices(s, x);
    s.poly.finish_rigid_image();
    s.stage = S::kFull;
    return s.poly;
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
      if (s.stage == S::kFull) return s.poly;  // every plane is there (derive_rigid_part would narrow its bound)
    } else {
      pose_vertices(s, x);
    }
    if (!faces.empty() || !edges.empty()) s.poly.derive_rigid_part(faces, edges);
    return s.poly;
  }

 private:
  using S = detail::PoseScratch<T>;

  // s.poly = the partial image of this shape at x (stage kVertices).
  void pose_vertices(S& s, const RigidTransform<T>& x) const {
    if (poly_.empty()) throw InvalidInput(ErrorCode::TooFewPoints, "PreparedShape: the shape is empty (moved from)");
    const bool same_topology = s.serial == serial_;
    s.stage = S::kNone;
    s.serial = 0;  // until the posing below has finished (it may throw)
    detail::pose_vertices_into(s.poly, poly_, same_topology, x);
    s.serial = serial_;
    s.x = x;
    s.stage = S::kVertices;
  }

  ConvexPolyhedron<T> poly_;
  GaussMapWalk walk_;
  std::uint64_t serial_ = 0;
};

}  // namespace sepax

#include "posed_queries.hpp"
