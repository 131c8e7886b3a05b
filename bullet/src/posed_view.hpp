// The part of B' (B posed in A's frame) a kept face reads, computed without
// posing the whole shape through PreparedShape::posed_part_scratch (docs/
// bullet.md, "Coherence"): B's vertices at x, the extent of their bounds,
// and only the planes the kept face and its manifold read.  Each value is
// the one the posed image holds, by the same operations:
//   * a vertex: pose_vertices_into's SIMD lane expression for the vertices
//     it poses in groups, x.apply(v) (transform.hpp) for the rest, as
//     posing does (posing.hpp; the lanes evaluate apply()'s operations in
//     its order);
//   * the extent: sqrt of the sum over x, y, z of (max - min)^2 in double,
//     finish_bounds' formula; the minimum and maximum of a coordinate are
//     the same values in any order of comparison (a zero's sign, which the
//     order can change, does not change max - min squared);
//   * a plane: plane_of_triple's own steps (detail::triple_cross and
//     detail::unit_plane, convex_polyhedron_derived.hpp) on the face's
//     plane triple, where its cross product is in range; otherwise the
//     view declines.
// The view declines (returns false) wherever posing would do more than that
// - a pose check or range check that could throw, a plane that needs
// plane_of_triple's rescaling - and the adapter then poses B' as before,
// which throws or computes as it always did.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/posing.hpp>
#include <sepax/simd_ops.hpp>
#include <sepax/transform.hpp>

namespace sepax::bullet {

/// B' in part, with the accessors of ConvexPolyhedron<float> the kept face's
/// functions read (face_refresh.hpp, contact_choice.hpp); topology from B.
class PosedView {
 public:
  using Scalar = float;
  /// Poses every vertex of b by x (check_rigid first, as pose_vertices_into,
  /// which throws the same error on a pose that is not a rotation, unless
  /// `rigid`: the caller has proven that check_rigid(x) passes,
  /// coherence.hpp's stays_rigid); false when a coordinate or the extent is
  /// outside the range below, where posing's own checks decide.
  bool pose(const ConvexPolyhedron<float>& b, const RigidTransform<float>& x, bool rigid) {
    if (!rigid) sepax::detail::check_rigid(x);
    src_ = &b;
    const int n = b.vertex_count();
    if (vertices_.size() != static_cast<std::size_t>(n)) vertices_.resize(static_cast<std::size_t>(n));
    if (planes_.size() != static_cast<std::size_t>(b.face_count()))
      planes_.resize(static_cast<std::size_t>(b.face_count()));
    // Posing refuses |coordinate| > FLT_MAX / 16 (and NaN); within 2^64 it
    // never does, so a view inside that range decides what posing decides.
    bool in_range = true;
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    const int grouped = pose_groups(b, x, lo, hi, in_range);
    for (int i = grouped; i < n; ++i) {
      Vec3<float>& v = vertices_[static_cast<std::size_t>(i)];
      v = x.apply(b.vertex(i));
      in_range &= std::abs(v[0]) <= kRange && std::abs(v[1]) <= kRange && std::abs(v[2]) <= kRange;
      for (int c = 0; c < 3; ++c) {
        if (i == 0) {
          lo[c] = hi[c] = v[c];
          continue;
        }
        lo[c] = v[c] < lo[c] ? v[c] : lo[c];
        hi[c] = v[c] > hi[c] ? v[c] : hi[c];
      }
    }
    if (!in_range || n < 3) return false;
    const double w0 = static_cast<double>(float(hi[0] - lo[0])),
                 w1 = static_cast<double>(float(hi[1] - lo[1])),
                 w2 = static_cast<double>(float(hi[2] - lo[2]));
    double d2 = 0;
    d2 += w0 * w0;
    d2 += w1 * w1;
    d2 += w2 * w2;
    extent_ = std::sqrt(d2);
    // Posing refuses an extent whose tolerances fall into float's subnormal
    // range (Tolerances<float>::kCoplanar 1e-5 x kAdjacentCoplanarFraction
    // 0.25 x extent < FLT_MIN, i.e. extent < 4.8e-33): decline far above.
    return extent_ >= 1e-30;
  }

