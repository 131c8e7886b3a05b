// sepax/convex_polyhedron_rigid.hpp
//
// ConvexPolyhedron<T>'s rigid image (convex_polyhedron.hpp declares it;
// posing.hpp is the entry point and defines the input a posed query decides
// on), in the order posing runs it:
//   * assign_rigid_vertices(): the topology, the image vertices with their
//     lanes, bounds, centroid and range checks (rigid_vertex_groups(): a few
//     vertices at a time in SIMD lanes);
//   * derive_rigid_part(): only the planes and edge entries a check reads;
//   * finish_rigid_image(): every plane (compute_planes), per-edge array and
//     lane (derive_rigid_edges()).
// Each step computes bit for bit what with_vertices computes from the same
// vertices.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <type_traits>

#include "convex_polyhedron.hpp"
#include "simd_ops.hpp"

namespace sepax {

template <Number T>
template <class Point, class PointLanes>
inline void ConvexPolyhedron<T>::assign_rigid_vertices(const ConvexPolyhedron& src, Point&& point,
                                                       PointLanes&& point_lanes) {
  if (!topology_.same_as(src.topology_)) topology_ = src.topology_;  // shared, not copied
  // (sized only when the size changes: resize is a call even when it has
  // nothing to do)
  auto size_to = [](auto& v, std::size_t n) {
    if (v.size() != n) v.resize(n);
  };
  const std::size_t nv = src.vertices_.size();
  size_to(vertices_, nv);
  size_to(planes_, static_cast<std::size_t>(topology_.face_count()));
  const auto ne = static_cast<std::size_t>(edge_count());
  size_to(edge_dirs_, ne);
  lanes_bounded_ = support_lanes_bounded_ = false;
  normal_conditioning_.store(std::numeric_limits<double>::infinity());
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    size_lanes();
    const auto vs = static_cast<std::size_t>(lane_vertex_stride_);
    T* const lv = lanes_.data() + 9 * static_cast<std::size_t>(lane_edge_stride_);
    const T tmax = std::numeric_limits<T>::max();
    const T inf = std::numeric_limits<T>::infinity();
    // bounds from +-infinity: the first vertex sets both (compute_bounds
    // starts from it and compares it with itself: the same values)
    // per coordinate in registers (x, y, z spelled out: a loop over the
    // coordinates kept them in memory)
    T lo0 = inf, lo1 = inf, lo2 = inf, hi0 = -inf, hi1 = -inf, hi2 = -inf;
    T s0 = T(0), s1 = T(0), s2 = T(0);
    bool finite = true;
    std::size_t i = 0;
    if constexpr (!std::is_same_v<std::remove_cvref_t<PointLanes>, std::nullptr_t>)
      i = rigid_vertex_groups(src, point_lanes, lo0, lo1, lo2, hi0, hi1, hi2, s0, s1, s2, finite);
    for (; i < nv; ++i) {
      const Vec3<T> v = point(src.vertices_[i]);
      vertices_[i] = v;
      const T x = v[0], y = v[1], z = v[2];
      s0 = s0 + x;
      s1 = s1 + y;
      s2 = s2 + z;
      lv[i] = x;
      lv[vs + i] = y;
      lv[2 * vs + i] = z;
      finite &= std::abs(x) <= tmax;  // false for NaN and infinities
      finite &= std::abs(y) <= tmax;
      finite &= std::abs(z) <= tmax;
      lo0 = x < lo0 ? x : lo0;
      lo1 = y < lo1 ? y : lo1;
      lo2 = z < lo2 ? z : lo2;
      hi0 = x > hi0 ? x : hi0;
      hi1 = y > hi1 ? y : hi1;
      hi2 = z > hi2 ? z : hi2;
    }
    if (nv != vs)  // the lanes' padding
      for (std::size_t c = 0; c < 3; ++c) std::fill(lv + c * vs + nv, lv + (c + 1) * vs, T(0));
    if (!finite || nv < 3) check_coordinates();  // throws, naming the vertex
    bmin_ = Vec3<T>(lo0, lo1, lo2);
    bmax_ = Vec3<T>(hi0, hi1, hi2);
    finish_bounds(Vec3<T>(s0, s1, s2));
  } else {
    for (std::size_t i = 0; i < nv; ++i) vertices_[i] = point(src.vertices_[i]);
    check_coordinates();
    compute_bounds();
  }
  if constexpr (!number_traits<T>::is_exact) {
    if (!(extent_ > 0)) fail(ErrorCode::BadScale, "all vertices coincide: the shape has no extent");
    if (!coordinates_in_range()) check_range(false);  // throws, naming the quantity
  }
  // the vertex lanes are written and every coordinate is finite (checked
  // above); no plane is derived yet
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>)
    support_lanes_bounded_ = max_abs_ <= 0x1p60;
}

