// sepax/error.hpp
//
// The one exception type sepax throws for bad input.  Its code() says which
// rule the input broke; what() names the offending element (vertex, face, edge,
// file line) in plain words.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace sepax {

enum class ErrorCode {
  NonFinite,       // NaN or infinity in a coordinate
  TooFewPoints,    // fewer than 3 distinct points (or 4 for a solid face list)
  Collinear,       // all points on one line
  BadIndex,        // a face refers to a vertex that does not exist
  DegenerateFace,  // a face with < 3 vertices, a repeated vertex (or two corners at one point), or zero area
  NotManifold,     // an edge not shared by exactly two faces, or used twice in one direction
  BadEuler,        // V - E + F != 2
  UnusedVertex,    // a vertex on no face
  NonPlanarFace,   // a face's vertices are not on one plane (within tolerance)
  NonConvexFace,   // a face polygon that turns the wrong way or has collinear corners
  NotConvex,       // a vertex above some face plane, or two adjacent faces coplanar
  InwardFaces,     // faces are oriented inward (clockwise seen from outside)
  BadScale,        // extent zero or too small, or coordinates too large, for the number type
  Parse,           // a malformed input file
};

class InvalidInput : public std::invalid_argument {
 public:
  InvalidInput(ErrorCode code, const std::string& message) : std::invalid_argument(message), code_(code) {}
  ErrorCode code() const noexcept { return code_; }

 private:
  ErrorCode code_;
};

/// A number for an error message: "%.9g", so 1e-20 and 1.7e30 read as such
/// (std::to_string prints "%f": "0.000000" and thirty digits).
inline std::string format_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

/// The error for a coordinate that is finite in the input but not in the
/// number type T it is converted to: "coordinate y of vertex 2 (1e+300) is
/// beyond the range of float" (BadScale).  `what` names the element ("vertex",
/// "point"); `value` is the input coordinate.
inline InvalidInput coordinate_beyond_range(int axis, const char* what, std::size_t index, double value,
                                            std::string_view type_name) {
  // (appended to one string: GCC 12 warns falsely, -Warray-bounds, on a chain of temporaries here)
  std::string m = "coordinate ";
  m += "xyz"[axis];
  m += " of ";
  m += what;
  m += ' ';
  m += std::to_string(index);
  m += " (";
  m += format_number(value);
  m += ") is beyond the range of ";
  m += type_name;
  return InvalidInput(ErrorCode::BadScale, std::move(m));
}

inline const char* to_string(ErrorCode c) {
  switch (c) {
    case ErrorCode::NonFinite:
      return "non-finite";
    case ErrorCode::TooFewPoints:
      return "too-few-points";
    case ErrorCode::Collinear:
      return "collinear";
    case ErrorCode::BadIndex:
      return "bad-index";
    case ErrorCode::DegenerateFace:
      return "degenerate-face";
    case ErrorCode::NotManifold:
      return "not-manifold";
    case ErrorCode::BadEuler:
      return "bad-euler";
    case ErrorCode::UnusedVertex:
      return "unused-vertex";
    case ErrorCode::NonPlanarFace:
      return "non-planar-face";
    case ErrorCode::NonConvexFace:
      return "non-convex-face";
    case ErrorCode::NotConvex:
      return "not-convex";
    case ErrorCode::InwardFaces:
      return "inward-faces";
    case ErrorCode::BadScale:
      return "bad-scale";
    case ErrorCode::Parse:
      return "parse";
  }
  return "unknown";
}

}  // namespace sepax
