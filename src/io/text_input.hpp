// src/io/text_input.hpp
//
// Line-oriented text input shared by the shape readers (OFF, OBJ, points):
// a line reader that counts lines, tokenising with '#' comments stripped,
// strict number parsing, and the error every reader throws:
//   InvalidInput(ErrorCode::Parse, "FILE:LINE: <what is wrong>").
#pragma once

#include <concepts>
#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sepax::cli::io {

/// Throws InvalidInput(ErrorCode::Parse, "file:line: what").
[[noreturn]] void fail_at(const std::string& file, std::size_t line, const std::string& what);

/// A place in a text input (file name and 1-based line), for the parse
/// errors of every reader.
class TextPlace {
 public:
  explicit TextPlace(std::string file) : file_(std::move(file)) {}
  std::size_t line_number() const { return line_; }
  const std::string& file() const { return file_; }
  /// Throws the parse error for the current line.
  [[noreturn]] void fail(const std::string& what) const { fail_at(file_, line_ == 0 ? 1 : line_, what); }

 protected:
  std::string file_;
  std::size_t line_ = 0;
};

/// Reads lines, keeping the 1-based number of the last line read.  Strips a
/// UTF-8 byte order mark before the first line and a trailing '\r' (CRLF
/// files), and rejects NUL bytes (binary data).
class LineReader : public TextPlace {
 public:
  LineReader(std::istream& in, std::string file) : TextPlace(std::move(file)), in_(in) {}
  /// The next line, false at end of input.
  bool next(std::string& line);

 private:
  std::istream& in_;
};

/// A UTF-8 byte order mark (editors on Windows write one before the first line); not content.
inline constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

/// text without a leading UTF-8 byte order mark.
inline std::string_view without_bom(std::string_view text) {
  return text.starts_with(kUtf8Bom) ? text.substr(kUtf8Bom.size()) : text;
}

/// s with its ASCII letters in lower case (file extensions, format names, STL keywords).
std::string lower_ascii(std::string s);

/// The whitespace-separated tokens of line, up to a '#' comment.  With
/// commas_separate, ',' also separates tokens (points files).
std::vector<std::string_view> tokens(std::string_view line, bool commas_separate = false);

/// The finite double spelled by token (a leading '+' is allowed); on failure
/// throws via reader.fail with "bad number 'tok' for <what>", or "<what> is
/// not finite" for NaN/Inf, or "... out of the range of a double".
double parse_double(const TextPlace& reader, std::string_view token, const std::string& what);

/// A non-negative decimal integer (at most max); errors like parse_double.
long long parse_count(const TextPlace& reader, std::string_view token, const std::string& what,
                      long long max);

/// A (possibly negative) decimal integer; errors like parse_double.
long long parse_integer(const TextPlace& reader, std::string_view token, const std::string& what);

/// The finite double or the integer spelled by token in the common way (no
/// leading '+'), without building any message; nullopt for anything else.
std::optional<double> quick_double(std::string_view token);
std::optional<long long> quick_integer(std::string_view token);

/// parse_double and parse_integer with the description made only for an
/// error (what() returns it): a reader calls them once per number of a file
/// of millions.
template <std::invocable What>
double parse_double(const TextPlace& reader, std::string_view token, const What& what) {
  if (const auto v = quick_double(token)) return *v;
  return parse_double(reader, token, std::string(what()));
}
template <std::invocable What>
long long parse_integer(const TextPlace& reader, std::string_view token, const What& what) {
  if (const auto v = quick_integer(token)) return *v;
  return parse_integer(reader, token, std::string(what()));
}

/// Shortens a token for an error message (binary garbage can be long).
std::string shown(std::string_view token);

}  // namespace sepax::cli::io