template <Number T>
inline void ConvexPolyhedron<T>::derive_rigid_part(std::span<const int> faces, std::span<const int> edges) {
  [[maybe_unused]] NormalConditioningScan scan;
  bool normals_bounded = true;  // (false for NaN)
  auto derive = [&](int f) {
    derive_plane(f, &scan);
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
      const Plane<T>& pl = planes_[static_cast<std::size_t>(f)];
      for (int c = 0; c < 3; ++c) normals_bounded &= std::abs(pl.normal[c]) <= T(0x1p60);
    }
  };
  if (is_flat()) {
    derive(0);  // the back face: the front one negated (compute_derived)
    planes_[1] = Plane<T>{Vec3<T>(-planes_[0].normal), T(-planes_[0].offset)};
  } else {
    for (const int f : faces) derive(f);
  }
  for (const int e : edges) derive_edge_direction(static_cast<std::size_t>(e));
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    normal_conditioning_.store(scan.result());
    support_lanes_bounded_ = support_lanes_bounded_ && normals_bounded;
  }
}

template <Number T>
inline void ConvexPolyhedron<T>::finish_rigid_image(bool edge_lanes) {
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    const PlanesInRange pr = compute_planes(true);
    // extent and coordinates were checked with the vertices; a plane that
    // is not finite is refused by check_range, one without a normal by
    // check_plane_normals (both pass otherwise)
    if (!(pr.normals_bounded && pr.offsets_finite)) {
      check_range();
      check_plane_normals();
    }
    const bool edges_bounded = edge_lanes ? derive_rigid_edges<true>() : derive_rigid_edges<false>();
    // compute_lanes' bound: normals, directions and vertices within 2^60
    // (max_abs_ is the largest |vertex coordinate|, exactly)
    lanes_bounded_ = support_lanes_bounded_ = pr.normals_bounded && edges_bounded && max_abs_ <= 0x1p60;
  } else {
    compute_derived(true, false);
    check_new_range();
  }
}

template <Number T>
template <bool kLanes, bool kCheck>
inline bool ConvexPolyhedron<T>::derive_rigid_edges() {
  const auto ne = static_cast<std::size_t>(edge_count());
  const auto es = static_cast<std::size_t>(lane_edge_stride_);
  T* const l = lanes_.data();
  [[maybe_unused]] const T big = T(0x1p60);
  bool ok = true;
  for (std::size_t e = 0; e < ne; ++e) {
    derive_edge_direction(e);
    const Vec3<T> d = edge_dirs_[e];  // (a copy: the lane stores below may alias it)
    const HalfEdge& h0 = topology_.half_edges()[2 * e];
    const HalfEdge& h1 = topology_.half_edges()[2 * e + 1];
    for (int c = 0; c < 3; ++c) {
      if constexpr (kCheck) ok &= std::abs(d[c]) <= big;
      if constexpr (kLanes) {
        const auto k = static_cast<std::size_t>(c);
        l[k * es + e] = planes_[static_cast<std::size_t>(h0.face)].normal[c];
        l[(3 + k) * es + e] = T(-planes_[static_cast<std::size_t>(h1.face)].normal[c]);
        l[(6 + k) * es + e] = d[c];
      }
    }
  }
  if constexpr (kLanes) {
    for (std::size_t k = 0; k < 9; ++k) std::fill(l + k * es + ne, l + (k + 1) * es, T(0));
  }
  return ok;
}

