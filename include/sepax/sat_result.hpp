// sepax/sat_result.hpp
//
// The result every SAT returns (brute force, Gauss map, traversal; any T; any
// policy), and the options they take.
#pragma once

#include <cstdint>

#include "feature.hpp"
#include "separation.hpp"
#include "vec3.hpp"

namespace sepax {

struct SatOptions {
  /// Stop at the first candidate axis whose separation is proven greater than
  /// `margin` (with margin 0: the first separating axis).  The result is then
  /// "separated" with that axis (SatResult::early_out set), which need not be
  /// the axis of maximum separation.  Under policy::Robust and with exact T
  /// "greater than the margin" is decided exactly (the feature's exact
  /// separation against the double value of margin); plain float/double
  /// compare the rounded value.
  bool early_out = false;
  /// A speculative margin (>= 0, finite; in the shapes' length unit): with
  /// early_out, a query stops only at a separation > margin, so a pair it
  /// does not stop for is either overlapping or closer than the margin and
  /// gets the full result (the axis of maximum separation).  Ignored without
  /// early_out.  contact_manifold keeps points within it.  A negative or
  /// non-finite margin is refused (InvalidInput, BadScale).
  double margin = 0.0;
};

struct SatStats {
  std::int64_t face_axes = 0;        // face normals evaluated
  std::int64_t edge_pairs = 0;       // edge pairs looked at
  std::int64_t minkowski_faces = 0;  // edge pairs that form a face of A - B
  std::int64_t side_axes = 0;        // in-plane edge normals (coplanar flat shapes only)
  std::int64_t exact_fallbacks = 0;  // robust policy: decisions the filter could not make
};

template <class T>
struct SatResult {
  /// No separating axis: the shapes share at least one point.  Touching shapes
  /// (maximum separation exactly 0) overlap.
  bool overlap = false;
  /// The candidate axis of maximum separation (= minimum penetration when
  /// overlapping), with its support feature on the other shape; see feature.hpp
  /// for the tie-break.
  Feature feature;
  /// Signed separation along that axis (> 0 separated, <= 0 overlapping).
  Separation<T> separation;
  /// The axis, pointing from A towards B.  Unit when T normalises; otherwise the
  /// unnormalised axis whose squared length is separation.norm2.
  Vec3<T> axis = Vec3<T>(T(0), T(0), T(0));
  /// The search stopped at an axis proven to separate by more than
  /// SatOptions::margin (SatOptions::early_out): then overlap is false and
  /// separation > margin (decided exactly under policy::Robust and exact T).
  bool early_out = false;
  SatStats stats;

  double separation_as_double() const { return sepax::to_double(separation); }
};

}  // namespace sepax
