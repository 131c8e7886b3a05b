// sepax/transform.hpp
//
// RigidTransform<T>: p -> R p + t, with R a 3x3 rotation and t a translation.
// Every product is written out with a fixed evaluation order (sepax::dot on
// rows), so exact number types never meet an Eigen reduction, and float runs
// are reproducible.  Where rotations come from:
//   * from_quaternion(w, x, y, z): any non-zero finite quaternion, normalised
//     in double (scaled by a power of two first where its squares leave
//     double's range); the matrix is computed in double and then converted to T.  For
//     float/double it is orthogonal up to rounding.  For exact T the entries
//     are the exact values of those rounded doubles, so R is NOT exactly
//     orthogonal (R^T R differs from I by ~1e-16): the moved shape is a very
//     slightly scaled/sheared copy.  Use the integer form when exactness matters.
//   * rotation_from_integer_quaternion<T>(w, x, y, z): R = M / (w^2+x^2+y^2+z^2)
//     with M the integer matrix of the (unnormalised) quaternion.  For exact T,
//     R is exactly orthogonal with determinant 1 (R^T R == I exactly), so
//     transformed() moves a shape rigidly and exactly.  For float/double the
//     entries are M/n rounded once.  Components must satisfy |c| <= 2^25 (so
//     every integer involved is exact in a double).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "number_traits.hpp"
#include "vec3.hpp"

namespace sepax {

/// q / |q| in double for a finite quaternion (w, x, y, z); false (q unchanged) when it is zero.  Where
/// its squares leave double's range (components beyond about 1e135 or below 1e-135) it is scaled by a
/// power of two first, exactly: the same direction.  |q|^2 is summed left to right.
inline bool normalize_quaternion(std::array<double, 4>& q) {
  double n2 = 0, largest = 0;
  for (const double c : q) {
    n2 += c * c;
    largest = std::max(largest, std::fabs(c));
  }
  if (!(largest > 0)) return false;
  if (!(n2 >= 0x1p-900 && n2 <= 0x1p900)) {
    const int e = std::ilogb(largest);
    n2 = 0;
    for (double& c : q) {
      c = std::ldexp(c, -e);
      n2 += c * c;
    }
  }
  const double n = std::sqrt(n2);
  for (double& c : q) c /= n;
  return true;
}

template <Number T>
struct RigidTransform {
  using Matrix3 = Eigen::Matrix<T, 3, 3>;

  Matrix3 rotation = identity_matrix();
  Vec3<T> translation = Vec3<T>(T(0), T(0), T(0));

  static Matrix3 identity_matrix() {
    Matrix3 m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = T(i == j ? 1 : 0);
    return m;
  }

  static RigidTransform identity() { return RigidTransform{}; }

  static RigidTransform translation_by(const Vec3<T>& t) {
    RigidTransform x;
    x.translation = t;
    return x;
  }

  Vec3<T> row(int i) const { return Vec3<T>(rotation(i, 0), rotation(i, 1), rotation(i, 2)); }
  Vec3<T> column(int j) const { return Vec3<T>(rotation(0, j), rotation(1, j), rotation(2, j)); }

  /// R p (no translation): for directions.
  Vec3<T> rotate(const Vec3<T>& p) const { return Vec3<T>(dot(row(0), p), dot(row(1), p), dot(row(2), p)); }

  /// R p + t.
  Vec3<T> apply(const Vec3<T>& p) const {
    const Vec3<T> r = rotate(p);
    return Vec3<T>(r[0] + translation[0], r[1] + translation[1], r[2] + translation[2]);
  }
  Vec3<T> operator()(const Vec3<T>& p) const { return apply(p); }

  /// (this * inner)(p) == this(inner(p)).
  RigidTransform compose(const RigidTransform& inner) const {
    RigidTransform out;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.rotation(i, j) = dot(row(i), inner.column(j));
    out.translation = apply(inner.translation);
    return out;
  }
  RigidTransform operator*(const RigidTransform& inner) const { return compose(inner); }

  /// The inverse, using R^{-1} = R^T: (R^T, -R^T t).  Exact for exact T when R
  /// is exactly orthogonal (rotation_from_integer_quaternion).
  RigidTransform inverse() const {
    RigidTransform out;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.rotation(i, j) = rotation(j, i);
    const Vec3<T> rt = out.rotate(translation);
    out.translation = Vec3<T>(-rt[0], -rt[1], -rt[2]);
    return out;
  }

  /// A rotation from a quaternion (normalised in double), then translation t.
  static RigidTransform from_quaternion(double w, double x, double y, double z,
                                        const Vec3<T>& t = Vec3<T>(T(0), T(0), T(0))) {
    if (!std::isfinite(w) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
      throw InvalidInput(ErrorCode::NonFinite, "quaternion has a non-finite component");
    }
    std::array<double, 4> q{w, x, y, z};
    if (!normalize_quaternion(q)) throw InvalidInput(ErrorCode::BadScale, "quaternion has zero length");
    w = q[0], x = q[1], y = q[2], z = q[3];
    const double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    RigidTransform out;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.rotation(i, j) = from_double<T>(m[i][j]);
    out.translation = t;
    return out;
  }
};

/// R = M / (w^2 + x^2 + y^2 + z^2): exactly orthogonal for exact T.
template <Number T>
Eigen::Matrix<T, 3, 3> rotation_from_integer_quaternion(long w, long x, long y, long z) {
  constexpr long limit = 1L << 25;
  for (long c : {w, x, y, z}) {
    if (c > limit || c < -limit) {
      throw InvalidInput(ErrorCode::BadScale, "integer quaternion component " + std::to_string(c) +
                                                  " exceeds 2^25 (its square would not be exact)");
    }
  }
  const long n = w * w + x * x + y * y + z * z;
  if (n == 0) throw InvalidInput(ErrorCode::BadScale, "integer quaternion is zero");
  const long m[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                        {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                        {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
  Eigen::Matrix<T, 3, 3> r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      // every |m_ij| and n is below 2^53: exact as doubles
      if constexpr (number_traits<T>::is_exact) {
        r(i, j) = T(from_double<T>(static_cast<double>(m[i][j])) / from_double<T>(static_cast<double>(n)));
      } else {
        r(i, j) = from_double<T>(static_cast<double>(m[i][j]) / static_cast<double>(n));
      }
    }
  }
  return r;
}

/// The rigid transform with rotation_from_integer_quaternion and translation t.
template <Number T>
RigidTransform<T> from_integer_quaternion(long w, long x, long y, long z,
                                          const Vec3<T>& t = Vec3<T>(T(0), T(0), T(0))) {
  RigidTransform<T> out;
  out.rotation = rotation_from_integer_quaternion<T>(w, x, y, z);
  out.translation = t;
  return out;
}

/// The polyhedron moved by xf: same topology and plane triples, vertices
/// x -> R x + t, planes recomputed from the moved vertices.  No re-validation:
/// a rigid motion preserves validity (up to rounding for float T).
template <Number T>
ConvexPolyhedron<T> transformed(const ConvexPolyhedron<T>& p, const RigidTransform<T>& xf) {
  std::vector<Vec3<T>> moved;
  moved.reserve(p.vertices().size());
  for (const auto& v : p.vertices()) moved.push_back(xf.apply(v));
  return p.with_vertices(std::move(moved));
}

}  // namespace sepax
