// sepax/posing.hpp
//
// Posing: one shape of a pair moved into the other's local frame, the input
// every posed query (prepared_shape.hpp) decides on:
//   1. X = relative_pose(pose_a, pose_b): B's frame in A's, in T;
//   2. check_rigid(X): a rotation within 1e-3 (float/double), det > 0 (exact);
//   3. the vertices of B' = posed(B, X), v' = X.apply(v), with B's bounds and
//      range checks (pose_vertices_into);
//   4. the planes, edge arrays, lanes and conditioning of B'
//      (ConvexPolyhedron::finish_rigid_image), or only the plane or edge an
//      early-out check reads (derive_rigid_part).
// A posed query returns exactly what the same SAT returns on (A, B').  The
// definition of that input, what the robust decisions are exact for, and why
// the staged steps change nothing: on posed() below.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "simd_ops.hpp"
#include "transform.hpp"

namespace sepax {

/// X = pose_a.inverse() * pose_b: B's local frame mapped into A's.  Spelled
/// out with the operations of inverse(), compose() and dot() in their order
/// (the same values for every T; the generic expression cost about 480
/// instructions a call in float): with R_a^T's rows the columns of R_a,
///   X.rotation(i, j) = dot(col_i(R_a), col_j(R_b)),
///   X.translation_i  = dot(col_i(R_a), t_b) + (-dot(col_i(R_a), t_a)).
template <Number T>
RigidTransform<T> relative_pose(const RigidTransform<T>& pose_a, const RigidTransform<T>& pose_b) {
  const auto& ra = pose_a.rotation;
  const auto& rb = pose_b.rotation;
  const Vec3<T>& ta = pose_a.translation;
  const Vec3<T>& tb = pose_b.translation;
  auto dot3 = [](const T& a0, const T& a1, const T& a2, const T& b0, const T& b1, const T& b2) {
    T s = a0 * b0;  // dot()'s order
    s = s + a1 * b1;
    s = s + a2 * b2;
    return s;
  };
  // built in place and returned as one aggregate: a default RigidTransform
  // would write the identity first
  typename RigidTransform<T>::Matrix3 rot;
  Vec3<T> tr;
  if constexpr (std::is_same_v<T, float> && simd::Lanes<float>::width == 4) {
    // Four lanes, lane i the dot products with col_i(R_a) (the rows of R_a
    // loaded as lanes): the same products and sums in the same order per
    // lane, so the same values (about 60 instructions instead of 200).
    using L = simd::Lanes<T>;  // (through T: without SSE2 this block is discarded unchecked)
    using V = typename L::V;
    V x0, x1, x2;  // lane i of xk: R_a(k, i)
    L::rows3x3(ra.data(), x0, x1, x2);
    auto dots = [&](T b0, T b1, T b2) {
      V s = L::mul(x0, L::set1(b0));
      s = L::add(s, L::mul(x1, L::set1(b1)));
      return L::add(s, L::mul(x2, L::set1(b2)));
    };
    const T* b = rb.data();  // column-major: b[k + 3 j] = R_b(k, j)
    L::store_cols3x3(rot.data(), dots(b[0], b[1], b[2]), dots(b[3], b[4], b[5]), dots(b[6], b[7], b[8]));
    const V back = L::neg(dots(ta[0], ta[1], ta[2]));
    L::store3(tr.data(), L::add(dots(tb[0], tb[1], tb[2]), back));
    return RigidTransform<T>{rot, tr};
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) rot(i, j) = dot3(ra(0, i), ra(1, i), ra(2, i), rb(0, j), rb(1, j), rb(2, j));
    const T back = -dot3(ra(0, i), ra(1, i), ra(2, i), ta[0], ta[1], ta[2]);
    tr[i] = T(dot3(ra(0, i), ra(1, i), ra(2, i), tb[0], tb[1], tb[2]) + back);
  }
  return RigidTransform<T>{rot, tr};
}

