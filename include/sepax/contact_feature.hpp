// sepax/contact_feature.hpp
//
// ContactFeatureId: which features of shape A and shape B produced a contact
// point.  A physics engine matches contact points across frames by this id
// (warm starting): it depends only on the combinatorics of the two shapes
// (vertex, undirected edge and face indices), never on coordinates, so it is
// stable while the shapes move as long as the same features stay in contact.
//
// The pairs a contact manifold produces:
//
//   face contact, reference face F on A, incident face G on B
//     incident vertex v inside F          A: Face(F)     B: Vertex(v)
//     incident edge e cut by side edge s  A: Edge(s)     B: Edge(e)
//     reference corner c inside G         A: Vertex(c)   B: Face(G)
//   face contact with the reference face on B: the same with A and B swapped
//   edge contact of edges eA, eB          A: Edge(eA)    B: Edge(eB)
//
// Edge indices are undirected edge indices (half-edge / 2), as in feature.hpp.
#pragma once

#include <cstdint>
#include <string>

namespace sepax {

enum class ShapeFeatureKind : std::uint8_t { None = 0, Vertex = 1, Edge = 2, Face = 3 };

/// One feature of one shape.
struct ShapeFeature {
  ShapeFeatureKind kind = ShapeFeatureKind::None;
  int index = -1;

  static ShapeFeature vertex(int v) { return {ShapeFeatureKind::Vertex, v}; }
  static ShapeFeature edge(int e) { return {ShapeFeatureKind::Edge, e}; }
  static ShapeFeature face(int f) { return {ShapeFeatureKind::Face, f}; }

  friend bool operator==(const ShapeFeature& x, const ShapeFeature& y) {
    return x.kind == y.kind && x.index == y.index;
  }
};

/// The pair of features (one of A, one of B) that made a contact point.
struct ContactFeatureId {
  ShapeFeature a;
  ShapeFeature b;

  /// A 64-bit key for hashing/matching: kinds in the top bits, indices below
  /// (indices up to 2^29 - 1).
  std::uint64_t key() const {
    const auto part = [](const ShapeFeature& f) {
      return (static_cast<std::uint64_t>(f.kind) << 30) |
             (static_cast<std::uint64_t>(static_cast<std::uint32_t>(f.index)) & 0x3fffffffu);
    };
    return (part(a) << 32) | part(b);
  }

  ContactFeatureId swapped() const { return {b, a}; }

  friend bool operator==(const ContactFeatureId& x, const ContactFeatureId& y) {
    return x.a == y.a && x.b == y.b;
  }
};

inline const char* kind_name(ShapeFeatureKind k) {
  switch (k) {
    case ShapeFeatureKind::None:
      return "none";
    case ShapeFeatureKind::Vertex:
      return "vertex";
    case ShapeFeatureKind::Edge:
      return "edge";
    case ShapeFeatureKind::Face:
      return "face";
  }
  return "?";
}

inline std::string to_string(const ShapeFeature& f) {
  return std::string(kind_name(f.kind)) + " " + std::to_string(f.index);
}

/// "A:face 1/B:vertex 4" (the form the CLI and the tests print).
inline std::string to_string(const ContactFeatureId& id) {
  return "A:" + to_string(id.a) + "/B:" + to_string(id.b);
}

}  // namespace sepax
