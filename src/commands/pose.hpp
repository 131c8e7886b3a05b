// src/commands/pose.hpp
//
// A rigid pose for the --pose option: x -> R(q) x + t, with R(q) the rotation
// of the unit quaternion q = (w, x, y, z) (the given quaternion divided by its
// length).  Evaluated in double; for exact number types the posed double
// coordinates are then converted exactly (see shape_builder.hpp).  The motion
// itself is sepax::RigidTransform<double>::from_quaternion (sepax/transform.hpp).
#pragma once

#include <array>

#include <sepax/transform.hpp>
#include <sepax/vec3.hpp>

namespace sepax::cli {

struct Pose {
  Vec3<double> translation = Vec3<double>(0, 0, 0);
  std::array<double, 4> rotation{1, 0, 0, 0};  // unit quaternion w, x, y, z
  RigidTransform<double> transform;            // the same motion as a matrix

  /// Throws InvalidInput for non-finite values or a zero quaternion.
  static Pose make(const Vec3<double>& t, std::array<double, 4> q = {1, 0, 0, 0});

  /// R p + t.  The identity rotation leaves p unchanged bit for bit.
  Vec3<double> apply(const Vec3<double>& p) const;
};

}  // namespace sepax::cli
