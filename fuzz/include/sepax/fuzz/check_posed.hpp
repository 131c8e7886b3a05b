// sepax/fuzz/check_posed.hpp
//
// Posed queries and warm sequences in the checking core (check.hpp): the
// engine's path (prepared shapes in local frames, a pose per shape, a
// per-pair SatCache) against the answers the library defines for it
// (posing.hpp, posed_queries.hpp, sat_cache.hpp).  check_posed draws the poses
// from the case seed (B near A) and compares, per configuration and SAT:
//   posed           the posed query against the same SAT on (A, B'), bit for bit;
//   posed_exact     robust decisions against exact arithmetic (Epeck::FT) on the exact images;
//   posed_rational  exact rational poses stay exact;
//   warm            cached queries along a coherent sequence against fresh ones.
// Every difference is unexplained: these are identities the library states,
// not roundings.
#pragma once

#include <cstdint>

#include <gmpxx.h>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/fuzz/check.hpp>
#include <sepax/robust/number_types.hpp>

namespace sepax::fuzz {

/// Posed queries and warm sequences in the checking core (check.hpp): the
/// engine's path (prepared shapes in local frames, a pose per shape, a
/// per-pair SatCache) against the answers the library defines for it
/// (posing.hpp, posed_queries.hpp, sat_cache.hpp).  A case's shapes are taken
/// as local frames; the poses are drawn from the case seed: pose_a a random
/// rotation and translation, pose_b = pose_a composed with a small relative
/// motion, so the posed pair is near the case's pair.
///
/// Comparisons (per configuration float_plain, double_plain, float_robust,
/// double_robust, and per SAT):
///   posed           the posed query equals the same SAT on (A, B'),
///                   B' = posed(B, relative_pose(pose_a, pose_b)), bit for bit
///                   (overlap, feature, separation, early exit), its axis
///                   pose_a.rotate(the local axis); and the posed contact
///                   manifold equals contact_manifold(A, B', local result) with
///                   its points mapped by pose_a (SAT "manifold")
///   posed_exact     robust configurations: the posed query's overlap verdict
///                   and feature equal the exact (Epeck::FT) run of the same SAT on the exact
///                   images of A and B' (the input the robust decisions are
///                   exact for), when E_A E_B <= posed_exact_pair_budget
///   posed_rational  exact rational poses stay exact: mpq prepared shapes at
///                   poses with integer-quaternion rotations and dyadic
///                   translations give the mpq Gauss map (and traversal) of
///                   the shapes moved exactly to the world: same verdict,
///                   feature, separation and world axis
///   warm            a coherent sequence of 8 small pose changes of B: the
///                   cached (warm-started) query equals the fresh query at
///                   every step, bit for bit without early exit; with an
///                   early exit at a margin, the same verdict and early-exit
///                   decision, and the fresh result whenever it does not exit
/// Every difference is unexplained: these are identities the library states,
/// not roundings.  Skips above the budget are counted (CaseReport::skipped).
/// Ad, Bd and Aq, Bq are the case's double and mpq images
/// (ConvexPolyhedron<T>::convert_from of Af, Bf), converted once per case by
/// check_case.
void check_posed(const ConvexPolyhedron<float>& Af, const ConvexPolyhedron<float>& Bf,
                 const ConvexPolyhedron<double>& Ad, const ConvexPolyhedron<double>& Bd,
                 const ConvexPolyhedron<mpq_class>& Aq, const ConvexPolyhedron<mpq_class>& Bq,
                 std::uint64_t seed, const CheckOptions& opt, CaseReport& rep);

}  // namespace sepax::fuzz
