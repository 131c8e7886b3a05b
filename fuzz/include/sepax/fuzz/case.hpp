// sepax/fuzz/case.hpp
//
// FuzzCase: one differential-fuzzing case, a pair of convex shapes A and B in
// one world frame, as the fuzzer generated (or decoded, or read) them, and its
// text format (read_case / write_case).
//
// Every coordinate is a float value stored in a double.  That is what makes
// "identical inputs" possible: the float polyhedron is built from exactly these
// values, and the double and exact polyhedra are its exact images
// (ConvexPolyhedron<T>::convert_from: same combinatorics, same plane triples).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include <sepax/vec3.hpp>

namespace sepax::fuzz {

struct ShapeSpec {
  std::vector<Vec3<double>> vertices;   // float-representable
  std::vector<std::vector<int>> faces;  // CCW from outside; a flat shape is a polygon and its reverse
};

struct FuzzCase {
  std::string family = "manual";
  std::uint64_t seed = 0;
  ShapeSpec a, b;
};

/// Round every coordinate to the nearest float (the canonical form).
void round_to_float(ShapeSpec& s);

/// Write in the text format; `comment` lines are written first as '#' comments.
///
/// Text format (one case per file, '#' starts a comment, human-readable):
///
///   sepax-fuzz-case 1
///   family boxes            # generator family (free text, no spaces)
///   seed 1234               # generator seed (informational)
///   shape A
///   v 1 -1 0.5              # vertices, "%.9g": round-trips every float exactly
///   f 0 3 2 1               # faces: 0-based vertex indices, CCW from outside
///   end
///   shape B
///   ...
///   end
///
/// Values are read as double and then rounded to float, so a hand-edited file
/// always denotes float inputs.
void write_case(std::ostream& out, const FuzzCase& c, const std::string& comment = "");
/// Parse the text format; throws InvalidInput(ErrorCode::Parse) naming the line.
FuzzCase read_case(std::istream& in, const std::string& name = "<case>");
FuzzCase read_case_file(const std::string& path);
void write_case_file(const std::string& path, const FuzzCase& c, const std::string& comment = "");

}  // namespace sepax::fuzz
