// sepax/fuzz/check.hpp
//
// The checking core shared by every driver (standalone campaign, corpus replay,
// libFuzzer target, ctest): check_case runs one FuzzCase through every
// configuration and classifies every disagreement with the exact reference.
//   1. configurations: float/double plain and robust, mpq, gmpq, epeck; SATs
//      brute_force, gauss_map, traversal; the reference is mpq + gauss_map;
//   2. comparisons (the report's keys): arc_sign, minkowski_face, overlap,
//      feature, separation, exact, manifold (check_manifold.hpp), margin,
//      posed / posed_exact / posed_rational / warm (check_posed.hpp);
//   3. every difference classified (Classification): agree, exact_zero,
//      explained, tie, unexplained (a bug: a reproducer and a non-zero exit),
//      nonconvex.
// Robust configurations decide every sign exactly: for them any difference in
// a sign, verdict or feature is unexplained.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/fuzz/case.hpp>
#include <sepax/sat_kernel.hpp>

namespace sepax::fuzz {

/// Classes of a comparison:
///   agree        identical (separation: the float value equals the exact one)
///   exact_zero   differs, and the exact quantity is exactly zero
///   explained    differs, and the exact value lies within the forward error
///                bound of the float computation (error_bounds.hpp); or a
///                plain run missed an exact winning edge pair that lies inside
///                its parallel-edge skip (error_bounds.hpp (6), parallel_band in
///                classify.hpp) and its choice reaches the optimum over the
///                candidates it certainly measured, within the bounds
///   tie          different features whose exact separations are equal, or
///                equal within the two features' bounds (both decided exactly)
///   unexplained  anything else: a bug (or a bound that is wrong) -- the
///                drivers write a reproducer and exit non-zero
///   nonconvex    two *different* SATs disagree in exact arithmetic on an input
///                whose exact image is not exactly convex (a float polyhedron
///                accepted within the planarity/convexity tolerances, e.g. the
///                "perturbed" family).  Exactness across SATs is only claimed
///                for exactly convex inputs: the Gauss map and the traversal
///                measure an edge pair in O(1) assuming its edges support the
///                shapes, which a vertex beyond a face plane can violate, while
///                the brute force projects every vertex.  On such inputs every
///                float and robust SAT is still checked strictly against the
///                exact run of the *same* SAT; only cross-SAT differences get
///                this class, and they are counted and reported, not hidden.
/// Robust configurations decide every sign exactly, so for them any difference
/// in a sign, verdict or feature is unexplained; only their separation *values*
/// may be "explained" (they are float numbers).
enum class Classification : int {
  agree = 0,
  exact_zero = 1,
  explained = 2,
  tie = 3,
  unexplained = 4,
  nonconvex = 5
};
inline constexpr int kClassificationCount = 6;
const char* classification_name(Classification k);

struct Counts {
  std::array<std::int64_t, kClassificationCount> n{};
  void add(Classification k, std::int64_t times = 1) { n[static_cast<std::size_t>(k)] += times; }
  std::int64_t operator[](Classification k) const { return n[static_cast<std::size_t>(k)]; }
  std::int64_t total() const {
    std::int64_t t = 0;
    for (auto x : n) t += x;
    return t;
  }
  Counts& operator+=(const Counts& o) {
    for (std::size_t i = 0; i < n.size(); ++i) n[i] += o.n[i];
    return *this;
  }
};

struct Finding {
  std::string comparison;  // arc_sign, minkowski_face, overlap, feature, separation, exact
  std::string config;      // float_plain, ..., epeck
  std::string sat;         // brute_force, gauss_map, traversal, or "kernel" for arc tests
  std::string detail;      // human-readable: what differed, exact vs float values, the bound
};

struct CaseReport {
  bool valid = false;  // false: the shapes were rejected (InvalidInput)
  std::string reject_reason;
  std::map<std::string, Counts> by_comparison;
  std::map<std::string, Counts> by_config;  // "comparison/config"
  std::vector<Finding> unexplained;         // at most a few per comparison
  std::int64_t unexplained_count = 0;
  std::vector<std::string> configs_run;  // "config/sat"
  /// Comparisons not made because a run was above a size budget
  /// (CheckOptions), as "comparison/config/sat" -> count.  Reported, never
  /// silently dropped.
  std::map<std::string, std::int64_t> skipped;
  std::map<std::string, Counts> details;  // sub-comparisons, e.g. "manifold.points" (check_manifold.hpp)
  std::map<std::string, double> maxima;   // largest error/bound ratios, e.g. "manifold.depth"
};

struct CheckOptions {
  /// Exact brute force / gmpq runs only when E_A*E_B*(V_A+V_B) is at most this
  /// (they are O(n^3) in rational arithmetic).
  std::int64_t exact_brute_budget = 100'000;
  /// Exact Gauss maps other than the mpq reference (epeck) only when E_A*E_B
  /// is at most this; gmpq only when E_A*E_B is at most gmpq_pair_budget.
  std::int64_t exact_gauss_pair_budget = 60'000;
  std::int64_t gmpq_pair_budget = 10'000;
  /// Float/double brute force only when E_A*E_B*(V_A+V_B) is at most this.
  std::int64_t float_brute_budget = 20'000'000;
  /// Keep at most this many Finding records per comparison (all are counted).
  int max_findings = 8;
  /// Compare float and exact contact manifolds (check_manifold.hpp).
  bool manifolds = true;
  /// Speculative margins (SatOptions::margin with early_out): the "margin"
  /// comparison (check.cpp, check_margins).
  bool margins = true;
  /// Posed queries on prepared shapes and warm (cached) coherent sequences:
  /// the "posed", "posed_exact", "posed_rational" and "warm" comparisons
  /// (check_posed.hpp).
  bool posed = true;
  /// The exact references of posed queries (mpq SATs on the posed input, and
  /// exact rational poses) only when E_A*E_B is at most this.
  std::int64_t posed_exact_pair_budget = 2'500;
  /// Checks the checker: float_robust's Gauss map reports the opposite
  /// overlap verdict, a fault the robust policy's claim of exact decisions
  /// makes unexplained in every valid case (`--inject-fault` of `sepax fuzz
  /// --replay` and `sepax audit`: their exit status 1 and the reproducer path,
  /// end to end).  Never set in a real campaign.
  bool inject_fault = false;
};

/// The four arc-test signs of every edge pair (index ea * E_B + eb), exactly,
/// from the float coordinates scaled to integers (the fuzzer's reference for
/// the arc_sign comparison; equal to PlainKernel<mpq>::arc_signs).
std::vector<ArcSigns> exact_arc_signs(const ConvexPolyhedron<float>& A, const ConvexPolyhedron<float>& B);

/// The support vertex of every face of A over B's vertices (index f), exactly,
/// in integers as exact_arc_signs: the vertex PlainKernel<mpq>::face_query_a
/// reports (the lowest index of least height), without rational arithmetic.
std::vector<int> exact_face_supports(const ConvexPolyhedron<float>& A, const ConvexPolyhedron<float>& B);

/// Is the exact image of p exactly convex: every face's vertices exactly on
/// the plane through its plane triple, every vertex on or below every face
/// plane?  Decided exactly (a semi-static filter, rationals where it cannot
/// decide).  The cross-SAT exactness claim needs it (Classification::nonconvex).
bool exactly_convex(const ConvexPolyhedron<float>& p);

/// Robust policy and traversal SAT availability (compiled in or not).
bool has_robust_policy();
bool has_traversal_sat();

/// Configurations (identical inputs, see case.hpp):
///   float_plain, double_plain     PlainKernel<float/double>
///   float_robust, double_robust   policy::Robust (when robust_kernel.hpp exists)
///   mpq, gmpq, epeck              PlainKernel over exact types
/// SATs: brute_force, gauss_map, traversal (when sat_traversal.hpp exists).
/// The reference is mpq + gauss_map.
///
/// Comparisons (the keys of the report):
///   arc_sign        each of the four triple-product signs of the arc test, for
///                   every edge pair (kernel level, so shared by all SATs)
///   minkowski_face  the arc test's verdict for every edge pair
///   overlap         the SAT's overlap verdict
///   feature         the minimum-penetration (maximum-separation) feature
///   separation      the reported separation against the exact optimum
///   exact           exact configurations and exact SATs among themselves
///   manifold        float against exact contact manifolds (check_manifold.hpp)
///   margin          early exits at a speculative margin (SatOptions::margin)
///   posed, posed_exact, posed_rational, warm
///                   posed queries on prepared shapes and cached coherent
///                   sequences (check_posed.hpp)
CaseReport check_case(const FuzzCase& c, const CheckOptions& opt = {});

/// check_case, with any exception other than the rejection of invalid shapes
/// (e.g. a library logic_error) turned into an "internal_error" finding.
CaseReport check_case_guarded(const FuzzCase& c, const CheckOptions& opt = {});

}  // namespace sepax::fuzz
