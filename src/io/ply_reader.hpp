// src/io/ply_reader.hpp
//
// Reader for PLY meshes and point clouds (Stanford polygon format), ASCII or
// binary of either byte order:
//   1. the header: "ply", the format line, "element NAME COUNT" lines each
//      followed by its "property TYPE NAME" / "property list COUNT_TYPE
//      INDEX_TYPE NAME" lines, comments, "end_header";
//   2. every count bounded by the data after the header (an instance with a
//      property takes at least one byte, a list entry at least its type's
//      size), so no declared count makes the reader loop or reserve beyond
//      the file;
//   3. the body, element by element in header order: the "vertex" element's
//      x, y, z (any scalar type), the "face" element's vertex_indices (or
//      vertex_index) list of an integer type; other properties (normals,
//      colours, texture coordinates) and other elements are read past.
// ASCII instances are one line each.  A file whose vertex element has no
// face element after it, or an empty one, is a point set (a scanner's
// point cloud), to be hulled.
//
// Errors: InvalidInput(ErrorCode::Parse, "FILE:LINE: <what is wrong>") in
// the header and an ASCII body, "FILE: <what is wrong> (byte N)" in a binary
// body.  (CGAL 5.5's read_PLY, which this replaces, crashes on a property
// line before any element and trusts a list's count: "2000000000" as a
// face's count took 7.8 GB and did not finish.)
#pragma once

#include <istream>
#include <string>

#include "io/shape_data.hpp"

namespace sepax::cli::io {

/// Read a PLY file's bytes from in; name is used in error messages.
ShapeData read_ply(std::istream& in, const std::string& name);

/// Read a PLY file (error when it cannot be opened).
ShapeData read_ply_file(const std::string& path);

}  // namespace sepax::cli::io
