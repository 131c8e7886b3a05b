// sepax/manifold_result.hpp
//
// What contact_manifold (contact_manifold.hpp) returns and takes:
//   * ContactManifold<T>: the contact kind, the normal from A to B, the SAT
//     separation, the reference and incident faces, and up to
//     kManifoldInlinePoints points without allocating;
//   * ContactPoint<T>: a point on each shape, its separation and the features
//     that made it (contact_feature.hpp);
//   * ManifoldOptions: reduction, speculative margin, recorded clip steps;
//   * the helpers every contact kind shares (squared normal lengths, the
//     margin test, index checks, extent-relative tolerances).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "contact_feature.hpp"
#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "feature.hpp"
#include "manifold_reduction.hpp"
#include "separation.hpp"
#include "small_vector.hpp"

namespace sepax {

enum class ContactKind : std::uint8_t { None = 0, Face = 1, Edge = 2, Side = 3 };

inline const char* to_string(ContactKind k) {
  switch (k) {
    case ContactKind::None:
      return "none";
    case ContactKind::Face:
      return "face";
    case ContactKind::Edge:
      return "edge";
    case ContactKind::Side:
      return "side";
  }
  return "?";
}

/// Options of contact_manifold.  The speculative margin is an absolute user
/// distance (same units as the shapes): shapes separated by at most the margin
/// get a manifold with the points whose separation is <= margin.  Every
/// internal tolerance is relative to the shapes' extent and named in
/// tolerances.hpp (kContactWeld, kContactArea); exact types use none.
struct ManifoldOptions {
  /// Keep at most 4 points (deepest + largest area).  false keeps all.
  bool reduce = true;
  /// Speculative margin: an absolute distance >= 0 in the shapes' units.
  double margin = 0;
  /// Record the clip steps (ContactManifold::clip_steps), for audits.
  bool record_steps = false;
};

/// One contact point (docs/contacts.md):
///   position    (point_a + point_b) / 2;
///   point_a/b   the contact point on A / on B: for a face contact one of them
///               is the clipped incident point, the other its projection onto
///               the reference plane; for an edge contact, the closest points
///               of the two segments;
///   separation  Separation{num, norm2}, value num/sqrt(norm2) along the unit
///               normal; < 0 penetration (depth = -value), > 0 only within a
///               speculative margin.  For a face contact it is the height of
///               the incident point above the reference plane; for an edge
///               contact the SAT separation;
///   id          the features of A and B that made the point
///               (contact_feature.hpp).
/// For exact T and rational inputs everything is exact.
template <class T>
struct ContactPoint {
  Vec3<T> position;  // (point_a + point_b) / 2
  Vec3<T> point_a;   // on A
  Vec3<T> point_b;   // on B
  Separation<T> separation;
  ContactFeatureId id;

  /// Penetration depth as a double (reporting only): -separation.
  double depth() const { return -sepax::to_double(separation); }
};

/// One Sutherland-Hodgman step: the incident polygon clipped by the side plane
/// of reference edge `side_edge`.
struct ClipStep {
  int side_edge = -1;
  int vertices_in = 0;
  int vertices_out = 0;
};

/// Inline capacities (small_vector.hpp): a manifold keeps up to
/// kManifoldInlinePoints points without allocating (with ManifoldOptions::
/// reduce, the default, it keeps at most 4); the clipped incident polygon
/// and its candidate points use up to kManifoldInlineClip vertices on the
/// stack (the reduction's tables: manifold_reduction.hpp).  Beyond these
/// sizes they spill to the heap.
inline constexpr std::size_t kManifoldInlinePoints = 8;
inline constexpr std::size_t kManifoldInlineClip = kReductionInlinePoints;

/// The contact manifold of a pair.  `normal` points from A to B (the SAT
/// axis): unit when T normalises; for rationals the exact unnormalised axis,
/// whose squared length is `norm2` (no sqrt anywhere).
template <class T>
struct ContactManifold {
  ContactKind kind = ContactKind::None;
  /// The SAT feature the manifold was built from.
  Feature feature;
  /// From A to B; unit iff number_traits<T>::normalizes, else |normal|^2 == norm2.
  Vec3<T> normal = Vec3<T>(T(0), T(0), T(0));
  T norm2 = T(1);
  /// The SAT separation along `normal` (<= 0 overlapping).
  Separation<T> separation;
  /// Face contacts: 0 when the reference face is on A, 1 when on B.
  int reference_shape = -1;
  int reference_face = -1;
  int incident_face = -1;
  /// Faces the incident-face search evaluated.
  int incident_faces_visited = 0;
  /// Points below the reference face before the reduction.
  int candidate_points = 0;
  /// Face contact whose clipped incident face was empty: the manifold is the
  /// support vertex alone (a safety net; see docs/contacts.md).
  bool support_fallback = false;
  SmallVector<ContactPoint<T>, kManifoldInlinePoints> points;
  /// Filled when ManifoldOptions::record_steps is set.
  std::vector<ClipStep> clip_steps;

