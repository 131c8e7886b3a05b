// src/io/open_file.cpp -- see open_file.hpp.
#include "io/open_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <sepax/error.hpp>

namespace sepax::cli::io {

std::ifstream open_input(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InvalidInput(ErrorCode::Parse, path + ": cannot open: is a directory");
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int e = errno;
    throw InvalidInput(ErrorCode::Parse, path + ": cannot open: " + (e ? std::strerror(e) : "unknown error"));
  }
  return in;
}

}  // namespace sepax::cli::io
