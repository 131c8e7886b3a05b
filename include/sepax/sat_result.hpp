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
  /// Stop at the first separating axis found (separation > 0).  The result is
  /// then "separated" with that axis, which need not be the axis of maximum
  /// separation.
  bool early_out = false;
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
  /// The search stopped at the first separating axis (SatOptions::early_out).
  bool early_out = false;
  SatStats stats;

  double separation_as_double() const { return sepax::to_double(separation); }
};

}  // namespace sepax
