// The manifold of a kept face re-derived at a new pose, without building a
// ContactManifold through contact_manifold (docs/bullet.md, "Coherence"):
//   1. the incident face: most_antiparallel_face around the contact's support
//      vertex, as face_contact chooses it;
//   2. the incident polygon clipped by the reference face's side planes with
//      face_contact's own steps (incident_polygon, side_plane,
//      clip_polygon, clip_polygon_if_cut, weld_polygon) in fixed buffers
//      (FixedPoly; SmallVector beyond 32 vertices);
//      the side planes of a reference face of A are the same at every pose
//      and computed once (KeptFace); a plane that keeps the whole polygon is
//      skipped on its heights alone (clip_if_cut);
//   3. the points within the margin (face_point, face_contact's step 3);
//   4. more than four of them reduced to four by face_contact's reduction
//      (reduce_contact_points_into, manifold_reduction.hpp) on the same
//      positions, depth keys and tolerances;
//   5. of each kept point, the one the adapter's writer reads (point_a or
//      point_b: the point on the Bullet manifold's body 1) mapped to world by
//      pose_a as posed_manifold_on maps it; position and the other point
//      stay in A's frame (the writer reads neither).
// When that leaves no point (face_contact's support-vertex fallback) or the
// contact's own separation is beyond the margin (contact_manifold returns no
// point), the refresh declines and the adapter builds the manifold with
// posed_manifold_on.  Otherwise the points read are those posed_manifold_on gives,
// bit for bit: the same functions on the same inputs.
#pragma once

#include <cstddef>
#include <new>
#include <type_traits>

#include <sepax/clip_polygon.hpp>
#include <sepax/face_contact.hpp>
#include <sepax/manifold_reduction.hpp>
#include <sepax/manifold_result.hpp>
#include <sepax/sat_result.hpp>
#include <sepax/small_vector.hpp>
#include <sepax/tolerances.hpp>
#include <sepax/transform.hpp>

namespace sepax::bullet {

/// The side planes of a kept reference face of A (A's frame), in the loop
/// order face_contact clips with; empty for a reference face of B, whose side
/// planes move with B'.
struct KeptFace {
  int face = -1;
  SmallVector<ClipPlane<float>, 16> planes;

  void set(const ConvexPolyhedron<float>& a, int f) {
    face = f;
    planes.clear();
    const Vec3<float>& nr = a.plane(f).normal;
    int h = a.face(f).edge;
    for (int i = 0; i < a.face(f).count; ++i, h = a.half_edge(h).next)
      planes.push_back(sepax::detail::side_plane(a, h, nr));
  }
};

/// A clip polygon in a fixed array of kCapacity vertices: the
/// subset of SmallVector (small_vector.hpp) that incident_polygon,
/// clip_polygon, clip_detail::clip_with and weld_polygon use, with a
/// push_back that never leaves the caller: SmallVector's grows through an
/// out-of-line call, across which the clip loop reloads both polygons'
/// storage and sizes and the heights at every vertex (about 3% more
/// instructions in the resting stack's narrowphase, docs/bullet.md).
/// The same functions on the same vertices: the same polygon.  A vertex
/// pushed beyond the capacity is dropped and `overflowed` set: the caller
/// then discards the result and clips again in SmallVector buffers (a clip
/// of a convex polygon adds at most one vertex per plane, but float
/// heights of nearly coincident vertices can alternate in sign, and a
/// hull's face can have any number of vertices).
template <class T>
class FixedPoly {
  static_assert(std::is_trivially_destructible_v<T>);

 public:
  /// Vertices held inline (a box's face clipped by a box's side planes
  /// leaves at most 8; a ramp's 24-sided face 24), count.
  static constexpr std::size_t kCapacity = 32;
  using value_type = T;

  FixedPoly() = default;
  FixedPoly(const FixedPoly&) = delete;
  FixedPoly& operator=(const FixedPoly&) = delete;

