// sepax/convex_hull.hpp
//
// convex_hull(points): the convex hull of a point set as a validated ConvexPolyhedron<T>, for every number
// type T (one template, no copies).  The steps, each in its header under hull/ (docs/hull.md):
//   1. input checks and welding (welded_points.hpp);
//   2. the initial simplex; a flat set is a 2D hull (quickhull.hpp, flat_hull.hpp);
//   3. quickhull with conflict lists (quickhull.hpp);
//   4. coplanar triangles merged into faces (face_merge.hpp);
//   5. face loops, clean-up, rebuild without rejected points (face_loops.hpp);
//   6. float T: the pre-check of what validation will check (precheck.hpp);
//   7. validation by ConvexPolyhedron<T>::from_faces (a failure there is a builder bug, std::logic_error);
//   8. float T: repair passes and the fallback policy (repair.hpp, fallbacks.hpp).
// Float T decides on the points translated by the centre of their bounding box, and far from unit size on
// a power of two times them (working_scale.hpp); the output vertices are the input points (except the
// documented fallbacks).  Exact T makes every decision exactly.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "hull/builder.hpp"
#include "hull/face_loops.hpp"
#include "hull/face_merge.hpp"
#include "hull/fallbacks.hpp"
#include "hull/flat_hull.hpp"
#include "hull/precheck.hpp"
#include "hull/quickhull.hpp"
#include "hull/repair.hpp"
#include "hull/traits.hpp"
#include "hull/vertex_removal.hpp"
#include "hull/welded_points.hpp"
#include "hull/working_scale.hpp"
#include "number_traits.hpp"
#include "tolerances.hpp"
#include "vec3.hpp"

namespace sepax {

namespace hull::detail {

/// The hull algorithm: welding, build passes, and for float T repair passes and the fallback policy.
template <Number T>
ConvexPolyhedron<T> build_hull(std::span<const Vec3<T>> points, bool allow_tent) {
  Builder<T> builder(points, allow_tent);
  // 1. NonFinite, TooFewPoints, BadScale; eps, flat and weld of the extent; the points welded.
  builder.check_input();
  builder.weld();
  RepairLog<T> log;
  std::vector<int> pinned;        // (float T: the points the last repair pass pinned)
  std::uint64_t last_digest = 0;  // (float T: the digest of the last pass's result)
  for (int pass = 0;; ++pass) {
    // 2-7. Initial simplex (or the flat hull), quickhull, face merge, loops and clean-up, pre-check,
    // validation; rebuilt without the points the clean-up rejects.  A repair pass may lose too many; it
    // goes on from the last pass's triangles with the pinned points when it can.
    std::optional<ConvexPolyhedron<T>> hull = builder.build_pass(log.nearest.has_value(), pinned);
    if constexpr (!HullTraits<T>::kRepairs) {
      return std::move(*hull);  // exact T: the exact hull holds every point
    } else {
      // 8. Float T: points farther than kHullRepairTolerance x eps from the result are pinned and the
      // hull rebuilt, at most kHullMaxRepairs times, and no more once a repair pass repeated the one
      // before: the same result (digest), the same points taken out by the clean-up at its end, and only
      // points already pinned left out (Builder::repeats).  Then the best result or a fallback.
      std::vector<int> outside;
      const std::uint64_t d = hull ? builder.measure(std::move(*hull), outside, log) : 0;
      if (!hull || outside.empty() || pass == kHullMaxRepairs) return builder.choose_result(log);
      if (pass > 0 && builder.repeats(d, last_digest, outside)) return builder.choose_result(log);
      last_digest = d;
      builder.pin(outside);
      pinned = std::move(outside);
    }
  }
}

}  // namespace hull::detail

/// The convex hull of points (docs/hull.md for the steps and the guarantees).
/// Throws InvalidInput: NonFinite (naming the point), TooFewPoints (< 3
/// distinct points), Collinear, BadScale (float/double: an extent outside the
/// range ConvexPolyhedron<T> accepts, or points too far from the origin for
/// float to resolve: use convex_hull_local).
template <Number T>
ConvexPolyhedron<T> convex_hull(std::span<const Vec3<T>> points) {
  if constexpr (hull::detail::HullTraits<T>::kWorkingScale) {
    // float / double far from unit size: built at a power of two times the points (working_scale.hpp)
    if (const int k = hull::detail::working_scale(points); k != 0) {
      const std::vector<Vec3<T>> scaled = hull::detail::scaled_points(points, k);
      return hull::detail::scaled_back(hull::detail::build_hull<T>(scaled, true), k, points, scaled);
    }
  }
  return hull::detail::build_hull<T>(points, true);
}

template <Number T>
ConvexPolyhedron<T> convex_hull(const std::vector<Vec3<T>>& points) {
  return convex_hull<T>(std::span<const Vec3<T>>(points.data(), points.size()));
}

}  // namespace sepax

#include "hull/local_frame.hpp"
