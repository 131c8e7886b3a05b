// src/io/points_reader.hpp
//
// Reader for a points file: one point "x y z" per line (whitespace or commas
// between the three values), '#' comments, blank lines ignored.  The point
// set is later replaced by its convex hull (sepax::convex_hull<T>).
// Errors: InvalidInput(ErrorCode::Parse, "FILE:LINE: ...").
#pragma once

#include <istream>
#include <string>

#include "io/shape_data.hpp"

namespace sepax::cli::io {

ShapeData read_points(std::istream& in, const std::string& name);
ShapeData read_points_file(const std::string& path);

}  // namespace sepax::cli::io
