// src/io/shape_data.hpp
//
// ShapeData: a shape as read from a file or named on the command line, before
// it is built in a number type: double coordinates plus either a face list
// (validated later by ConvexPolyhedron<T>::from_faces) or a bare point set
// (hulled later by sepax::convex_hull<T>).  Doubles are the input format:
// converting them to an exact type is exact (from_double).
#pragma once

#include <string>
#include <vector>

#include <sepax/vec3.hpp>

namespace sepax::cli::io {

struct ShapeData {
  enum class Kind { Faces, Points };
  Kind kind = Kind::Faces;
  std::string name;                       // file name or built-in spec, for messages
  std::vector<Vec3<double>> vertices;     // Faces: the vertices; Points: the point set
  std::vector<std::vector<int>> faces;    // Faces only: 0-based vertex indices, CCW from outside
  std::vector<std::size_t> face_lines;    // Faces read from a file: the line of each face (0 if none)
  std::vector<std::size_t> vertex_lines;  // Faces read from a file: the line of each vertex (0 if none)
  bool from_file = false;                 // read from a mesh file (errors suggest hull:)

  /// The face list to build: a single face is that face as a double-sided
  /// polygon (sepax's flat shape: the loop and the same loop reversed), so a
  /// file holding one triangle is the double-sided triangle.
  std::vector<std::vector<int>> closed_faces() const {
    if (faces.size() != 1) return faces;
    return {faces[0], std::vector<int>(faces[0].rbegin(), faces[0].rend())};
  }
};

}  // namespace sepax::cli::io