namespace detail {

/// An upper bound on |R^T R - I|_F for R = m (exact doubles), evaluated in
/// double.  Rounding of the evaluation (u_d = 2^-53): each entry of
/// G - I, G = R^T R (g_ij = m_0i m_0j + m_1i m_1j + m_2i m_2j, summed left
/// to right, then minus 1 on the diagonal), rounds at most 4 times relative
/// to |R|_F^2 + 1; a Frobenius norm over 9 entries then moves by at most 3x
/// the entry error; the sum of squares and the square root add a relative
/// 1e-15, inside the (1 + 1e-10).  G is symmetric bit for bit (g_ij and g_ji
/// are the same products summed in the same order), so the off-diagonal
/// squares are summed once and doubled (exact), and |R|_F^2 is the trace of
/// G (the same nine squares, summed in another order: a relative 1e-15).
/// Written out: with its loops over i, j and k (not unrolled) check_rigid
/// cost about 330 instructions a call, now about 150.
inline double rotation_defect(const double (&m)[3][3]) {
  auto g = [&m](int i, int j) {
    double s = m[0][i] * m[0][j];
    s += m[1][i] * m[1][j];
    s += m[2][i] * m[2][j];
    return s;
  };
  const double g00 = g(0, 0), g11 = g(1, 1), g22 = g(2, 2);
  const double g01 = g(0, 1), g02 = g(0, 2), g12 = g(1, 2);
  const double d0 = g00 - 1.0, d1 = g11 - 1.0, d2 = g22 - 1.0;
  const double o2 = (d0 * d0 + d1 * d1 + d2 * d2) + 2.0 * (g01 * g01 + g02 * g02 + g12 * g12);
  const double f2 = g00 + g11 + g22;
  const double ud = 0x1p-53;
  const double fro = std::sqrt(f2) * (1 + 1e-10);
  return std::sqrt(o2) * (1 + 1e-10) + 13 * ud * (fro * fro + 1);
}

/// m = x's rotation in double (float/double entries, taken exactly), written
/// out (Eigen's storage is column-major: data()[i + 3 j] = R(i, j)).
template <Number T>
void rotation_in_double(const RigidTransform<T>& x, double (&m)[3][3]) {
  static_assert(std::is_floating_point_v<T>);
  const T* r = x.rotation.data();
  auto at = [r](int k) { return static_cast<double>(r[k]); };
  m[0][0] = at(0), m[0][1] = at(3), m[0][2] = at(6);
  m[1][0] = at(1), m[1][1] = at(4), m[1][2] = at(7);
  m[2][0] = at(2), m[2][1] = at(5), m[2][2] = at(8);
}

/// The same for x's rotation (float/double, its entries taken exactly).
template <Number T>
double rotation_defect(const RigidTransform<T>& x) {
  double m[3][3];
  rotation_in_double(x, m);
  return rotation_defect(m);
}

/// check_rigid's refusal of a float/double rotation (out of line: the
/// message's formatting stays off the query path).
[[noreturn]] [[gnu::cold]] [[gnu::noinline]] inline void refuse_rotation(double omega, double det) {
  throw InvalidInput(ErrorCode::BadScale, "pose: the rotation is not a rotation (|R^T R - I| about " +
                                              std::to_string(omega) + ", det = " + std::to_string(det) +
                                              "; sepax needs an orthonormal matrix with det +1 within 1e-3)");
}

/// x.apply on simd::Lanes<T> vectors of coordinates (float/double), in
/// place: per lane apply()'s operations in its order,
/// fl(fl(fl(fl(r_i0 v_0 + r_i1 v_1) + r_i2 v_2) + t_i), so a lane gives
/// bit for bit what x.apply gives (the same expression wherever it is used,
/// so contracted alike under FMA contraction).  The lane form of every
/// posed vertex (pose_vertices_into, and views that pose a shape in part).
template <class T>
struct PoseLanes {
  using L = simd::Lanes<T>;
  using V = typename L::V;
  V r[3][3], t[3];
  explicit PoseLanes(const RigidTransform<T>& x) {
    const T* m = x.rotation.data();  // column-major: m[i + 3 j] = R(i, j)
    r[0][0] = L::set1(m[0]), r[1][0] = L::set1(m[1]), r[2][0] = L::set1(m[2]);
    r[0][1] = L::set1(m[3]), r[1][1] = L::set1(m[4]), r[2][1] = L::set1(m[5]);
    r[0][2] = L::set1(m[6]), r[1][2] = L::set1(m[7]), r[2][2] = L::set1(m[8]);
    t[0] = L::set1(x.translation[0]), t[1] = L::set1(x.translation[1]), t[2] = L::set1(x.translation[2]);
  }
  // written out: the loop over the rows was not unrolled (about 12
  // instructions a group of lanes)
  SEPAX_SIMD_INLINE V row(int i, V a, V b, V c) const {
    return L::add(L::add(L::add(L::mul(r[i][0], a), L::mul(r[i][1], b)), L::mul(r[i][2], c)), t[i]);
  }
  SEPAX_SIMD_INLINE void operator()(V& a, V& b, V& c) const {
    const V o0 = row(0, a, b, c), o1 = row(1, a, b, c), o2 = row(2, a, b, c);
    a = o0, b = o1, c = o2;
  }
};

/// x.apply on one point at a time: for float with SSE2 the three
/// coordinates in the lanes of one register, lane i computing apply()'s
/// operations in its order, fl(fl(fl(fl(r_i0 p_0 + r_i1 p_1) + r_i2 p_2) +
/// t_i)), from x's columns (the same expression as PoseLanes, contracted
/// alike under FMA contraction); bit for bit x.apply(p).  Other T: x.apply.
template <class T>
struct PointMap {
  const RigidTransform<T>& x;
  explicit PointMap(const RigidTransform<T>& xf) : x(xf) {}
  Vec3<T> operator()(const Vec3<T>& p) const { return x.apply(p); }
};

#if defined(SEPAX_SIMD_SSE2)
template <>
struct PointMap<float> {
  using L = simd::Lanes<float>;
  using V = L::V;
  V c0, c1, c2, t;  // lane i of cj: R(i, j); of t: t_i (lane 3 zero)
  explicit PointMap(const RigidTransform<float>& x) {
    const float* m = x.rotation.data();  // column-major: m[i + 3 j] = R(i, j)
    c0 = L::load3(m), c1 = L::load3(m + 3), c2 = L::load3(m + 6);
    t = L::load3(x.translation.data());
  }
  Vec3<float> operator()(const Vec3<float>& p) const {
    V s = L::mul(c0, L::set1(p[0]));
    s = L::add(s, L::mul(c1, L::set1(p[1])));
    s = L::add(L::add(s, L::mul(c2, L::set1(p[2]))), t);
    Vec3<float> out;
    L::store3(out.data(), s);
    return out;
  }
};
#endif

/// Poses must be rigid.  Throws InvalidInput (BadScale) unless x's linear
/// part R is a rotation: for float/double |R^T R - I|_F <= 1e-3 (with the
/// rounding of its double evaluation bounded below) and det R > 0 (a
/// reflection or a scale would turn B inside out or break every bound); exact
/// T requires det R > 0, decided exactly, and is exact for any such R.
template <Number T>
void check_rigid(const RigidTransform<T>& x) {
  if constexpr (number_traits<T>::is_exact) {
    const auto& r = x.rotation;
    const T det = r(0, 0) * (r(1, 1) * r(2, 2) - r(1, 2) * r(2, 1)) -
                  r(0, 1) * (r(1, 0) * r(2, 2) - r(1, 2) * r(2, 0)) +
                  r(0, 2) * (r(1, 0) * r(2, 1) - r(1, 1) * r(2, 0));
    if (!(det > T(0))) {
      throw InvalidInput(ErrorCode::BadScale,
                         "pose: the rotation's determinant is not positive (a reflection or "
                         "a degenerate matrix would turn the shape inside out)");
    }
  } else {
    double m[3][3];
    rotation_in_double(x, m);
    // Within omega <= 1e-3, |det M| >= (1 - 1e-3)^(3/2), far beyond the
    // rounding of its double evaluation, so det's computed sign is exact.
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    const double omega = rotation_defect(m);
    if (!(omega <= 1e-3) || !(det > 0)) [[unlikely]]
      refuse_rotation(omega, det);
  }
}

/// Step 1 of posed(src, x) (the header's formula, "Staged posing"): out =
/// the partial image with src's topology (shared, not copied) and
/// the vertices x.apply(v), bounds and range checks
/// (ConvexPolyhedron::assign_rigid_vertices), reusing out's arrays.  One
/// out-of-line body, so that every caller (the posed queries, their checks
/// and posed()) computes the vertices of B' with the same instructions,
/// contracted or not.
template <Number T>
[[gnu::noinline]] void pose_vertices_into(ConvexPolyhedron<T>& out, const ConvexPolyhedron<T>& src,
                                          const RigidTransform<T>& x) {
  check_rigid(x);
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
    // x.apply a few vertices at a time (simd_ops.hpp)
    const PoseLanes<T> lanes(x);
    out.assign_rigid_vertices(
        src, [&](const Vec3<T>& v) { return x.apply(v); }, lanes);
  } else {
    out.assign_rigid_vertices(src, [&](const Vec3<T>& v) { return x.apply(v); });
  }
}

