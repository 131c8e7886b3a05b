// src/io/open_file.hpp
//
// Opening an input file with a clear error (InvalidInput, ErrorCode::Parse,
// "FILE: cannot open: <reason>") instead of a silently empty stream.
#pragma once

#include <fstream>
#include <string>

namespace sepax::cli::io {

std::ifstream open_input(const std::string& path);

}  // namespace sepax::cli::io
