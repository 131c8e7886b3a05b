// sepax/tolerances.hpp
//
// Every tolerance sepax uses, in one place.  All of them are *relative*: they
// are multiplied by the extent of the shapes involved (the length of the
// diagonal of the axis-aligned bounding box of the point set or polyhedron), so
// that a configuration scaled by 1e-4 or 1e4 is treated exactly like the
// original.  There are no absolute tolerances anywhere in sepax.  For exact
// number types every tolerance is zero: decisions are exact.
//
//   Tolerances<T>      the relative tolerances of the hull builder, validation,
//                      the plain float SATs and the contact manifold (float, double)
//   scale range        what float and double accept (BadScale beyond), on Tolerances
//   kSupportRoundingSlack, kAdjacentCoplanarFraction   slacks of the brute force and validation
//   kHull*, kConvexityScanPairs   the hull builder's bounds and slack multipliers (docs/hull.md)
#pragma once

#include "number_traits.hpp"

namespace sepax {

/// The relative tolerances of one number type, each x extent unless its line
/// says otherwise.  Exact types (and any type not specialised below): all zero.
///
/// The validation tolerances are looser than the hull builder's so that every
/// hull the builder produces validates (planarity, convexity = 4 x coplanar; the
/// builder also checks its output against half of them before returning it).
/// The hull builder computes its decisions on coordinates relative to the
/// centre of the bounding box; float cannot resolve a shape whose coordinates
/// exceed planarity x extent / (16u) (about 40 extents from the origin for
/// float, 2e5 for double), and the builder reports BadScale for such inputs
/// when validation would be at risk.
///
/// Scale range (float, double).  Since every tolerance is relative, the
/// absolute scale does not matter within the range where the arithmetic is
/// sound: ConvexPolyhedron (planes, normals, extent, centroid) and the plain
/// SAT kernel (edge axes, parallel test) rescale by powers of two where |N|^2
/// would overflow or underflow, and validation accepts
///   |coordinate| <= max(T)/16          (sums and differences stay finite)
///   coplanar/4 x extent >= min(T)      (the smallest tolerance is a normal
///                                       number: extent >= ~9e-298 for double,
///                                       ~5e-33 for float)
/// refusing anything else with BadScale.  The hull builder covers the same
/// range: it builds a point set whose bounding box is wider than
/// kHullExtentHigh or narrower than kHullExtentLow at a power of two times its
/// coordinates (exactly) and validates the result at the input's scale
/// (hull/working_scale.hpp).
template <class T>
struct Tolerances {
  /// Hull builder: points closer than this are one point, x extent.
  static constexpr double kWeld = 0;
  /// Hull builder: a point this close above a face plane is on it (dropped); two
  /// adjacent faces are merged when either sees every vertex of the other less
  /// than this below its plane; a face corner this close to the line through its
  /// neighbours is removed (every output face strictly convex).  Validation
  /// refuses adjacent faces within coplanar / 4.  x extent.
  static constexpr double kCoplanar = 0;
  /// Hull builder: a point set this close to a plane is a flat polygon, this
  /// close to a line it is Collinear.  2 x coplanar, so that a solid is never
  /// thinner than twice the merge tolerance (its sides cannot merge into its
  /// top).  x extent.
  static constexpr double kFlat = 0;
  /// Validation: face vertices within this of the face's plane, x extent.
  static constexpr double kPlanarity = 0;
  /// Validation: no vertex more than this above any face plane, x extent.
  static constexpr double kConvexity = 0;
  /// Validation: a face whose plane triangle is at most sliver x L high over its
  /// longest side L has zero area up to rounding (DegenerateFace).  Rounding
  /// alone gives collinear points a height up to ~14u L, and a face normal's
  /// angular error is ~4u / (height / L).  Below coplanar / 4, so every hull face
  /// (no corner within coplanar x extent of its neighbours' line) passes.
  /// x the face's longest side, not the extent.
  static constexpr double kSliver = 0;
  /// Brute-force SAT, float only: an edge endpoint within this of the extreme
  /// projection (on the unit axis) counts as supporting, plus the projections'
  /// own rounding, kSupportRoundingSlack (25) x u max|coordinate| (derived in
  /// PlainKernel::support_tolerance), which dominates for a small shape far
  /// from the origin.  x extent.
  static constexpr double kSupport = 0;
  /// Plain float SATs: edges with |eA x eB| <= parallel |eA| |eB| are parallel
  /// and skipped (their float cross product is too inaccurate to be an axis).
  /// The robust policy skips only exactly parallel edges; exact types likewise.
  /// The sine of the edges' angle, dimensionless.
  static constexpr double kParallel = 0;
  /// Contact manifold, float only: clip points closer than this are one point;
  /// in the 4-point reduction, depths within it are equally deep.  x the smaller
  /// of the two shapes' extents.
  static constexpr double kContactWeld = 0;
  /// Contact manifold reduction: a point is kept only if it adds more than this
  /// (doubled) area; squared distances and areas within it of the largest are
  /// ties.  x extent^2.
  static constexpr double kContactArea = 0;
  /// Hull builder (float, double): the widths of the points' bounding box it
  /// builds at as given.  Its predicates multiply up to four coordinate
  /// differences and compare them with squared tolerances (a squared
  /// cross-product length against (flat x length)^2), so they need
  /// extent^4 x flat^2 to be a normal number of T and 16 extent^4 to be
  /// finite; a point set whose largest width is outside the range is built at
  /// a power of two times its coordinates (hull/working_scale.hpp).
  /// Absolute: units of the coordinates (the only ones in this file, and not a
  /// tolerance: a power of two changes no decision within them).
  static constexpr double kHullExtentLow = 0;
  static constexpr double kHullExtentHigh = 0;
};

template <>
struct Tolerances<float> {
  static constexpr double kWeld = 1e-5;
  static constexpr double kCoplanar = 1e-5;
  static constexpr double kFlat = 2e-5;
  static constexpr double kPlanarity = 4e-5;
  static constexpr double kConvexity = 4e-5;
  static constexpr double kSliver = 2e-6;
  static constexpr double kSupport = 1e-5;
  static constexpr double kParallel = 1e-4;
  static constexpr double kContactWeld = 1e-5;
  static constexpr double kContactArea = 1e-6;
  /// 2^-80 x (2e-5)^2 = 3.3e-34 >= 1.2e-38 (the smallest normal float);
  /// 16 x 2^120 = 2.1e37 <= 3.4e38.
  static constexpr double kHullExtentLow = 0x1p-20;
  static constexpr double kHullExtentHigh = 0x1p30;
};

template <>
struct Tolerances<double> {
  static constexpr double kWeld = 1e-10;
  static constexpr double kCoplanar = 1e-10;
  static constexpr double kFlat = 2e-10;
  static constexpr double kPlanarity = 4e-10;
  static constexpr double kConvexity = 4e-10;
  static constexpr double kSliver = 2e-11;
  static constexpr double kSupport = 1e-10;
  static constexpr double kParallel = 1e-8;
  static constexpr double kContactWeld = 1e-10;
  static constexpr double kContactArea = 1e-14;
  /// 2^-800 x (2e-10)^2 = 6e-261 >= 2.2e-308; 16 x 2^800 = 1e242 <= 1.8e308.
  static constexpr double kHullExtentLow = 0x1p-200;
  static constexpr double kHullExtentHigh = 0x1p200;
};

/// The brute force's support tolerance (PlainKernel::support_tolerance) adds
/// this many u x max|coordinate| of the shape for the rounding of two
/// projections fl(n.v): at most 2 x 7 sqrt(3) u max|v_i| (first order, derived
/// there), so an edge endpoint rounding hides is still supporting; x u max|x|.
inline constexpr double kSupportRoundingSlack = 25;

/// Validation refuses two adjacent faces when every vertex of one is within this
/// fraction of the coplanar tolerance (x extent) of the other's plane (they must
/// be merged), and the range check needs that smallest tolerance to be a normal
/// number.  A quarter: below the hull builder's merge tolerance (coplanar), so
/// every hull it builds passes; x coplanar x extent.
inline constexpr double kAdjacentCoplanarFraction = 0.25;

// ---- convex hull (float/double; docs/hull.md) --------------------------------
// Every constant of the hull builder (include/sepax/hull/), in units of eps = Tolerances<T>::kCoplanar x
// extent unless its line says otherwise.  Exact types use none of them.
//
// | name                        | value | reason                                                          |
// |-----------------------------|-------|-----------------------------------------------------------------|
// | kHullOutsideBound           | 64    | the guarantee: every input point within it of the hull, measured |
// | kHullSlabHalfThickness      | 63    | a projected slab polygon is within it of every point (< bound)   |
// | kHullSlabThickness          | 126   | twice the half-thickness: the thickest slab projected            |
// | kHullSlabCandidateWidth     | 252   | a set wider across its largest face is not a slab (one pass)     |
// | kHullSlabAxisPreference     | 2     | a coordinate plane this near the thinnest keeps projections exact|
// | kHullTentLift               | 8     | above the merge (1) and coplanar-face (1/4) tolerances, room left|
// | kHullRepairTolerance        | 2     | a repair pass pins points farther out than this                  |
// | kHullFoldDistance           | 2     | a pinned vertex this far from its neighbours' segment is a fold  |
// | kHullHeightSafe             | 32    | half the bound: a result's heights it may reach                  |
// | kHullMeasureReach           | 65    | a point this far below a face no longer climbs past it           |
// | kHullMaxRepairs             | 8     | repair passes, each rebuilding with the lost points pinned       |
// | kHullMaxEyeVisits           | 4     | float: times a point may be the eye; then it is dropped (repair) |
// | kHullPlaneRoundingSlack     | 8     | x u max|x|: rounding of a plane height on input coordinates      |
// | kHullDeepInsideSlack        | 4     | x that slack: a deep-inside point clears every height's rounding |
// | kHullDeepInsidePlanarity    | 2     | x planarity x extent: validated plane against Newell plane       |
// | kHullFarRounding            | 16    | x u max|x|: beyond planarity x extent float cannot resolve shape |
// | kHullPrecheckFraction       | 0.5   | the pre-check uses half of validation's planarity and convexity  |
// | kHullPrecheckCoplanarMargin | 2     | x validation's coplanar/4: faces it would see as coplanar        |
// | kHullPrecheckSliverMargin   | 2     | x validation's sliver: plane triangles it would refuse           |
// | kHullDistanceTie            | 1e-9  | relative: face distances this close are ties                     |
// | kConvexityScanPairs         | 4e6   | faces x vertices scanned pairwise; beyond, the local certificate |
// | kHullPointScanPairs         | 1e5   | points x faces scanned pairwise; beyond, a climb                 |
// | kHullResumeScanPairs        | 4e6   | pinned points x triangles a repair pass resumes from; beyond, not |

/// How far outside its hull an input point may be (height above a face plane
/// and Euclidean distance), x eps; measured over every stress set, not proven.
inline constexpr double kHullOutsideBound = 64;
/// Half-thickness of the thickest slab returned as its projected polygon, x eps.
inline constexpr double kHullSlabHalfThickness = kHullOutsideBound - 1;
/// Thickness of the thickest slab returned as its projected polygon, x eps.
inline constexpr double kHullSlabThickness = 2 * kHullSlabHalfThickness;
/// A point set wider than this across the plane of its hull's largest face is not a slab, x eps.
inline constexpr double kHullSlabCandidateWidth = 4 * kHullSlabHalfThickness;
/// A coordinate plane at most this much wider than the thinnest direction is preferred, x eps.
inline constexpr double kHullSlabAxisPreference = 2;
/// How far a tent lifts a lost slab corner into the slab, x eps.
inline constexpr double kHullTentLift = 8;
/// A repair pass puts back points farther than this from the hull, x eps.
inline constexpr double kHullRepairTolerance = 2;
/// A pinned vertex farther than this from its neighbours' segment is a fold, x eps.
inline constexpr double kHullFoldDistance = 2;
/// A nearer-every-point result is kept only with heights at most this, x eps.
inline constexpr double kHullHeightSafe = kHullOutsideBound / 2;
/// Measuring a point, faces it is farther than this below are not climbed past, x eps.
inline constexpr double kHullMeasureReach = kHullOutsideBound + 1;
/// Repair passes (each rebuilds the hull with the lost points pinned), count.
inline constexpr int kHullMaxRepairs = 8;
/// Float T: how many times one point may be quickhull's eye in one build.  A vertex a later step
/// removes is tested again like any other point (float: it may be outside by rounding) and can
/// become the eye again; without a limit two such points can replace each other forever.  A point
/// over the limit is dropped like an eye with a non-simple horizon; the repair passes measure it.
/// Exact T never re-uses an eye (every eye is an extreme point of the input).  A count.
inline constexpr int kHullMaxEyeVisits = 4;
/// Rounding slack of a plane height evaluated on input coordinates, x u max|x|.
inline constexpr double kHullPlaneRoundingSlack = 8;
/// A point is deep inside when it clears this many plane-rounding slacks, dimensionless.
inline constexpr double kHullDeepInsideSlack = 4;
/// ... plus this many planarity x extent (a validated plane against its Newell plane), dimensionless.
inline constexpr double kHullDeepInsidePlanarity = 2;
/// Float T cannot resolve a shape when this x u max|x| exceeds planarity x extent.
inline constexpr double kHullFarRounding = 16;
/// The builder's own check of its output uses this fraction of validation's
/// planarity and convexity tolerances, dimensionless.
inline constexpr double kHullPrecheckFraction = 0.5;
/// The pre-check refuses adjacent faces within this many validation coplanar tolerances
/// (coplanar / 4 x extent) of each other's plane, dimensionless.
inline constexpr double kHullPrecheckCoplanarMargin = 2;
/// The pre-check refuses plane triangles of aspect below this many validation sliver tolerances,
/// dimensionless.
inline constexpr double kHullPrecheckSliverMargin = 2;
/// Relative difference below which two distances of a point from face polygons are a tie, dimensionless.
inline constexpr double kHullDistanceTie = 1e-9;
/// Faces x vertices up to which convexity is checked vertex against every face
/// plane (validation and the builder's pre-check); beyond, by the local
/// certificate (docs/hull.md, "Validation"), pairs.
inline constexpr double kConvexityScanPairs = 4e6;
/// Points x faces up to which the quickhull's sweep and the measure of a
/// pass's result take every point against every face; beyond, each point
/// against the faces near the one it climbs to, pairs.  The climb reads only
/// the faces a point can be above or near and costs less from small hulls on
/// (measured, docs/hull.md: the 10^3-point float cylinder, 1 237 faces, 41.6 M
/// instructions with this bound, 60.8 M with 4e6).
inline constexpr double kHullPointScanPairs = 1e5;
/// Pinned points x live triangles up to which a repair pass goes on from the
/// last pass's triangles (repair.hpp, resume: a scan of every pair); beyond,
/// the pass builds from the start, pairs.
inline constexpr double kHullResumeScanPairs = 4e6;

}  // namespace sepax