  /// Vertices held, count.
  std::size_t size() const { return size_; }
  /// True when no vertex is held.
  bool empty() const { return size_ == 0; }
  /// Vertex i (i < size()).
  T& operator[](std::size_t i) { return data()[i]; }
  /// Vertex i (i < size()).
  const T& operator[](std::size_t i) const { return data()[i]; }
  /// The last vertex (size() > 0).
  T& back() { return data()[size_ - 1]; }
  /// The last vertex (size() > 0).
  const T& back() const { return data()[size_ - 1]; }
  /// The first vertex.
  T* begin() { return data(); }
  /// Past the last vertex.
  T* end() { return data() + size_; }
  /// The first vertex.
  const T* begin() const { return data(); }
  /// Past the last vertex.
  const T* end() const { return data() + size_; }
  /// Holds no vertex (the overflow flag stays).
  void clear() { size_ = 0; }
  /// Keeps the first n vertices (n <= size(): weld_polygon only shrinks).
  void resize(std::size_t n) { size_ = n; }
  /// Appends v; beyond the capacity drops it and sets overflowed.
  void push_back(const T& v) {
    if (size_ == kCapacity) {
      overflowed = true;
      return;
    }
    ::new (static_cast<void*>(raw_ + size_ * sizeof(T))) T(v);
    ++size_;
  }
  /// A vertex was dropped: the polygon is not the clip's.
  bool overflowed = false;

 private:
  T* data() { return std::launder(reinterpret_cast<T*>(raw_)); }
  const T* data() const { return std::launder(reinterpret_cast<const T*>(raw_)); }

