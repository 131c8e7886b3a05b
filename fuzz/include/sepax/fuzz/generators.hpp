// sepax/fuzz/generators.hpp
//
// Case families of the standalone fuzzer (generate: each case from (family,
// seed) alone; the families and what each imitates are listed on
// family_names), the libFuzzer byte decoder (decode_bytes), and the built-in
// shape names the audit command accepts (builtin_shape).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <sepax/fuzz/case.hpp>

namespace sepax::fuzz {

/// Families (each case is generated from (family, seed) alone, so a seed
/// reproduces it):
///   sphere      hulls of 4..256 random points on a sphere (log-uniform count)
///   boxes       boxes, axis-aligned or rotated (random and 90-degree rotations),
///               grid placements: many exact ties and parallel edges
///   tetra       random tetrahedra and slivers (4th point 1e-6..1e-1 off the plane)
///   flat        double-sided triangles and quads against every other kind
///   prisms      prisms/cylinders with 3..32 sides: many parallel edges
///   perturbed   boxes and prisms with one vertex moved off its faces' planes
///               (inside the float validation tolerance)
///   scales      any of the above scaled by 1e-4..1e4 and moved far from the origin
///   touching    exactly touching placements: integer shapes, the 24 cube
///               rotations and dyadic translations, so contact survives the
///               conversion to float exactly
///   decomposition  neighbouring pieces of a convex decomposition (V-HACD,
///               CoACD output): hulls of 16..64 points of an ellipsoid cut by a
///               plane, sharing the cut section (touching, or a 1e-7..1e-3 gap
///               or overlap), thin pieces, world scale far from the origin
///   scanned     a scanned object's hull (200..2000 noisy points on an ellipsoid
///               or superellipsoid) against a box or a tetrahedron
/// All coordinates are rounded to float (case.hpp).
const std::vector<std::string>& family_names();

/// Generate the case of a family from a seed (throws std::invalid_argument for
/// an unknown family).
FuzzCase generate(const std::string& family, std::uint64_t seed);

/// libFuzzer: decode arbitrary bytes into a hull pair and a pose.  Never throws;
/// the shapes may still be invalid (the checker then rejects the case).
FuzzCase decode_bytes(const std::uint8_t* data, std::size_t size);

/// Built-in shapes by name: cube, box:HX,HY,HZ, tetra, prism:N, polygon:N,
/// triangle.  Throws InvalidInput(Parse) for an unknown name.
ShapeSpec builtin_shape(const std::string& name);

/// Apply a rigid pose: v -> R(q) v + t (q = (w,x,y,z), normalised here), then
/// round to float.
ShapeSpec posed(const ShapeSpec& s, const double t[3], const double q[4]);

/// Hull of a point set (sepax::convex_hull<float> on the points rounded to
/// float).  Throws InvalidInput for degenerate point sets.
ShapeSpec hull_of(std::vector<Vec3<double>> points);

}  // namespace sepax::fuzz