// (inlined into assign_rigid_vertices, its one caller: its ten results stay
// in registers)
template <Number T>
template <class PointLanes>
[[gnu::always_inline]] inline std::size_t ConvexPolyhedron<T>::rigid_vertex_groups(
    const ConvexPolyhedron& src, PointLanes& point_lanes, T& lo0, T& lo1, T& lo2, T& hi0, T& hi1, T& hi2,
    T& s0, T& s1, T& s2, bool& finite) {
  using L = simd::Lanes<T>;
  constexpr int W = L::width;
  if constexpr (W == 1) {
    (void)src, (void)point_lanes, (void)lo0, (void)lo1, (void)lo2, (void)hi0, (void)hi1, (void)hi2;
    (void)s0, (void)s1, (void)s2, (void)finite;
    return 0;
  } else {
    using V = typename L::V;
    static_assert(sizeof(Vec3<T>) == 3 * sizeof(T), "store_xyz writes Vec3<T> as three contiguous T");
    const std::size_t done = src.vertices_.size() / W * W;
    if (done == 0) return 0;
    const auto vs = static_cast<std::size_t>(lane_vertex_stride_);
    const auto ss = static_cast<std::size_t>(src.lane_vertex_stride_);
    const T* const sx = src.lanes_.data() + 9 * static_cast<std::size_t>(src.lane_edge_stride_);
    T* const lv = lanes_.data() + 9 * static_cast<std::size_t>(lane_edge_stride_);
    simd::LaneBounds<T> box(std::numeric_limits<T>::max());
    // the vertex sum in index order: float, the three coordinates in the
    // lanes of one register (Lanes::add_points); double, after the groups
    [[maybe_unused]] V sum = L::set1(T(0));
    for (std::size_t b = 0; b < done; b += W) {
      V x = L::load(sx + b), y = L::load(sx + ss + b), z = L::load(sx + 2 * ss + b);
      point_lanes(x, y, z);
      L::store(lv + b, x);
      L::store(lv + vs + b, y);
      L::store(lv + 2 * vs + b, z);
      L::store_xyz(vertices_[b].data(), x, y, z);  // (Vec3<T> is three contiguous T)
      box.add(x, y, z);
      if constexpr (std::is_same_v<T, float>) L::add_points(sum, x, y, z);
    }
    if constexpr (std::is_same_v<T, float>) {
      alignas(16) T st[W];
      L::store(st, sum);
      s0 = st[0], s1 = st[1], s2 = st[2];
    } else {
      for (std::size_t k = 0; k < done; ++k) {  // the sequential sum, in index order
        s0 = s0 + lv[k];
        s1 = s1 + lv[vs + k];
        s2 = s2 + lv[2 * vs + k];
      }
    }
    finite &= box.within();
    T lo[3], hi[3];
    if (!box.reduce(lo, hi)) [[unlikely]] {  // (done > 0) some bound is zero
      // A zero bound: its sign is that of the first zero in index order (the
      // sequential comparisons keep the first of equal values), so it is
      // found again in that order.  Each bound tested in turn, written out (a
      // loop over the six was not unrolled).
      auto signed_zero = [&](T& r, int c, bool is_lo) {
        if (r != T(0)) return;
        const T* const lane = lv + static_cast<std::size_t>(c) * vs;
        r = is_lo ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
        for (std::size_t k = 0; k < done; ++k)
          r = is_lo ? (lane[k] < r ? lane[k] : r) : (lane[k] > r ? lane[k] : r);
      };
      signed_zero(lo[0], 0, true), signed_zero(lo[1], 1, true), signed_zero(lo[2], 2, true);
      signed_zero(hi[0], 0, false), signed_zero(hi[1], 1, false), signed_zero(hi[2], 2, false);
    }
    lo0 = lo[0], lo1 = lo[1], lo2 = lo[2], hi0 = hi[0], hi1 = hi[1], hi2 = hi[2];
    return done;
  }
}

}  // namespace sepax
