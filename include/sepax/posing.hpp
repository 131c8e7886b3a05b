// sepax/posing.hpp
//
// Posing: one shape of a pair moved into the other's local frame, the input
// every posed query (prepared_shape.hpp) decides on.
//
// Definition (the input the posed queries are exact for).  Shapes A and B are
// given in their local frames with poses pose_a, pose_b (world = R local + t,
// transform.hpp).  A posed query works in A's frame:
//
//   X  = relative_pose(pose_a, pose_b) = pose_a.inverse() * pose_b,
//        computed in T exactly as transform.hpp evaluates inverse() and
//        compose() (for float/double: rounded, one fixed evaluation order);
//   B' = posed(B, X): the polyhedron with B's topology and plane triples and
//        the vertices  v' = X.apply(v)  (fl(fl(row_i . v) + t_i) for
//        float/double, transform.hpp's apply()), its planes recomputed from
//        v' as every ConvexPolyhedron computes them: bit for bit
//        transformed(B, X), built in reused scratch without allocating.
//
// A posed query on (A, pose_a, B, pose_b) returns exactly what the same SAT
// returns on (A, posed(B, X)) - same feature, verdict, separation and stats,
// bit for bit - with the axis (and manifold points) mapped to world
// coordinates by pose_a.  Under policy::Robust its decisions are the exact
// decisions on that input (the mpq SAT on the exact images of A and B').
// Exact T with an exactly orthogonal rotation (rotation_from_integer_quaternion):
// inverse, compose and apply are exact, so B' is exactly B moved rigidly and
// the posed query is the exact answer for the poses given.
//
// (ConvexPolyhedron::RigidImageTerms and RobustKernel's "Rotated normals"
// bound support storing rotated normals instead; posing does not use them:
// measured, the rounding of the moved vertices tilts the small faces of fine
// meshes by ~u |x| / edge, which widened the filters until exact fallbacks
// grew ~1000x at N = 256.)
//
// Poses must be rigid: for float/double the query throws InvalidInput
// (BadScale) when |M^T M - I| > 1e-3 or det M <= 0 (a reflection or a scale,
// which would turn B inside out or break every bound); exact T requires
// det M > 0 (decided exactly) and is exact for any such linear part.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "transform.hpp"

