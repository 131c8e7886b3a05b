// src/io/off_reader.hpp
//
// Reader for the OFF polyhedron format (Geomview "Object File Format"):
//
//   OFF                      header (also "COFF", "NOFF", "CNOFF", "STOFF"...:
//   # comment                the extra per-vertex values are ignored)
//   V F [E]                  counts (E, the edge count, is optional and ignored)
//   x y z                    V vertex lines
//   n i0 i1 ... i(n-1) [..]  F face lines, 0-based indices, extra values
//                            (face colours) ignored
//
// Accepted quirks: '#' comments anywhere (whole line or trailing), blank lines,
// CRLF line ends, the counts on the header line ("OFF 8 6 12"), a missing
// header (the file starts with the counts line).  Not accepted: 4OFF/nOFF
// (other dimensions), binary OFF, and vertices or faces split across lines.
// Errors: InvalidInput(ErrorCode::Parse, "FILE:LINE: <what is wrong>").
#pragma once

#include <istream>
#include <string>

#include "io/shape_data.hpp"

namespace sepax::cli::io {

/// Read OFF text from in; name is used in error messages.
ShapeData read_off(std::istream& in, const std::string& name);

/// Read an OFF file (error when it cannot be opened).
ShapeData read_off_file(const std::string& path);

}  // namespace sepax::cli::io
