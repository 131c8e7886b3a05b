// src/io/soup_reader.hpp
//
// STL meshes, read with CGAL's polygon-soup reader (CGAL::IO::read_STL,
// called on a stream so that standard input works as well as a file):
//
//   STL   ASCII ("solid ...") or binary (80-byte header, triangle count,
//         50 bytes per triangle); identical points are one vertex (CGAL
//         merges them), so a closed STL mesh is a closed face list
//
// The result is a face list like OFF's (faces CCW from outside).  A file the
// reader refuses, one without faces, or one whose faces name missing
// vertices is InvalidInput(ErrorCode::Parse, "FILE: ...") -- CGAL's reader
// does not report a line.  This is the program's one translation unit that
// includes CGAL's IO headers.  (PLY has its own reader, ply_reader.hpp.)
#pragma once

#include <istream>
#include <string>

#include "io/shape_data.hpp"

namespace sepax::cli::io {

ShapeData read_stl(std::istream& in, const std::string& name);
ShapeData read_stl_file(const std::string& path);

}  // namespace sepax::cli::io
