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
//   o NAME / g NAME    objects: when the file has 'o' statements, each 'o'
//                      name is one shape (the faces after it, up to the next
//                      'o'); otherwise each 'g' name is one.  Statements of the
//                      same name are one shape; faces before the first are the
//                      shape "" (listed by its index).  Vertex indices stay
//                      global, as OBJ defines them (a V-HACD decomposition:
//                      one 'o' per convex piece, indices counting on).
//
// Every other statement (vt, vn, vp, s, l, p, usemtl, mtllib, ...) is ignored;
// '#' starts a comment.  Each shape keeps only the vertices its faces use,
// renumbered 0-based in file order.  Errors: InvalidInput(ErrorCode::Parse,
// "FILE:LINE: ...").
#pragma once

#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "io/shape_data.hpp"

namespace sepax::cli::io {

struct ObjObject {
  std::string name;  // the 'o' or 'g' name ("" for faces before any)
  ShapeData shape;   // named FILE#NAME (FILE#K for ""); FILE alone when it is the only one
};

/// Every object of the file, in order of first appearance (at least one).
std::vector<ObjObject> read_obj_objects(std::istream& in, const std::string& name);

/// "0 'a', 1 'b', ..." for messages and listings.
std::string object_list(const std::vector<ObjObject>& objects);

/// The object named *selector, else the one of index *selector (0-based);
/// without a selector, the only object.  Errors name the file and list the
/// objects (InvalidInput, ErrorCode::Parse).
ShapeData select_object(const std::vector<ObjObject>& objects, const std::string& file,
                        const std::optional<std::string>& selector);

/// The file's only object (an error listing them when there are several).
ShapeData read_obj(std::istream& in, const std::string& name);
ShapeData read_obj_file(const std::string& path);

}  // namespace sepax::cli::io
