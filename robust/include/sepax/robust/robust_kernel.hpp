// sepax/robust/robust_kernel.hpp
//
// policy::Robust and RobustKernel<T> (T = float or double): the SAT kernel whose
// values are PlainKernel<T>'s and whose every decision is exact.  Each decision
// compares the plain value with an error bound (error_bounds.hpp) and falls
// back to an exact evaluation from the vertex coordinates (orientation.hpp,
// parallel.hpp, separation_compare.hpp) only when |value| <= bound.  The kernel
// is a stack of layers, each a class deriving from the one before:
//   robust_kernel_state.hpp      the shapes, the query's bounds, exact predicates;
//   robust_kernel_edge_axes.hpp  edge-pair axes and their orientation;
//   robust_kernel_values.hpp     error bounds of values, compare(), sign(), snap;
//   robust_kernel_faces.hpp      support vertices below faces (face queries);
//   robust_kernel_edges.hpp      arc signs, parallel edges, edge-pair values;
//   this header                  RobustKernel<T> itself (axis()) and
//                                kernel_for<policy::Robust, T>.
#pragma once

#include <sepax/robust/robust_kernel_edges.hpp>

namespace sepax {

namespace policy {
/// float/double values, every decision by a filtered exact predicate.
struct Robust {};
}  // namespace policy

/// The robust kernel.  Contract: for float/double polyhedra A, B, a SAT run
/// with policy::Robust makes exactly the decisions that PlainKernel<mpq_class>
/// makes on the exact images ConvexPolyhedron<mpq_class>::convert_from(A),
/// convert_from(B): the same support vertices (lowest index among the exactly
/// deepest), arc signs, parallel edges, edge-axis orientations, brute-force
/// support checks, comparisons and signs.  Hence the same feature, the same
/// overlap verdict and the same sign of separation.  The separation value and
/// the axis are the float/double numbers PlainKernel<T> computes for that
/// feature, except that a value whose sign is wrong (|value| within its error
/// bound, exact sign different) is replaced by 0 (exact zero) or by the exact
/// separation rounded to T: a returned separation always has the exact sign.
template <RobustFloat T>
class RobustKernel : public robust::detail::RobustEdgePairs<T> {
  using Base = robust::detail::RobustEdgePairs<T>;
  using Base::a_;
  using Base::b_;
  using Base::edge_axis;
  using Base::edge_sigma;
  using Base::exact_edge_axis;
  using Base::side_normal;
  using typename Base::EdgeAxis;

 public:
  using FT = T;
  /// Every decision is exact (sat_kernel.hpp, exact_decisions_v).
  static constexpr bool kExactDecisions = true;

  RobustKernel(const ConvexPolyhedron<T>& a, const ConvexPolyhedron<T>& b) : Base(a, b) {}

  /// Largest error |n - n*| of a reported edge-pair axis (axis()), unitless
  /// (a chord of the unit sphere, about the angle in radians).  Beyond it the
  /// T unit axis is replaced by the exact direction (a few units of roundoff).
  static constexpr double kReportedAxisError = 0x1p-10;

  /// The feature's unit axis, from A to B.  An edge pair's axis is the T
  /// unit cross product (PlainKernel's) when its bound delta (|n - n*|, n*
  /// the exact unit direction) is at most kReportedAxisError; otherwise (edges
  /// nearly parallel, where the T cross product may point anywhere) it is the
  /// exact cross product's direction, rounded.  Its orientation is the exact
  /// one either way (edge_sigma).
  Vec3<T> axis(const Feature& f) const {
    switch (f.type) {
      case FeatureType::FaceA:
        return a_.plane(f.a).normal;
      case FeatureType::FaceB:
        return Vec3<T>(-b_.plane(f.b).normal);
      case FeatureType::EdgePair: {
        EdgeAxis ax = edge_axis(f.a, f.b);
        const int sigma = edge_sigma(f.a, f.b);
        if (!(ax.delta <= kReportedAxisError)) ax = exact_edge_axis(f.a, f.b);
        return sigma < 0 ? Vec3<T>(-ax.n) : ax.n;
      }
      case FeatureType::SideA:
        return side_normal(a_, f.a);
      case FeatureType::SideB:
        return Vec3<T>(-side_normal(b_, f.b));
    }
    return Vec3<T>(T(0), T(0), T(0));
  }
};

template <RobustFloat T>
struct kernel_for<policy::Robust, T> {
  using type = RobustKernel<T>;
};

/// For exact number types every decision is already exact: Robust is Plain.
template <ExactNumber T>
struct kernel_for<policy::Robust, T> {
  using type = PlainKernel<T>;
};

}  // namespace sepax
