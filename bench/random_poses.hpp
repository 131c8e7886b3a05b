// Random numbers and rigid poses of the benchmark: a fixed-seed splitmix64
// (the same shapes and poses on every platform and standard library) and
// poses held in double, from which every row's input is derived.
#pragma once

#include <cmath>
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <sepax/vec3.hpp>

namespace bench {

using V3d = sepax::Vec3<double>;
using V3f = sepax::Vec3<float>;

inline V3d to_d(const V3f& v) { return V3d(double(v[0]), double(v[1]), double(v[2])); }
inline V3f to_f(const V3d& v) {
  return V3f(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

// Fixed-seed, implementation-independent uniform doubles.
struct Rng {
  std::uint64_t s;
  explicit Rng(std::uint64_t seed) : s(seed) {}
  std::uint64_t next() {  // splitmix64
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int below(int m) { return static_cast<int>(next() % static_cast<std::uint64_t>(m)); }
  V3d unit() {  // uniform on the sphere, by rejection
    for (;;) {
      V3d p(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const double n2 = p.squaredNorm();
      if (n2 > 1e-6 && n2 <= 1.0) return p / std::sqrt(n2);
    }
  }
  V3d in_ball(double radius) {  // uniform in the ball
    for (;;) {
      V3d t(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      if (t.squaredNorm() <= 1) return radius * t;
    }
  }
  Eigen::Matrix3d rotation() {  // uniform random rotation
    Eigen::Quaterniond q;
    do {
      q = Eigen::Quaterniond(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    } while (q.squaredNorm() < 1e-3 || q.squaredNorm() > 1);
    q.normalize();
    return q.toRotationMatrix();
  }
};

// x -> r x + t, in double.
struct Pose {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  V3d t = V3d::Zero();
  V3d apply(const V3d& v) const { return r * v + t; }
  Pose operator*(const Pose& inner) const { return Pose{r * inner.r, r * inner.t + t}; }
};

// A random rotation; the centre uniform in the ball of radius dmax (dmin <= 0)
// or at a distance uniform in [dmin, dmax] in a uniform direction.
inline Pose random_pose(Rng& rng, double dmin, double dmax) {
  Pose p;
  p.r = rng.rotation();
  if (dmin <= 0) {
    p.t = rng.in_ball(dmax);
  } else {
    const V3d dir = rng.unit();  // drawn before the distance: a fixed order of draws
    p.t = dir * rng.uniform(dmin, dmax);
  }
  return p;
}

}  // namespace bench