  /// Raw storage: only the vertices pushed are constructed (a default
  /// ClipVertex writes its labels).
  alignas(T) unsigned char raw_[kCapacity * sizeof(T)];
  std::size_t size_ = 0;
};

/// clip_polygon_if_cut (clip_polygon.hpp) on a polygon of at most 32
/// vertices with its heights in a fixed buffer: each vertex's height over
/// `plane` (clip_detail::height_over) computed once; when none is above the
/// plane (a large reference face, a ramp under a box, has many side planes
/// that keep the whole polygon) false and `out` untouched, else `in`
/// clipped by clip_detail::clip_with on those heights into `out`: the same
/// heights, decision and clip.
template <class Poly>
bool clip_if_cut(const Poly& in, const ClipPlane<float>& plane, int incident_face, Poly& out) {
  float heights[32];
  bool cut = false;
  std::size_t n = 0;
  for (const auto& v : in) {
    heights[n] = clip_detail::height_over(plane, v.point);
    cut |= heights[n] > 0.0f;
    ++n;
  }
  if (!cut) return false;
  clip_detail::clip_with(in, plane, incident_face, out, [&](std::size_t i) { return heights[i]; });
  return true;
}

namespace refresh_detail {

using sepax::detail::extent_tolerance;  // face_contact.hpp's steps, on B' or its view
using sepax::detail::incident_polygon;
using sepax::detail::most_antiparallel_face;
using sepax::detail::side_plane;

}  // namespace refresh_detail

/// face_contact's step 4 where the clip `poly` has more than four points
/// within the margin: all of them (face_point, in clip order) reduced to
/// four by face_contact's reduction (reduce_contact_points_into) on the same
/// positions, depth keys and tolerances; pts[0..5) holds the first five
/// (refresh_on's), the vertices from `next` on (after the fifth's) give the
/// rest; the kept points go to pts[0..count).  Returns the number of points
/// within the margin (candidate_points).
template <class BP, class Poly>
int reduce_points(const ConvexPolyhedron<float>& a, const BP& bp, const Poly& poly, std::size_t next,
                  const Plane<float>& rp, bool ref_is_a, float margin, ContactPoint<float> (&pts)[5],
                  std::size_t& count) {
  const float n2 = sepax::detail::norm2_of(rp.normal);
  SmallVector<ContactPoint<float>, 16> all;
  SmallVector<Vec3<float>, 16> pos;
  SmallVector<float, 16> keys;
  const int unit = sepax::detail::manifold_scale_exponent(a, bp);  // (face_contact's units)
  auto add = [&](const ContactPoint<float>& c) {
    all.push_back(c);
    pos.push_back(sepax::detail::in_manifold_units(c.position, unit));
    keys.push_back(sepax::detail::in_manifold_units(c.separation.num, unit));
  };
  for (const ContactPoint<float>& c : pts) add(c);
  ContactPoint<float> c;
  for (std::size_t i = next; i < poly.size(); ++i) {
    if (sepax::detail::face_point(poly[i], rp, n2, ref_is_a, margin, c)) add(c);
  }
  const float area_tol = refresh_detail::extent_tolerance(a, bp, Tolerances<float>::kContactArea, 3, unit);
  const float key_tol = refresh_detail::extent_tolerance(a, bp, Tolerances<float>::kContactWeld, 1, unit);
  SmallVector<int, 4> keep;
  reduce_contact_points_into(pos, keys, rp.normal, key_tol, area_tol, keep);
  count = 0;
  for (const int i : keep) pts[count++] = all[static_cast<std::size_t>(i)];
  return static_cast<int>(all.size());
}

namespace refresh_detail {

/// What refresh_on did: declined (face_contact would do more than the
/// refresh), built the manifold, or dropped a vertex of its fixed buffers
/// (FixedPoly::overflowed: nothing written, to be clipped again in
/// SmallVector buffers).
enum class Refresh { Declined, Done, Overflowed };

/// refresh_face_manifold's body with the reference shape R and the incident
/// shape I (a and bp, in the order r's feature says), clipping in buf0 and
/// buf1 (empty; FixedPoly or SmallVector: the same functions, the same
/// polygon where no FixedPoly overflowed).
template <class BP, class RS, class IS, class Poly>
Refresh refresh_on(const ConvexPolyhedron<float>& a, const RigidTransform<float>& pose_a, const BP& bp,
                   const RS& R, const IS& I, const SatResult<float>& r, float m, const KeptFace& kept,
                   bool world_a, Poly& buf0, Poly& buf1, ContactManifold<float>& out) {
  const bool ref_is_a = r.feature.type == FeatureType::FaceA;
  const int ref_face = ref_is_a ? r.feature.a : r.feature.b;
  const int support = ref_is_a ? r.feature.b : r.feature.a;
  const Plane<float>& rp = R.plane(ref_face);
  const Vec3<float>& nr = rp.normal;
  int visited = 0;
  const int inc = most_antiparallel_face(I, nr, support, visited);

  Poly* pp = &buf0;
  Poly* tp = &buf1;
  incident_polygon(I, inc, ref_face, *pp);
  const int unit = sepax::detail::manifold_scale_exponent(a, bp);  // (face_contact's units)
  const float weld2 = extent_tolerance(a, bp, Tolerances<float>::kContactWeld, 2, unit);
  const bool cached = ref_is_a && kept.face == ref_face;
  bool welded = false;
  int h = R.face(ref_face).edge;
  for (int i = 0; i < R.face(ref_face).count && !pp->empty(); ++i, h = R.half_edge(h).next) {
    const ClipPlane<float> cp = cached ? kept.planes[static_cast<std::size_t>(i)] : side_plane(R, h, nr);
    if (welded &&
        (pp->size() > 32 ? !clip_polygon_if_cut(*pp, cp, inc, *tp) : !clip_if_cut(*pp, cp, inc, *tp)))
      continue;
    if (!welded) clip_polygon(*pp, cp, inc, *tp);
    weld_polygon(*tp, weld2, unit);
    welded = true;
    std::swap(pp, tp);
  }
  if constexpr (requires { buf0.overflowed; }) {
    if (buf0.overflowed || buf1.overflowed) return Refresh::Overflowed;
  }
  // face_contact's step 3, in A's frame
  const float n2 = sepax::detail::norm2_of(nr);
  // face_point writes its point only where it returns true: each point is
  // built in place; a fifth in pts[4] says there are more, and the
  // reduction starts from the five
  ContactPoint<float> pts[5];
  std::size_t count = 0;
  std::size_t next = 0;  // after the fifth point's vertex, where there is one
  const auto* const first = pp->begin();
  for (const auto* v = first; v != pp->end(); ++v) {
    if (!sepax::detail::face_point(*v, rp, n2, ref_is_a, m, pts[count])) continue;
    if (count == 4) {
      next = static_cast<std::size_t>(v - first) + 1;
      break;
    }
    ++count;
  }
  if (count == 0) return Refresh::Declined;  // face_contact's support-vertex fallback: its full path
  const int candidates =
      next > 0 ? reduce_points(a, bp, *pp, next, rp, ref_is_a, m, pts, count) : static_cast<int>(count);
  out.kind = ContactKind::Face;
  out.feature = r.feature;
  out.normal = r.axis;
  out.norm2 = r.separation.norm2;
  out.separation = r.separation;
  out.reference_shape = ref_is_a ? 0 : 1;
  out.reference_face = ref_face;
  out.incident_face = inc;
  out.incident_faces_visited = visited;
  out.candidate_points = candidates;
  out.support_fallback = false;
  out.clip_steps.clear();
  out.points.clear();
  // posed_manifold_on's map to world, of the one point the writer reads
  for (std::size_t i = 0; i < count; ++i) {
    ContactPoint<float>& c = pts[i];
    if (world_a) {
      c.point_a = pose_a.apply(c.point_a);
    } else {
      c.point_b = pose_a.apply(c.point_b);
    }
    out.points.push_back(c);
  }
  return Refresh::Done;
}

/// refresh_on in FixedPoly buffers, again in SmallVector buffers where a
/// FixedPoly overflowed; true when the manifold was built.
template <class BP, class RS, class IS>
bool refresh_with(const ConvexPolyhedron<float>& a, const RigidTransform<float>& pose_a, const BP& bp,
                  const RS& R, const IS& I, const SatResult<float>& r, float m, const KeptFace& kept,
                  bool world_a, ContactManifold<float>& out) {
  {
    FixedPoly<ClipVertex<float>> buf0, buf1;
    const Refresh done = refresh_on(a, pose_a, bp, R, I, r, m, kept, world_a, buf0, buf1, out);
    if (done != Refresh::Overflowed) return done == Refresh::Done;
  }
  SmallVector<ClipVertex<float>, 16> buf0, buf1;
  return refresh_on(a, pose_a, bp, R, I, r, m, kept, world_a, buf0, buf1, out) == Refresh::Done;
}

}  // namespace refresh_detail

/// The refresh of the header on (a, bp) for the kept face contact r (FaceA
/// or FaceB, support vertex in r.feature, axis in world); `kept`: the side
/// planes of r's face of A when r is FaceA and kept.face is that face.  BP:
/// B' as a ConvexPolyhedron<float> or a PosedView (posed_view.hpp) holding
/// the planes the refresh reads (r's face of B, or B's faces around the
/// support vertex).  `world_a`: map point_a to world, else point_b (step 5
/// of the header).  Returns false (out untouched) where the header says it
/// declines.
template <class BP>
bool refresh_face_manifold(const ConvexPolyhedron<float>& a, const RigidTransform<float>& pose_a,
                           const BP& bp, const SatResult<float>& r, double margin, const KeptFace& kept,
                           bool world_a, ContactManifold<float>& out) {
  const float m = from_double<float>(margin);
  if (!sepax::detail::within_margin(r.separation, m)) return false;
  if (r.feature.type == FeatureType::FaceA)
    return refresh_detail::refresh_with(a, pose_a, bp, a, bp, r, m, kept, world_a, out);
  return refresh_detail::refresh_with(a, pose_a, bp, bp, a, r, m, kept, world_a, out);
}

}  // namespace sepax::bullet