namespace sepax {

/// X = pose_a.inverse() * pose_b: B's local frame mapped into A's.
template <Number T>
RigidTransform<T> relative_pose(const RigidTransform<T>& pose_a, const RigidTransform<T>& pose_b) {
  return pose_a.inverse() * pose_b;
}

namespace detail {

/// Throws unless x's linear part is a rotation (see the header comment);
/// for float/double returns the rigid-image terms of B (local data: its
/// normal_conditioning, max |coordinate|, pose_conditioning) under x.
template <Number T>
typename ConvexPolyhedron<T>::RigidImageTerms pose_terms(const RigidTransform<T>& x, double local_conditioning,
                                                double local_max_abs,
                                                const typename ConvexPolyhedron<T>::PoseConditioning& pc) {
  typename ConvexPolyhedron<T>::RigidImageTerms terms;
  const auto& r = x.rotation;
  if constexpr (number_traits<T>::is_exact) {
    const T det = r(0, 0) * (r(1, 1) * r(2, 2) - r(1, 2) * r(2, 1)) - r(0, 1) * (r(1, 0) * r(2, 2) - r(1, 2) * r(2, 0)) +
                  r(0, 2) * (r(1, 0) * r(2, 1) - r(1, 1) * r(2, 0));
    if (!(det > T(0))) {
      throw InvalidInput(ErrorCode::BadScale, "pose: the rotation's determinant is not positive (a reflection or "
                                              "a degenerate matrix would turn the shape inside out)");
    }
    return terms;
  } else {
    double m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = static_cast<double>(r(i, j));
    // cofactor matrix: cof(M)_ij = (row_{i+1} x row_{i+2})_j
    double cof[3][3];
    for (int i = 0; i < 3; ++i) {
      const double* a = m[(i + 1) % 3];
      const double* b = m[(i + 2) % 3];
      cof[i][0] = a[1] * b[2] - a[2] * b[1];
      cof[i][1] = a[2] * b[0] - a[0] * b[2];
      cof[i][2] = a[0] * b[1] - a[1] * b[0];
    }
    double f2 = 0, k2 = 0, o2 = 0, rinf = 0, det = 0;
    for (int i = 0; i < 3; ++i) {
      double row = 0;
      for (int j = 0; j < 3; ++j) {
        f2 += m[i][j] * m[i][j];
        k2 += (cof[i][j] - m[i][j]) * (cof[i][j] - m[i][j]);
        double g = 0;
        for (int k = 0; k < 3; ++k) g += m[k][i] * m[k][j];
        g -= i == j ? 1.0 : 0.0;
        o2 += g * g;
        row += std::abs(m[i][j]);
      }
      rinf = std::max(rinf, row);
      det += m[0][i] * cof[0][i];
    }
    // Rounding of the double evaluation (u_d = 2^-53): each entry of
    // cof(M) - M rounds at most 3 times relative to |M|_F^2 + |M|_F, each of
    // M^T M - I 4 times relative to |M|_F^2 + 1; a Frobenius norm over 9
    // entries then moves by at most 3x the entry error; the sums of squares
    // and square roots add a relative 1e-15, inside the (1 + 1e-10).
    const double ud = 0x1p-53;
    const double fro = std::sqrt(f2) * (1 + 1e-10);
    const double omega = std::sqrt(o2) * (1 + 1e-10) + 13 * ud * (fro * fro + 1);
    if (!(omega <= 1e-3) || !(det > 0)) {
      throw InvalidInput(ErrorCode::BadScale, "pose: the rotation is not a rotation (|R^T R - I| = " +
                                                  std::to_string(std::sqrt(o2)) + ", det = " + std::to_string(det) +
                                                  "; sepax needs an orthonormal matrix with det +1 within 1e-3)");
    }
    constexpr double u = number_traits<T>::unit_roundoff;
    constexpr double g4 = 4 * u / (1 - 4 * u);
    double tinf = 0;
    for (int i = 0; i < 3; ++i) tinf = std::max(tinf, std::abs(static_cast<double>(x.translation[i])));
    const double eps = std::sqrt(3.0) * g4 * (rinf * local_max_abs + tinf) * (1 + 1e-10);
    terms.rotated = true;
    terms.local_conditioning = local_conditioning;
    terms.scale = fro;
    terms.kappa = std::sqrt(k2) * (1 + 1e-10) + 10 * ud * (fro * fro + fro);
    terms.omega = omega;
    terms.vertex_term = (4 * eps * fro * pc.edge_ratio + 8 * eps * eps * pc.inv_normal) * (1 + 1e-10);
    if (!std::isfinite(terms.vertex_term)) terms.vertex_term = std::numeric_limits<double>::infinity();
    return terms;
  }
}

/// out = posed(src, x) (the header's formula), reusing out's arrays; the
/// topology is copied unless same_topology.  One out-of-line body, so that
/// every caller (the posed queries and posed()) computes B' with the same
/// instructions, contracted or not.
template <Number T>
[[gnu::noinline]] void pose_into(ConvexPolyhedron<T>& out, const ConvexPolyhedron<T>& src, bool same_topology,
                                 const RigidTransform<T>& x,
                                 const typename ConvexPolyhedron<T>::RigidImageTerms& terms) {
  out.assign_rigid_image(
      src, same_topology, [&](const Vec3<T>& v) { return x.apply(v); }, [&](const Vec3<T>& n) { return x.rotate(n); },
      terms);
}

}  // namespace detail

/// B' = B moved by x, as the posed queries compute it (see the header
/// comment): the pre-posed reference of a posed query, posed(B,
/// relative_pose(pose_a, pose_b)).  Allocates (a new polyhedron); the posed
/// queries use per-thread scratch instead.
template <Number T>
ConvexPolyhedron<T> posed(const ConvexPolyhedron<T>& b, const RigidTransform<T>& x) {
  ConvexPolyhedron<T> out;
  const auto terms = detail::pose_terms(x, b.normal_conditioning(), b.max_abs_coordinate(), b.pose_conditioning());
  detail::pose_into(out, b, false, x, terms);
  return out;
}

}  // namespace sepax
