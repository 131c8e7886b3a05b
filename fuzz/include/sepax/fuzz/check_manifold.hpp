// sepax/fuzz/check_manifold.hpp
//
// The contact-manifold comparison of the checking core (check.hpp): for every
// float configuration whose Gauss-map SAT feature equals the exact one,
// check_manifolds builds the contact manifold in that configuration and
// exactly (mpq; Gmpq as a second exact type), and compares
//   1. the incident face;
//   2. the clipped points before the reduction, matched by feature id;
//   3. the depth and position of every matched point against a derived
//      forward error bound (check_manifold.cpp);
//   4. the points after the reduction to at most 4;
// and classifies each (case, configuration) by the worst of its aspects
// (check_manifold_float).  Exact types among themselves must be identical.
#pragma once

#include <iosfwd>
#include <optional>

#include <gmpxx.h>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/fuzz/check.hpp>
#include <sepax/robust/number_types.hpp>
#include <sepax/sat_result.hpp>

namespace sepax::fuzz {

/// The Gauss-map results of a case's configurations that the checking core
/// has already computed (check.cpp runs them for the SAT comparisons): the
/// manifold check builds its manifolds from these instead of running the same
/// deterministic queries on the same inputs again.  One that is missing is run.
/// The double and Gmpq images of the case's shapes those results were computed
/// on (ConvexPolyhedron<T>::convert_from of the float shapes, converted once
/// per case) are shared the same way; a null one is converted again.
struct CaseGaussMaps {
  std::optional<SatResult<float>> float_plain, float_robust;
  std::optional<SatResult<double>> double_plain, double_robust;
  std::optional<SatResult<CGAL::Gmpq>> gmpq;
  const ConvexPolyhedron<double>* double_a = nullptr;
  const ConvexPolyhedron<double>* double_b = nullptr;
  const ConvexPolyhedron<CGAL::Gmpq>* gmpq_a = nullptr;
  const ConvexPolyhedron<CGAL::Gmpq>* gmpq_b = nullptr;
};

/// Compare the float and exact manifolds of one case and record them in
/// `rep` (by_comparison["manifold"], by_config["manifold/<config>"], details,
/// maxima, unexplained findings).  `exact_sat` is the mpq Gauss-map result on
/// the exact images `Aq`, `Bq` of `Af`, `Bf`; `given` the configurations'
/// Gauss-map results already computed (CaseGaussMaps).
/// The contact-manifold comparison of the checking core (check.hpp): for every
/// float configuration (float_plain, double_plain, float_robust, double_robust)
/// whose Gauss-map SAT feature equals the exact one, build the contact manifold
/// (contact_manifold.hpp) in that configuration and exactly (mpq; Gmpq as a
/// second exact type), and compare
///   * the incident face,
///   * the clipped points before the reduction: point count and feature ids
///     (contact_feature.hpp), matched by id,
///   * the depth and position of every matched point against a derived forward
///     error bound (check_manifold.cpp: the clip replay propagates a bound
///     through every Sutherland-Hodgman step; a clip point is a segment-plane
///     intersection, a depth a dot product; all relative to the coordinates,
///     valid with and without FMA),
///   * the points after the reduction to at most 4.
/// One class per (case, configuration), the worst of its aspects:
///   agree        same incident face, ids before and after the reduction, every
///                depth and position within its bound
///   exact_zero   ids differ, every difference explained (below), and caused
///                by an exact zero: an exact point without a partner lies exactly
///                on the reference plane or on a side plane it was not made by
///                (for a float point without a partner: such an exact clipped
///                vertex within its tolerance)
///   explained    ids differ; every unmatched point lies within its bound of
///                the other manifold's clipped polygon, of a side plane or of
///                the reference plane (a decision at a boundary, or a weld)
///   tie          a different incident face whose exact anti-parallelism equals
///                the exact choice's within the two bounds; or the same clipped
///                points and a different reduction whose exact area (and
///                deepest depth) is within the reduction's float tolerance plus
///                the bounds of the exact optimum
///   unexplained  anything else (a bound exceeded, an unmatched point far from
///                every boundary, the exact types disagreeing): a bug
/// Exact types among themselves (gmpq against mpq) must be identical.
/// Sub-classes per aspect are kept in CaseReport::details under "manifold.*",
/// the largest error/bound ratios in CaseReport::maxima.
void check_manifolds(const ConvexPolyhedron<float>& Af, const ConvexPolyhedron<float>& Bf,
                     const ConvexPolyhedron<mpq_class>& Aq, const ConvexPolyhedron<mpq_class>& Bq,
                     const SatResult<mpq_class>& exact_sat, const CaseGaussMaps& given,
                     const CheckOptions& opt, CaseReport& rep);

/// One float configuration against the exact manifolds, with the float SAT
/// result given (the core of check_manifolds, for tests): records under the
/// configuration name "float_given" and returns its class (agree when the SAT
/// feature differs from the exact one: nothing is compared).
Classification check_manifold_float(const ConvexPolyhedron<float>& Af, const ConvexPolyhedron<float>& Bf,
                                    const ConvexPolyhedron<mpq_class>& Aq,
                                    const ConvexPolyhedron<mpq_class>& Bq,
                                    const SatResult<mpq_class>& exact_sat, const SatResult<float>& float_sat,
                                    const CheckOptions& opt, CaseReport& rep);

/// The report's "manifold" section as a text table (its JSON value is
/// written by print_json, campaign.hpp).
void print_manifold_text(std::ostream& out, const std::map<std::string, Counts>& comparisons,
                         const std::map<std::string, Counts>& by_config,
                         const std::map<std::string, Counts>& details,
                         const std::map<std::string, double>& maxima);

}  // namespace sepax::fuzz