/// out = posed(src, x): pose_vertices_into, then every plane, edge array and
/// lane (ConvexPolyhedron::finish_rigid_image).
template <Number T>
void pose_into(ConvexPolyhedron<T>& out, const ConvexPolyhedron<T>& src, const RigidTransform<T>& x) {
  pose_vertices_into(out, src, x);
  out.finish_rigid_image();
}

}  // namespace detail

/// B' = B moved by x, as the posed queries compute it (see the header
/// comment): the pre-posed reference of a posed query, posed(B,
/// relative_pose(pose_a, pose_b)).  Allocates (a new polyhedron); the posed
/// queries use per-thread scratch instead.
/// Definition (the input the posed queries are exact for).  Shapes A and B are
/// given in their local frames with poses pose_a, pose_b (world = R local + t,
/// transform.hpp).  A posed query works in A's frame:
///
///   X  = relative_pose(pose_a, pose_b) = pose_a.inverse() * pose_b,
///        computed in T exactly as transform.hpp evaluates inverse() and
///        compose() (for float/double: rounded, one fixed evaluation order);
///   B' = posed(B, X): the polyhedron with B's topology and plane triples and
///        the vertices  v' = X.apply(v)  (fl(fl(row_i . v) + t_i) for
///        float/double, transform.hpp's apply()), its planes recomputed from
///        v' as every ConvexPolyhedron computes them: bit for bit
///        transformed(B, X), built in reused scratch without allocating.
///
/// A posed query on (A, pose_a, B, pose_b) returns exactly what the same SAT
/// returns on (A, posed(B, X)) - same feature, verdict, separation and stats,
/// bit for bit - with the axis (and manifold points) mapped to world
/// coordinates by pose_a.  Under policy::Robust its decisions are the exact
/// decisions on that input (the mpq SAT on the exact images of A and B').
/// Exact T with an exactly orthogonal rotation (rotation_from_integer_quaternion):
/// inverse, compose and apply are exact, so B' is exactly B moved rigidly and
/// the posed query is the exact answer for the poses given.
///
/// Staged posing.  The vertices of B' come first (pose_vertices_into: the
/// formula above, with B's bounds, centroid and range checks); planes, edge
/// arrays, lanes and normal conditioning follow (ConvexPolyhedron::
/// finish_rigid_image), bit for bit as in one pass.  A posed query with
/// early_out that can prove a separation beyond the margin from one feature
/// (the cached feature of a SatCache, posed_queries.hpp) derives only the
/// plane or edge of B' that feature reads (ConvexPolyhedron::
/// derive_rigid_part: the same formulas; the robust kernel's normal bound
/// for B is then the conditioning of those planes alone, a bound for every
/// plane it reads) and decides on the same vertices of B' with the same
/// kernel predicates: the same decision as on the full B', so the input it is
/// exact for is the one defined above.  Only when the check fails is the rest
/// of B' derived.
template <Number T>
ConvexPolyhedron<T> posed(const ConvexPolyhedron<T>& b, const RigidTransform<T>& x) {
  ConvexPolyhedron<T> out;
  detail::pose_into(out, b, x);
  return out;
}

}  // namespace sepax
