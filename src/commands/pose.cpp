// src/commands/pose.cpp -- see pose.hpp.
#include "commands/pose.hpp"

#include <cmath>

#include <sepax/error.hpp>

namespace sepax::cli {

Pose Pose::make(const Vec3<double>& t, std::array<double, 4> q) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(t[i]))
      throw InvalidInput(ErrorCode::NonFinite, "--pose: the translation is not finite");
  }
  for (const double c : q) {
    if (!std::isfinite(c)) throw InvalidInput(ErrorCode::NonFinite, "--pose: the quaternion is not finite");
  }
  if (!normalize_quaternion(q)) throw InvalidInput(ErrorCode::BadScale, "--pose: the quaternion is zero");
  Pose p;
  p.translation = t;
  p.rotation = q;
  p.transform = RigidTransform<double>::from_quaternion(q[0], q[1], q[2], q[3], t);
  return p;
}

Vec3<double> Pose::apply(const Vec3<double>& p) const { return transform.apply(p); }

}  // namespace sepax::cli
