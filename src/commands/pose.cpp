// src/commands/pose.cpp -- see pose.hpp.
#include "commands/pose.hpp"

#include <algorithm>
#include <cmath>

#include <sepax/error.hpp>

namespace sepax::cli {

Pose Pose::make(const Vec3<double>& t, std::array<double, 4> q) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(t[i]))
      throw InvalidInput(ErrorCode::NonFinite, "--pose: the translation is not finite");
  }
  double n2 = 0, largest = 0;
  for (const double c : q) {
    if (!std::isfinite(c)) throw InvalidInput(ErrorCode::NonFinite, "--pose: the quaternion is not finite");
    n2 += c * c;
    largest = std::max(largest, std::fabs(c));
  }
  if (!(largest > 0)) throw InvalidInput(ErrorCode::BadScale, "--pose: the quaternion is zero");
  if (!(n2 >= 0x1p-900 && n2 <= 0x1p900)) {
    // its squares leave double's range: scaled by a power of two first (exactly), the same direction
    const int e = std::ilogb(largest);
    n2 = 0;
    for (double& c : q) {
      c = std::ldexp(c, -e);
      n2 += c * c;
    }
  }
  const double n = std::sqrt(n2);
  Pose p;
  p.translation = t;
  if (n != 1.0) {
    for (double& c : q) c /= n;
  }
  p.rotation = q;
  p.transform = RigidTransform<double>::from_quaternion(q[0], q[1], q[2], q[3], t);
  return p;
}

Vec3<double> Pose::apply(const Vec3<double>& p) const { return transform.apply(p); }

}  // namespace sepax::cli
