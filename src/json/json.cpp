// src/json/json.cpp -- see json.hpp.
#include "json/json.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <system_error>

namespace sepax::cli::json {

const Value* Value::find(std::string_view key) const {
  if (!is_object()) return nullptr;
  for (const auto& [k, v] : as_object()) {
    if (k == key) return &v;
  }
  return nullptr;
}

const char* kind_name(const Value& v) {
  switch (v.data.index()) {
    case 0: return "null";
    case 1: return "boolean";
    case 2: return "number";
    case 3: return "string";
    case 4: return "array";
    case 5: return "object";
  }
  return "?";
}

ParseError::ParseError(std::size_t line, std::size_t column, const std::string& problem)
    : std::runtime_error("line " + std::to_string(line) + ", column " + std::to_string(column) +
                         ": " + problem),
      line_(line),
      column_(column),
      problem_(problem) {}

namespace {

std::string printable(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
  static const char* hex = "0123456789abcdef";
  return std::string("byte 0x") + hex[u >> 4] + hex[u & 15];
}

class Parser {
 public:
  Parser(std::string_view text, const ParseOptions& opt) : s_(text), opt_(opt) {}

  Value run() {
    skip_ws();
    if (at_end()) fail("empty input: expected a JSON value");
    Value v = value(0);
    skip_ws();
    if (!at_end()) fail("unexpected " + printable(s_[pos_]) + " after the JSON value");
    return v;
  }

 private:
  [[noreturn]] void fail_at(std::size_t pos, const std::string& what) const {
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < pos && i < s_.size(); ++i) {
      if (s_[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    }
    throw ParseError(line, pos - line_start + 1, what);
  }
  [[noreturn]] void fail(const std::string& what) const { fail_at(pos_, what); }

  bool at_end() const { return pos_ >= s_.size(); }
  char peek() const { return s_[pos_]; }

  void skip_ws() {
    while (!at_end() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) ++pos_;
  }

  void expect_more(const char* what) const {
    if (at_end()) fail(std::string("unexpected end of input: expected ") + what);
  }

  Value value(int depth) {
    expect_more("a JSON value");
    const char c = peek();
    switch (c) {
      case '{': return object(depth + 1);
      case '[': return array(depth + 1);
      case '"': return Value(string());
      case 't': literal("true"); return Value(true);
      case 'f': literal("false"); return Value(false);
      case 'n': literal("null"); return Value(nullptr);
      default:
        if (c == '-' || (c >= '0' && c <= '9')) return Value(number());
        fail("unexpected " + printable(c) + ": expected a JSON value");
    }
  }

  void literal(std::string_view word) {
    if (s_.substr(pos_, word.size()) != word) {
      fail("invalid literal: expected '" + std::string(word) + "'");
    }
    pos_ += word.size();
  }

  void check_depth(int depth) const {
    if (depth > opt_.max_depth) {
      fail("nesting deeper than " + std::to_string(opt_.max_depth) + " levels");
    }
  }

  Value array(int depth) {
    check_depth(depth);
    ++pos_;  // '['
    Array out;
    skip_ws();
    expect_more("a value or ']'");
    if (peek() == ']') {
      ++pos_;
      return Value(std::move(out));
    }
    for (;;) {
      skip_ws();
      out.push_back(value(depth));
      skip_ws();
      expect_more("',' or ']' in array");
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      if (peek() == ']') {
        ++pos_;
        return Value(std::move(out));
      }
      fail("unexpected " + printable(peek()) + ": expected ',' or ']' in array");
    }
  }

  Value object(int depth) {
    check_depth(depth);
    ++pos_;  // '{'
    Object out;
    skip_ws();
    expect_more("a key or '}'");
    if (peek() == '}') {
      ++pos_;
      return Value(std::move(out));
    }
    for (;;) {
      skip_ws();
      expect_more("an object key");
      if (peek() != '"') fail("unexpected " + printable(peek()) + ": expected a string key");
      const std::size_t key_pos = pos_;
      std::string key = string();
      for (const auto& kv : out) {
        if (kv.first == key) fail_at(key_pos, "duplicate key " + quote(key));
      }
      skip_ws();
      expect_more("':' after the key");
      if (peek() != ':') fail("unexpected " + printable(peek()) + ": expected ':' after the key");
      ++pos_;
      skip_ws();
      Value v = value(depth);
      out.emplace_back(std::move(key), std::move(v));
      skip_ws();
      expect_more("',' or '}' in object");
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      if (peek() == '}') {
        ++pos_;
        return Value(std::move(out));
      }
      fail("unexpected " + printable(peek()) + ": expected ',' or '}' in object");
    }
  }

  unsigned hex4() {
    if (s_.size() - pos_ < 4) fail("truncated \\u escape: expected 4 hex digits");
    unsigned v = 0;
    for (int i = 0; i < 4; ++i) {
      const char c = s_[pos_];
      unsigned d;
      if (c >= '0' && c <= '9') d = static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f') d = static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') d = static_cast<unsigned>(c - 'A' + 10);
      else fail("bad \\u escape: " + printable(c) + " is not a hex digit");
      v = v * 16 + d;
      ++pos_;
    }
    return v;
  }

