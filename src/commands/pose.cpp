// src/commands/pose.cpp -- see pose.hpp.
#include "commands/pose.hpp"

#include <cmath>

#include <sepax/error.hpp>

namespace sepax::cli {

Pose Pose::make(const Vec3<double>& t, std::array<double, 4> q) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(t[i])) throw InvalidInput(ErrorCode::NonFinite, "--pose: the translation is not finite");
  }
  double n2 = 0;
  for (const double c : q) {
    if (!std::isfinite(c)) throw InvalidInput(ErrorCode::NonFinite, "--pose: the quaternion is not finite");
    n2 += c * c;
  }
  const double n = std::sqrt(n2);
  if (!(n > 0) || !std::isfinite(n)) {
    throw InvalidInput(ErrorCode::BadScale, "--pose: the quaternion is zero (or too large to normalise)");
  }
  Pose p;
  p.translation = t;
  if (n != 1.0) {
    for (double& c : q) c /= n;
  }
  p.rotation = q;
  return p;
}

Vec3<double> Pose::apply(const Vec3<double>& p) const {
  const double w = rotation[0], x = rotation[1], y = rotation[2], z = rotation[3];
  const double r00 = 1 - 2 * (y * y + z * z), r01 = 2 * (x * y - w * z), r02 = 2 * (x * z + w * y);
  const double r10 = 2 * (x * y + w * z), r11 = 1 - 2 * (x * x + z * z), r12 = 2 * (y * z - w * x);
  const double r20 = 2 * (x * z - w * y), r21 = 2 * (y * z + w * x), r22 = 1 - 2 * (x * x + y * y);
  return Vec3<double>(r00 * p[0] + r01 * p[1] + r02 * p[2] + translation[0],
                      r10 * p[0] + r11 * p[1] + r12 * p[2] + translation[1],
                      r20 * p[0] + r21 * p[1] + r22 * p[2] + translation[2]);
}

}  // namespace sepax::cli