  /// The plane of face f from the posed vertices (plane_of_triple); false
  /// where plane_of_triple would rescale the cross product.  Inlined into
  /// its callers, as plane_of_triple is.
  [[gnu::always_inline]] bool derive(int f) {
    const auto& t = src_->face(f).plane_vertices;
    const sepax::detail::TripleCross<float> x =
        sepax::detail::triple_cross(vertex(t[0]).data(), vertex(t[1]).data(), vertex(t[2]).data());
    if (!sepax::detail::safe_squared_norm(x.s)) return false;
    planes_[static_cast<std::size_t>(f)] = sepax::detail::unit_plane(x.c0, x.c1, x.c2, x.s, x.a0, x.a1, x.a2);
    return true;
  }

  int vertex_count() const { return static_cast<int>(vertices_.size()); }
  int face_count() const { return src_->face_count(); }
  const Vec3<float>& vertex(int v) const { return vertices_[static_cast<std::size_t>(v)]; }
  /// Only the planes derived since pose() are B''s.
  const Plane<float>& plane(int f) const { return planes_[static_cast<std::size_t>(f)]; }
  const FaceLoop& face(int f) const { return src_->face(f); }
  const HalfEdge& half_edge(int h) const { return src_->half_edge(h); }
  std::span<const int> vertex_half_edges(int v) const { return src_->vertex_half_edges(v); }
  double extent() const { return extent_; }

 private:
  /// |coordinate| limit of a view, in the shape's length unit (pose above).
  static constexpr float kRange = 0x1p64f;

  /// Vertices [0, k W) of b posed a SIMD group at a time (W =
  /// simd::Lanes<float>::width, k W the largest multiple of W up to the
  /// vertex count) from b's vertex lanes with posing's lane expression
  /// (detail::PoseLanes, as pose_vertices_into), the rest left to x.apply
  /// as it leaves them: the same instructions for the same vertices, so the
  /// same values with FMA contraction on or off.  When k W > 0, lo and hi
  /// get the posed vertices' smallest and largest coordinates
  /// (simd::LaneBounds over the groups, then L::hmin over the lanes; the
  /// same values as any order of comparison where no coordinate is NaN,
  /// up to a zero's sign) and
  /// in_range is false when a coordinate is NaN or beyond kRange (lo
  /// and hi are then not read).  Returns k W.
  int pose_groups(const ConvexPolyhedron<float>& b, const RigidTransform<float>& x, float (&lo)[3],
                  float (&hi)[3], bool& in_range) {
    using L = simd::Lanes<float>;
    constexpr int W = L::width;
    if constexpr (W == 1) {
      (void)b, (void)x, (void)lo, (void)hi, (void)in_range;
      return 0;
    } else {
      using V = typename L::V;
      const int done = b.vertex_count() / W * W;
      if (done == 0) return 0;
      const sepax::detail::PoseLanes<float> pose(x);
      const float* const lx = b.lane_vertex(0);
      const float* const ly = b.lane_vertex(1);
      const float* const lz = b.lane_vertex(2);
      simd::LaneBounds<float> box(kRange);
      for (int g = 0; g < done; g += W) {
        V vx = L::load(lx + g), vy = L::load(ly + g), vz = L::load(lz + g);
        pose(vx, vy, vz);
        L::store_xyz(vertices_[static_cast<std::size_t>(g)].data(), vx, vy, vz);
        box.add(vx, vy, vz);
      }
      in_range = box.within();
      // the lowest and highest over the lanes (L::hmin; the highest as the
      // negated lowest of the negated lanes, both exact): the same values
      // as LaneBounds::reduce where no coordinate is NaN (where one is,
      // in_range is false and the extent is not read), but a zero's sign,
      // which does not change max - min squared
      for (int c = 0; c < 3; ++c) {
        lo[c] = L::first(L::hmin(box.lo[c]));
        hi[c] = -L::first(L::hmin(L::neg(box.hi[c])));
      }
      return done;
    }
  }

  const ConvexPolyhedron<float>* src_ = nullptr;
  std::vector<Vec3<float>> vertices_;
  std::vector<Plane<float>> planes_;
  double extent_ = 0;
};

}  // namespace sepax::bullet
