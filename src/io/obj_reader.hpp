// src/io/obj_reader.hpp
//
// Reader for the polygon part of Wavefront OBJ:
//
//   v x y z [w]        vertex (w, if present, must be 1; "v x y z r g b"
//                      vertex colours are accepted and ignored)
//   f i j k ...        face, 1-based vertex indices; each entry may be i,
//                      i/t, i//n or i/t/n (texture/normal indices ignored);
//                      negative indices count back from the last vertex read
//                      (-1 is the latest)
//
// Every other statement (vt, vn, vp, g, o, s, l, p, usemtl, mtllib, ...) is
// ignored; '#' starts a comment.  All faces form one polyhedron.  Faces are
// stored 0-based.  Errors: InvalidInput(ErrorCode::Parse, "FILE:LINE: ...").
#pragma once

#include <istream>
#include <string>

#include "io/shape_data.hpp"

namespace sepax::cli::io {

ShapeData read_obj(std::istream& in, const std::string& name);
ShapeData read_obj_file(const std::string& path);

}  // namespace sepax::cli::io
