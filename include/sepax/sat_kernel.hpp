// sepax/sat_kernel.hpp
//
// The interface between the SAT algorithms and arithmetic.
//
// A SAT algorithm (brute force, Gauss map, traversal) is written once.  Every
// number it computes and every sign it decides goes through a *kernel*, built
// for one pair of shapes (A, B) in a common frame.  Kernels take features
// (indices into A and B), not numbers, so a kernel can recompute any decision
// exactly from the vertex coordinates: that is how the robust policy (robust/)
// makes float SATs decide exactly what exact arithmetic decides, without a
// second copy of any algorithm.
//
// A *policy* is a tag that picks the kernel for a number type:
//   policy::Plain   PlainKernel<T>: evaluate in T.  Exact for exact T; plain
//                   rounding arithmetic (with the named tolerances of
//                   tolerances.hpp) for float and double.
//   policy::Robust  (robust/sepax/robust/robust_kernel.hpp) float/double values,
//                   every decision by a filtered exact predicate.
// Usage:  sat::gauss_map(A, B)                  // Plain
//         sat::gauss_map<policy::Robust>(A, B)  // Robust (include robust/)
#pragma once

#include <concepts>
#include <limits>
#include <optional>
#include <string>

#include "convex_polyhedron.hpp"
#include "error.hpp"
#include "feature.hpp"
#include "sat_result.hpp"
#include "separation.hpp"

