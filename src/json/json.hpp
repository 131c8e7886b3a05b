// src/json/json.hpp
//
// A small, strict JSON reader and writer for the command-line program (batch
// queries, --json output).  No dependencies beyond the standard library.
//
// Reader (RFC 8259):
//   * values: objects, arrays, strings, numbers, true, false, null;
//   * strings: the escapes \" \\ \/ \b \f \n \r \t \uXXXX (UTF-16 surrogate
//     pairs combined; a lone surrogate is an error), raw control characters
//     are rejected, and the raw bytes must be valid UTF-8;
//   * numbers: the JSON grammar exactly (no leading '+', no leading zeros, no
//     "NaN"/"Infinity", no hex); the value is the nearest double, and the text
//     as written is kept so that an id can be echoed unchanged.  A number
//     outside the double range is an error;
//   * nesting deeper than ParseOptions::max_depth is an error (no stack
//     exhaustion on hostile input); duplicate object keys are an error;
//   * errors are ParseError, whose what() reads "line L, column C: <problem>"
//     (column counted in bytes from 1).
// Writer: compact output; strings escaped (control characters as \u00XX);
// numbers in the shortest form that reads back as the same double (non-finite
// doubles, which JSON cannot express, are written as null).
#pragma once

#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace sepax::cli::json {

struct Value;
using Array = std::vector<Value>;
using Object = std::vector<std::pair<std::string, Value>>;  // in input order

struct Number {
  double value = 0;
  std::string text;  // the lexeme as read; empty for numbers made in code
};

struct Value {
  std::variant<std::nullptr_t, bool, Number, std::string, Array, Object> data;

  Value() : data(nullptr) {}
  Value(std::nullptr_t) : data(nullptr) {}
  Value(bool b) : data(b) {}
  Value(double d) : data(Number{d, {}}) {}
  Value(int i) : data(Number{static_cast<double>(i), std::to_string(i)}) {}
  Value(long long i) : data(Number{static_cast<double>(i), std::to_string(i)}) {}
  Value(Number n) : data(std::move(n)) {}
  Value(std::string s) : data(std::move(s)) {}
  Value(const char* s) : data(std::string(s)) {}
  Value(Array a) : data(std::move(a)) {}
  Value(Object o) : data(std::move(o)) {}

  bool is_null() const { return std::holds_alternative<std::nullptr_t>(data); }
  bool is_bool() const { return std::holds_alternative<bool>(data); }
  bool is_number() const { return std::holds_alternative<Number>(data); }
  bool is_string() const { return std::holds_alternative<std::string>(data); }
  bool is_array() const { return std::holds_alternative<Array>(data); }
  bool is_object() const { return std::holds_alternative<Object>(data); }

  bool as_bool() const { return std::get<bool>(data); }
  double as_double() const { return std::get<Number>(data).value; }
  const Number& as_number() const { return std::get<Number>(data); }
  const std::string& as_string() const { return std::get<std::string>(data); }
  const Array& as_array() const { return std::get<Array>(data); }
  const Object& as_object() const { return std::get<Object>(data); }

  /// The member named key of an object, or nullptr (also when not an object).
  const Value* find(std::string_view key) const;
};

/// "null", "boolean", "number", "string", "array" or "object".
const char* kind_name(const Value& v);

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

/// Parse one JSON text (surrounding whitespace allowed, nothing else).
Value parse(std::string_view text, const ParseOptions& options = {});

/// Compact JSON text of v.
std::string write(const Value& v);
void write(std::ostream& out, const Value& v);

/// The shortest decimal text that reads back as d ("null" when not finite).
std::string number_text(double d);

/// s as a quoted, escaped JSON string.
std::string quote(std::string_view s);

}  // namespace sepax::cli::json