  bool empty() const { return points.empty(); }
  int size() const { return static_cast<int>(points.size()); }

  /// The translation of B, along `normal`, that brings the shapes exactly to
  /// touching (the SAT separation becomes 0): normal * (-num / norm2).  Exact
  /// for exact T (no sqrt).
  Vec3<T> resolving_translation() const {
    const T s = T(-separation.num) / separation.norm2;
    return Vec3<T>(normal[0] * s, normal[1] * s, normal[2] * s);
  }
};

namespace detail {

template <Number T>
T norm2_of(const Vec3<T>& n) {
  if constexpr (number_traits<T>::normalizes) {
    (void)n;
    return T(1);
  } else {
    return squared_norm(n);
  }
}

/// s <= margin, exactly for exact T (squared form, no sqrt).
template <Number T>
bool within_margin(const Separation<T>& s, const T& margin) {
  if (!(s.num > T(0))) return true;
  if constexpr (number_traits<T>::normalizes) {
    return s.num <= margin;
  } else {
    return s.num * s.num <= margin * margin * s.norm2;
  }
}

[[noreturn]] inline void bad_feature(const std::string& what) {
  throw InvalidInput(ErrorCode::BadIndex,
                     "contact_manifold: the SAT result does not fit the shapes: " + what);
}

inline void check_index(int i, int count, const char* what) {
  if (i < 0 || i >= count) {
    bad_feature(std::string(what) + " " + std::to_string(i) + " out of range [0, " + std::to_string(count) +
                ")");
  }
}

/// Float and double: while the smaller extent is within 2^+-kManifoldUnscaledBand<T> of 1 (float
/// 2^+-32, double 2^+-256) the manifold's weld and reduction tests use lengths as they are: squared
/// lengths, areas and their tolerances stay far inside T's range.  Beyond it they are compared in units
/// of a power of two near the extent (manifold_scale_exponent).
template <class T>
inline constexpr int kManifoldUnscaledBand = std::numeric_limits<T>::max_exponent / 4;

/// The power of two the manifold's length tests are made in (float and double): 0 while the smaller
/// extent is within 2^+-kManifoldUnscaledBand<T> of 1, else k with 2^k <= that extent < 2^(k+1):
/// lengths, squared lengths and areas are then compared as multiples of 2^k, 4^k (in_manifold_units), so
/// that they stay in range at every scale the shapes accept.  Scaling by a power of two is exact in
/// range: where 0 would do, k gives the same decisions.  0 for exact T.
template <Number T, class P = ConvexPolyhedron<T>>
int manifold_scale_exponent(const ConvexPolyhedron<T>& a, const P& b) {
  if constexpr (number_traits<T>::is_exact) {
    (void)a, (void)b;
    return 0;
  } else {
    const double ext = std::min(a.extent(), b.extent());
    if (!(ext > 0) || !std::isfinite(ext)) return 0;
    constexpr int kBand = kManifoldUnscaledBand<T>;
    const int e = pow2_exponent(ext);
    return e >= -kBand && e <= kBand ? 0 : e;
  }
}

/// v 2^-k (manifold_scale_exponent's k): v itself for k = 0 and exact T.
template <Number T>
Vec3<T> in_manifold_units(const Vec3<T>& v, int k) {
  if constexpr (std::is_floating_point_v<T>) {
    if (k != 0) return scale_pow2(v, k);
  }
  return v;
}
/// x 2^-k (manifold_scale_exponent's k): x itself for k = 0 and exact T.
template <Number T>
T in_manifold_units(const T& x, int k) {
  if constexpr (std::is_floating_point_v<T>) {
    if (k != 0) return scale_value_pow2(x, k);
  }
  return x;
}

/// A tolerance relative to the smaller of the two shapes' extents (0 for exact
/// T): power 1 a length rel x ext, 2 its square, 3 an area rel x ext^2; in
/// units of 2^scale_exponent (manifold_scale_exponent).
template <Number T, class P = ConvexPolyhedron<T>>
T extent_tolerance(const ConvexPolyhedron<T>& a, const P& b, double rel, int power, int scale_exponent = 0) {
  if constexpr (number_traits<T>::is_exact) {
    (void)a, (void)b, (void)rel, (void)power, (void)scale_exponent;
    return T(0);
  } else {
    const double ext = std::ldexp(std::min(a.extent(), b.extent()), -scale_exponent);
    return static_cast<T>(power == 1 ? rel * ext : (power == 2 ? rel * ext * rel * ext : rel * ext * ext));
  }
}

}  // namespace detail

}  // namespace sepax
