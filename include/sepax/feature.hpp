// sepax/feature.hpp
//
// Feature: which candidate axis a SAT result refers to, and the tie-break order
// that every SAT and every number type uses.
//
//   FaceA:    a = face of A,              b = support vertex of B (deepest along -normal)
//   FaceB:    a = support vertex of A,    b = face of B
//   EdgePair: a = edge of A,              b = edge of B   (undirected edge indices)
//   SideA:    a = edge of A,              b = support vertex of B
//   SideB:    a = support vertex of A,    b = edge of B
//
// Side axes (only when A and B are both flat) are described on FeatureType;
// the tie-break rule, the same for every T and every SAT, on precedes:
// among exactly equal separations, FaceA < FaceB < EdgePair < SideA < SideB,
// each by index.
#pragma once

#include <cstdint>
#include <string>
#include <tuple>

namespace sepax {

/// The kind of a candidate axis.  Side axes exist only when A and B are both
/// flat (double-sided polygons): the in-plane outward normal of a polygon
/// edge, edge direction x face normal.  For two polygons in one plane every 3D
/// candidate axis is the common plane normal (separation 0), and the side axes
/// are what separates polygons with a gap between them (see best_axis.hpp,
/// scan_side_axes).
enum class FeatureType : std::uint8_t { FaceA = 0, FaceB = 1, EdgePair = 2, SideA = 3, SideB = 4 };

struct Feature {
  FeatureType type = FeatureType::FaceA;
  int a = -1;
  int b = -1;

  static Feature face_a(int face, int support_vertex_b) {
    return {FeatureType::FaceA, face, support_vertex_b};
  }
  static Feature face_b(int support_vertex_a, int face) {
    return {FeatureType::FaceB, support_vertex_a, face};
  }
  static Feature edges(int edge_a, int edge_b) { return {FeatureType::EdgePair, edge_a, edge_b}; }
  static Feature side_a(int edge, int support_vertex_b) {
    return {FeatureType::SideA, edge, support_vertex_b};
  }
  static Feature side_b(int support_vertex_a, int edge) {
    return {FeatureType::SideB, support_vertex_a, edge};
  }

  /// The index that orders features of one type (the face for face features,
  /// the edge for side features).
  int primary() const { return type == FeatureType::FaceB || type == FeatureType::SideB ? b : a; }
  int secondary() const { return type == FeatureType::EdgePair ? b : 0; }

  friend bool operator==(const Feature& x, const Feature& y) {
    return x.type == y.type && x.a == y.a && x.b == y.b;
  }
};

/// True when x comes strictly before y in the tie-break order.  The rule (the
/// same for every T and every SAT): among candidate axes with exactly equal
/// separation, the one whose feature comes first in
///   FaceA (by face index)  <  FaceB (by face index)  <  EdgePair (by edge of A, then edge of B)
///     <  SideA (by edge of A)  <  SideB (by edge of B)
/// wins.  The support vertex is not part of the order: it is a function of the
/// axis (the lowest-index vertex among the exactly deepest ones).
inline bool precedes(const Feature& x, const Feature& y) {
  return std::make_tuple(static_cast<int>(x.type), x.primary(), x.secondary()) <
         std::make_tuple(static_cast<int>(y.type), y.primary(), y.secondary());
}

/// "faceA", "faceB", "edges", "sideA" or "sideB" (the names the JSON output uses).
inline const char* type_name(FeatureType t) {
  switch (t) {
    case FeatureType::FaceA:
      return "faceA";
    case FeatureType::FaceB:
      return "faceB";
    case FeatureType::EdgePair:
      return "edges";
    case FeatureType::SideA:
      return "sideA";
    case FeatureType::SideB:
      return "sideB";
  }
  return "?";
}

inline std::string to_string(const Feature& f) {
  return std::string(type_name(f.type)) + "(" + std::to_string(f.a) + "," + std::to_string(f.b) + ")";
}

}  // namespace sepax
