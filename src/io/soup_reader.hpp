// src/io/soup_reader.hpp
//
// PLY and STL meshes, read with CGAL's polygon-soup readers
// (CGAL::IO::read_PLY, CGAL::IO::read_STL: the readers
// CGAL::IO::read_polygon_soup dispatches to by extension, called on a
// stream so that standard input works as well as a file):
//
//   PLY   ASCII or binary (either byte order); the "vertex" element's x, y, z
//         and the "face" element's vertex_indices (or vertex_index) list;
//         other properties (normals, colours, texture coordinates) ignored
//   STL   ASCII ("solid ...") or binary (80-byte header, triangle count,
//         50 bytes per triangle); identical points are one vertex (CGAL
//         merges them), so a closed STL mesh is a closed face list
//
// The result is a face list like OFF's (faces CCW from outside).  A file the
// reader refuses, one without faces, or one whose faces name missing
// vertices is InvalidInput(ErrorCode::Parse, "FILE: ...") -- CGAL's readers
// do not report a line.  This is the program's one translation unit that
// includes CGAL's IO headers.
#pragma once

#include <istream>
#include <string>

#include "io/shape_data.hpp"

namespace sepax::cli::io {

ShapeData read_ply(std::istream& in, const std::string& name);
ShapeData read_stl(std::istream& in, const std::string& name);
ShapeData read_ply_file(const std::string& path);
ShapeData read_stl_file(const std::string& path);

}  // namespace sepax::cli::io