namespace sepax {

namespace policy {
struct Plain {};
}  // namespace policy

/// Result of a face query: the support vertex of the other shape along the
/// face's inward normal, and its height above the face plane.
template <class T>
struct FaceQuery {
  Separation<T> separation;
  int support_vertex = -1;
};

/// Signs of the four triple products of the Minkowski-face (arc intersection)
/// test of edge eA of A and edge eB of B.  With a, b the normals of eA's faces
/// (sides 0 and 1), c, d those of eB's, and the Gauss map of -B (so -c, -d):
///   cba = sign((-c).(b x a)) = sign(c . eA)     dba = sign(d . eA)
///   adc = sign(a.((-d) x (-c))) = -sign(a . eB) bdc = -sign(b . eB)
/// using the edge directions eA ~ a x b, eB ~ c x d, which stay defined for a
/// double-sided polygon (a = -b).  The arcs cross (eA x eB is a face normal of
/// A - B) iff cba*dba < 0, adc*bdc < 0 (they straddle each other's planes)
/// and cba*bdc > 0 (same hemisphere).  Signs, not products: products of float
/// triple products can underflow to zero.
struct ArcSigns {
  int cba = 0, dba = 0, adc = 0, bdc = 0;
  bool minkowski_face() const { return cba * dba < 0 && adc * bdc < 0 && cba * bdc > 0; }
};

/// What a SAT algorithm needs of a kernel.
template <class K>
concept SatKernel = requires(K k, const K ck, int i, int j, const Separation<typename K::FT>& s,
                             const Feature& f) {
  typename K::FT;
  { ck.a() } -> std::same_as<const ConvexPolyhedron<typename K::FT>&>;
  { ck.b() } -> std::same_as<const ConvexPolyhedron<typename K::FT>&>;
  // face i of A against B / face i of B against A (full support scan)
  { k.face_query_a(i) } -> std::same_as<FaceQuery<typename K::FT>>;
  { k.face_query_b(i) } -> std::same_as<FaceQuery<typename K::FT>>;
  // side axis of edge i of A / of edge i of B (both shapes flat only):
  // the polygon's in-plane outward edge normal, with a full support scan
  { k.side_query_a(i) } -> std::same_as<FaceQuery<typename K::FT>>;
  { k.side_query_b(i) } -> std::same_as<FaceQuery<typename K::FT>>;
  // O(1): height of vertex j of B above face i of A / of vertex j of A above
  // face i of B (for SATs that carry the support vertex, e.g. traversal)
  { k.face_separation_a(i, j) } -> std::same_as<Separation<typename K::FT>>;
  { k.face_separation_b(i, j) } -> std::same_as<Separation<typename K::FT>>;
  // Minkowski-face test of edge i of A and edge j of B
  { k.arc_signs(i, j) } -> std::same_as<ArcSigns>;
  // edges skipped as parallel
  { k.edges_parallel(i, j) } -> std::same_as<bool>;
  // O(1) separation of a Minkowski edge pair, axis oriented from A to B
  { k.edge_separation(i, j) } -> std::same_as<Separation<typename K::FT>>;
  // brute force: project both shapes on eA x eB; the separation if the two
  // edges support the shapes along the axis (one orientation or the other)
  { k.edge_separation_full(i, j) } -> std::same_as<std::optional<Separation<typename K::FT>>>;
  // exact comparison of two candidates' separations (-1, 0, +1)
  { k.compare(s, f, s, f) } -> std::same_as<int>;
  // sign of a candidate's separation
  { k.sign(s, f) } -> std::same_as<int>;
  // the axis of a feature, from A to B (unit when FT normalises)
  { k.axis(f) } -> std::same_as<Vec3<typename K::FT>>;
  // decisions the kernel had to make exactly (0 for Plain)
  { ck.exact_fallbacks() } -> std::convertible_to<std::int64_t>;
};

/// Optional kernel member (not part of SatKernel):
///   bool minkowski_face(int ea, int eb)
/// must return exactly arc_signs(ea, eb).minkowski_face(), the same decision
/// from the same values, but may stop early: most pairs of the Gauss map's
/// O(E_A E_B) loop are rejected by cba and dba alone (the arc of eA does not
/// straddle the plane of eB's arc), so a kernel decides sign(cba), sign(dba)
/// first and returns false unless they are strictly opposite, and only then
/// decides adc, bdc.  sat::gauss_map_with calls it when the kernel has it
/// (`requires { k.minkowski_face(ea, eb); }`), arc_signs otherwise.
/// arc_signs itself must keep returning all four signs (audits compare them).
template <class K>
concept HasMinkowskiFace = requires(K k, int i, int j) {
  { k.minkowski_face(i, j) } -> std::same_as<bool>;
};

/// Optional batched kernel member (not part of SatKernel):
///   int minkowski_faces(int ea, int lo, int hi, int* out)
/// writes to out, in increasing order, every eb in [lo, hi) for which
/// minkowski_face(ea, eb) (equivalently arc_signs(ea, eb).minkowski_face())
/// holds, and returns their number; hi - lo <= kMinkowskiBatch and lo is a
/// multiple of kMinkowskiBatch.  It lets a kernel test one edge of A against
/// many edges of B at once (SIMD over B's lane arrays).  sat::gauss_map_with
/// uses it when present, minkowski_face / arc_signs otherwise.
inline constexpr int kMinkowskiBatch = 256;

template <class K>
concept HasMinkowskiFaces = requires(const K k, int i, int* out) {
  { k.minkowski_faces(i, i, i, out) } -> std::same_as<int>;
};

/// Result of a face estimate (HasFaceEstimate): face i's separation without
/// its support vertex.  `separation` is within `error` of the exact
/// separation of the face, i.e. of the height of the other shape's exactly
/// deepest vertex, whichever vertex that is.
template <class T>
struct FaceEstimate {
  Separation<T> separation;
  double error = 0;
};

/// Optional kernel members (not part of SatKernel; RobustKernel has them):
///   FaceEstimate<FT> face_estimate_a(int i), face_estimate_b(int i)
///   double compare_width(double ex, double ey)
/// face_estimate_* is the face query's value without certifying which vertex
/// is the support vertex (a min-only scan: no second minimum, no argmin).
/// compare_width(ex, ey) is the filter width of the kernel's comparison of
/// two values with error bounds ex, ey (BestAxis's kBounded kernels: error_bound,
/// compare_bounded): when the difference of the two values, in double, is
/// beyond it, the exact comparison has that sign.  The shared face scan
/// (best_axis.hpp, scan_face_axes) then asks for the certified face_query_*
/// only for the faces whose estimate is not certainly below the best axis so
/// far: a face certainly below is never the answer, whatever its support
/// vertex (derivation at BestAxis::certainly_below).  Kernels without these
/// members (Plain, exact) take face_query_* for every face.
template <class K>
concept HasFaceEstimate = requires(const K k, int i, double e) {
  { k.face_estimate_a(i) } -> std::same_as<FaceEstimate<typename K::FT>>;
  { k.face_estimate_b(i) } -> std::same_as<FaceEstimate<typename K::FT>>;
  { k.compare_width(e, e) } -> std::same_as<double>;
};

/// Optional kernel members (not part of SatKernel; RobustKernel has them):
///   double error_bound(const Feature& f)
///   int compare_bounded(const Separation<FT>& x, const Feature& fx, double ex,
///                       const Separation<FT>& y, const Feature& fy, double ey)
///   double compare_width(double ex, double ey)
/// error_bound(f) bounds |value - exact value| of the separation the kernel
/// returns for feature f; compare_bounded is compare() given both bounds, so
/// a caller that keeps its best's bound compares a candidate with one filter
/// (BestAxis, the traversal's best); compare_width is that filter's width
/// (see HasFaceEstimate), from which the traversal derives its thresholds.
template <class K>
concept HasBoundedCompare = requires(const K& k, const Feature& f, const Separation<typename K::FT>& s,
                                     double e) {
  { k.error_bound(f) } -> std::same_as<double>;
  { k.compare_bounded(s, f, e, s, f, e) } -> std::same_as<int>;
  { k.compare_width(e, e) } -> std::same_as<double>;
};

/// Optional kernel members (not part of SatKernel; PlainKernel<float/double>
/// and RobustKernel have them): the filtered support comparison.
///   FT support_filter_a(), support_filter_b()
///   int support_sign_a(int f, int u, int v, FT d), support_sign_b(...)
/// Two vertices u, v of the other shape are compared below face f through
/// g = fl(n_f . x), the face's stored normal: d = fl(g_u - g_v) > W (the
/// filter) means u is higher, d < -W lower; otherwise (or d NaN) support_sign
/// gives the sign of height(f, u) - height(f, v).  RobustKernel: W bounds the
/// rounding of d and support_sign is exact.  PlainKernel: W = 0 and
/// support_sign is the sign of d, the comparison of the rounded heights.  The
/// traversal's climb and the face scans use it instead of a Separation and a
/// compare() per vertex.
template <class K>
concept HasSupportFilter = requires(const K& k, int i, typename K::FT d) {
  { k.support_filter_a() } -> std::same_as<typename K::FT>;
  { k.support_filter_b() } -> std::same_as<typename K::FT>;
  { k.support_sign_a(i, i, i, d) } -> std::same_as<int>;
  { k.support_sign_b(i, i, i, d) } -> std::same_as<int>;
};

/// Optional kernel constant (not part of SatKernel):
///   static constexpr bool kExactDecisions
/// true when every decision the kernel takes (signs, comparisons, support
/// vertices, parallel edges) is the exact one: RobustKernel, and PlainKernel
/// over an exact number type.  A kernel without it is taken to decide exactly
/// if and only if its number type is exact.  Algorithms that guard against
/// inconsistent rounded decisions (the traversal with a flat shape) ask it.
template <class K>
inline constexpr bool exact_decisions_v = [] {
  if constexpr (requires { K::kExactDecisions; }) {
    return static_cast<bool>(K::kExactDecisions);
  } else {
    return number_traits<typename K::FT>::is_exact;
  }
}();

/// Optional kernel member (not part of SatKernel):
///   bool edge_pair_below(int ea, int eb, FT best, double best_err)
/// true only if the edge pair's exact separation (edge_separation's, with its
/// orientation rule) is certainly below best - best_err; false when that is
/// not certain.  A caller that holds a best with value `best` and error bound
/// `best_err` (its feature's error_bound) may then skip the pair without
/// edges_parallel, edge_separation or a comparison: exact arithmetic would
/// reject it there.  RobustKernel<float> has it (robust_kernel.hpp, "(pair
/// prefilter)"); sat::gauss_map and sat::traversal use it
/// (BestAxis::pair_certainly_below).
template <class K>
concept HasEdgePairBelow = requires(const K k, int i, typename K::FT x, double e) {
  { k.edge_pair_below(i, i, x, e) } -> std::same_as<bool>;
};

/// Optional kernel member (not part of SatKernel; PlainKernel and
/// RobustKernel have it for float and double):
///   bool edge_pair_ruled_out(int ea, int eb)
/// true only when edge_separation_full(ea, eb) would return nothing (or the
/// edges are parallel): eA x eB is certainly no Minkowski face normal as the
/// kernel decides it.  false says nothing.  sat::brute_force asks it first,
/// so most pairs skip edges_parallel and edge_separation_full
/// (edge_pair_rule_out.hpp).
template <class K>
concept HasEdgePairRuledOut = requires(const K k, int i) {
  { k.edge_pair_ruled_out(i, i) } -> std::same_as<bool>;
};

/// Optional kernel member (not part of SatKernel; PlainKernel and
/// RobustKernel have it):
///   int compare_margin(const Separation<FT>& s, const Feature& f, double m)
/// the sign of (f's separation - m), m >= 0 finite: exact for exact T and
/// under policy::Robust (f's exact separation against the exact value of the
/// double m), the comparison of the values for plain float/double.
/// Kernels without it compare s with m converted to FT (sepax::compare).
template <class K>
concept HasCompareMargin = requires(const K k, const Separation<typename K::FT>& s, const Feature& f,
                                    double m) {
  { k.compare_margin(s, f, m) } -> std::same_as<int>;
};

/// Optional kernel member (not part of SatKernel; PlainKernel and
/// RobustKernel have it):
///   bool in_edge_wedge_a(int e, int x)
/// true when vertex x of B lies strictly inside the wedge of edge e of A: with
/// E = head - tail (parallel to n0 x n1, n_s the normal of edge_face(e, s))
/// and w = x - tail, (E x n0).w > 0 and (E x n1).w < 0, i.e. the component
/// of w orthogonal to E points strictly between n0 and n1.  Exact for exact
/// T and under policy::Robust (n_s the exact normal of the face's plane
/// triple); the signs of the T values for plain float/double.  The
/// traversal's arc bound uses it when the best is > 0: for x outside the open
/// wedge, max over the arc's unit normals n of n.w is max(n0.w, n1.w), the
/// two heights of x (docs/traversal.md, "The wedge bound").
template <class K>
concept HasEdgeWedge = requires(const K k, int i) {
  { k.in_edge_wedge_a(i, i) } -> std::same_as<bool>;
};

/// Throws InvalidInput (BadScale) unless opt.margin is finite and >= 0.
inline void check_options(const SatOptions& opt) {
  if (!(opt.margin >= 0.0) || !(opt.margin <= std::numeric_limits<double>::max())) {
    throw InvalidInput(ErrorCode::BadScale,
                       "SatOptions::margin must be finite and >= 0, got " + std::to_string(opt.margin));
  }
}

/// The early-out test every SAT applies to each candidate it has evaluated:
/// opt.early_out and the candidate's separation is > opt.margin (> 0 when
/// the margin is 0: k.sign, as before margins existed).
template <SatKernel K>
bool stops_early(const K& k, const Separation<typename K::FT>& s, const Feature& f, const SatOptions& opt) {
  if (!opt.early_out) return false;
  if (opt.margin == 0.0) return k.sign(s, f) > 0;
  if constexpr (HasCompareMargin<K>) {
    return k.compare_margin(s, f, opt.margin) > 0;
  } else {
    using T = typename K::FT;
    return compare(s, Separation<T>{from_double<T>(opt.margin), T(1)}) > 0;
  }
}

/// Maps (policy, T) to a kernel type.  Specialised by each policy.
template <class Policy, class T>
struct kernel_for;

template <class Policy, class T>
using kernel_t = typename kernel_for<Policy, T>::type;

}  // namespace sepax
