// tests/cli/cli_test_support.hpp -- shared by the CLI tests: a command's exit
// status and captured output, and temporary input files (one directory per
// test process, removed at exit).
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace sepax::cli::test {

struct CommandRun {
  int status;
  std::string out, err;
};

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& prefix) {
    path = std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string write(const std::string& name, const std::string& text) const {
    const auto p = path / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
};

/// The whole content of the file at path (binary-safe; "" when unreadable).
inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A file `name` with `text` in this process's temporary directory; its path.
inline std::string temp_file(const std::string& name, const std::string& text) {
  static const TempDir dir("sepax_cli_test");
  return dir.write(name, text);
}

}  // namespace sepax::cli::test
