// src/json/json.hpp
//
// JSON for the command-line program (batch queries, --json output), on
// nlohmann-json (Debian nlohmann-json3-dev).  Values are
// nlohmann::ordered_json: objects keep their keys in insertion order, so
// output keys come in the documented order.
//
// Reading (parse) is nlohmann's strict RFC 8259 reader (UTF-8 checked, lone
// surrogates, raw control characters, leading zeros, NaN/Infinity and numbers
// outside the double range rejected), plus what the batch format needs:
//   * duplicate object keys are an error;
//   * nesting deeper than ParseOptions::max_depth is an error;
//   * errors are ParseError, whose what() reads "line L, column C: <problem>"
//     (C counted in bytes from 1: the first byte of the token in error);
//   * the text of each number that is a member of the top-level object is
//     kept as written (Document::number_text), so an id is echoed unchanged.
// Writing (write) is compact nlohmann output; number(d) makes the JSON number
// for a double in its shortest form ("1", "0.5", "1e+300"; non-finite as null).
#pragma once

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sepax::cli::json {

using Value = nlohmann::ordered_json;

class ParseError : public std::runtime_error {
 public:
  ParseError(std::size_t line, std::size_t column, const std::string& problem);
  std::size_t line() const noexcept { return line_; }
  std::size_t column() const noexcept { return column_; }
  const std::string& problem() const noexcept { return problem_; }

 private:
  std::size_t line_, column_;
  std::string problem_;
};

struct ParseOptions {
  int max_depth = 64;  // arrays/objects nested deeper than this are rejected
};

struct Document {
  Value value;
  /// Top-level object members that are numbers: member name -> the number's text as written.
  std::map<std::string, std::string> number_text;
};

/// Parse one JSON text (surrounding whitespace allowed, nothing else).
Document parse_document(std::string_view text, const ParseOptions& options = {});
Value parse(std::string_view text, const ParseOptions& options = {});

/// The JSON number for d: an integer when d is one (|d| < 2^53, not -0), so
/// that it is written without ".0"; null when d is not finite.
Value number(double d);

/// Compact JSON text of v.  A string that is not valid UTF-8 (a file name,
/// a batch line's id, a message quoting input) is written with U+FFFD for
/// each invalid byte: the output is always valid JSON.
std::string write(const Value& v);

/// The shortest decimal text that reads back as d ("null" when not finite),
/// for text output.
std::string number_text(double d);

/// s as a quoted, escaped JSON string (invalid UTF-8 as write() writes it).
std::string quote(std::string_view s);

/// "null", "boolean", "number", "string", "array" or "object".
const char* kind_name(const Value& v);

}  // namespace sepax::cli::json