  static void append_utf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  // Length of the valid UTF-8 sequence starting at pos_ (lead byte >= 0x80), or 0.
  std::size_t utf8_length() const {
    const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s_[pos_ + i]); };
    const std::size_t left = s_.size() - pos_;
    const unsigned char c = b(0);
    const auto cont = [&](std::size_t i) { return i < left && (b(i) & 0xC0) == 0x80; };
    if (c >= 0xC2 && c <= 0xDF) return cont(1) ? 2 : 0;
    if (c >= 0xE0 && c <= 0xEF) {
      if (!cont(1) || !cont(2)) return 0;
      if (c == 0xE0 && b(1) < 0xA0) return 0;   // overlong
      if (c == 0xED && b(1) >= 0xA0) return 0;  // UTF-16 surrogate
      return 3;
    }
    if (c >= 0xF0 && c <= 0xF4) {
      if (!cont(1) || !cont(2) || !cont(3)) return 0;
      if (c == 0xF0 && b(1) < 0x90) return 0;   // overlong
      if (c == 0xF4 && b(1) >= 0x90) return 0;  // > U+10FFFF
      return 4;
    }
    return 0;
  }

  std::string string() {
    const std::size_t start = pos_;
    ++pos_;  // opening quote
    std::string out;
    for (;;) {
      if (at_end()) fail_at(start, "unterminated string");
      const char c = peek();
      const auto u = static_cast<unsigned char>(c);
      if (c == '"') {
        ++pos_;
        return out;
      }
      if (u < 0x20) fail("raw control character (" + printable(c) + ") in string: escape it");
      if (u >= 0x80) {
        const std::size_t n = utf8_length();
        if (n == 0) fail("invalid UTF-8 in string");
        out.append(s_.substr(pos_, n));
        pos_ += n;
        continue;
      }
      if (c != '\\') {
        out += c;
        ++pos_;
        continue;
      }
      ++pos_;
      if (at_end()) fail_at(start, "unterminated string");
      const char e = peek();
      ++pos_;
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          const std::size_t esc = pos_ - 2;
          std::uint32_t cp = hex4();
          if (cp >= 0xDC00 && cp <= 0xDFFF) fail_at(esc, "lone low surrogate in \\u escape");
          if (cp >= 0xD800 && cp <= 0xDBFF) {
            if (s_.substr(pos_, 2) != "\\u") fail_at(esc, "high surrogate not followed by a low surrogate");
            pos_ += 2;
            const std::uint32_t lo = hex4();
            if (lo < 0xDC00 || lo > 0xDFFF) fail_at(esc, "high surrogate not followed by a low surrogate");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          }
          append_utf8(out, cp);
          break;
        }
        default:
          fail_at(pos_ - 2, "invalid escape \\" + std::string(1, e) + " in string");
      }
    }
  }

  Number number() {
    const std::size_t start = pos_;
    auto digit = [&] { return !at_end() && peek() >= '0' && peek() <= '9'; };
    if (peek() == '-') ++pos_;
    if (!digit()) fail("invalid number: expected a digit");
    if (peek() == '0') {
      ++pos_;
      if (digit()) fail_at(start, "invalid number: leading zeros are not allowed");
    } else {
      while (digit()) ++pos_;
    }
    if (!at_end() && peek() == '.') {
      ++pos_;
      if (!digit()) fail("invalid number: expected a digit after '.'");
      while (digit()) ++pos_;
    }
    if (!at_end() && (peek() == 'e' || peek() == 'E')) {
      ++pos_;
      if (!at_end() && (peek() == '+' || peek() == '-')) ++pos_;
      if (!digit()) fail("invalid number: expected a digit in the exponent");
      while (digit()) ++pos_;
    }
    Number n;
    n.text = std::string(s_.substr(start, pos_ - start));
    const char* first = n.text.data();
    const char* last = first + n.text.size();
    const auto r = std::from_chars(first, last, n.value);
    if (r.ec == std::errc::result_out_of_range) {
      fail_at(start, "number " + n.text + " is outside the range of a double");
    }
    if (r.ec != std::errc() || r.ptr != last) fail_at(start, "invalid number " + n.text);
    return n;
  }

  std::string_view s_;
  const ParseOptions& opt_;
  std::size_t pos_ = 0;
};

void write_string(std::string& out, std::string_view s) {
  static const char* hex = "0123456789abcdef";
  out += '"';
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (u < 0x20 || u == 0x7f) {
          out += "\\u00";
          out += hex[u >> 4];
          out += hex[u & 15];
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

void write_value(std::string& out, const Value& v) {
  switch (v.data.index()) {
    case 0: out += "null"; break;
    case 1: out += v.as_bool() ? "true" : "false"; break;
    case 2: {
      const Number& n = v.as_number();
      out += n.text.empty() ? number_text(n.value) : n.text;
      break;
    }
    case 3: write_string(out, v.as_string()); break;
    case 4: {
      out += '[';
      bool first = true;
      for (const auto& e : v.as_array()) {
        if (!first) out += ',';
        first = false;
        write_value(out, e);
      }
      out += ']';
      break;
    }
    case 5: {
      out += '{';
      bool first = true;
      for (const auto& [k, e] : v.as_object()) {
        if (!first) out += ',';
        first = false;
        write_string(out, k);
        out += ':';
        write_value(out, e);
      }
      out += '}';
      break;
    }
  }
}

}  // namespace

Value parse(std::string_view text, const ParseOptions& options) { return Parser(text, options).run(); }

std::string number_text(double d) {
  if (!std::isfinite(d)) return "null";
  if (d == 0) return std::signbit(d) ? "-0" : "0";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, d);
  return std::string(buf, r.ptr);
}

std::string quote(std::string_view s) {
  std::string out;
  write_string(out, s);
  return out;
}

std::string write(const Value& v) {
  std::string out;
  write_value(out, v);
  return out;
}

void write(std::ostream& out, const Value& v) { out << write(v); }

}  // namespace sepax::cli::json
