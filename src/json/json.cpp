// src/json/json.cpp -- see json.hpp.
#include "json/json.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <iterator>
#include <vector>

namespace sepax::cli::json {

ParseError::ParseError(std::size_t line, std::size_t column, const std::string& problem)
    : std::runtime_error("line " + std::to_string(line) + ", column " + std::to_string(column) + ": " +
                         problem),
      line_(line),
      column_(column),
      problem_(problem) {}

namespace {

// A byte iterator that counts the bytes nlohmann's reader has taken, so that
// the SAX handler below knows where in the text each event happens.
class CountingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator() = default;
  CountingIterator(const char* p, std::size_t* consumed) : p_(p), consumed_(consumed) {}
  reference operator*() const { return *p_; }
  CountingIterator& operator++() {
    ++p_;
    if (consumed_) ++*consumed_;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator t = *this;
    ++*this;
    return t;
  }
  bool operator==(const CountingIterator& o) const { return p_ == o.p_; }
  bool operator!=(const CountingIterator& o) const { return p_ != o.p_; }

 private:
  const char* p_ = nullptr;
  std::size_t* consumed_ = nullptr;
};

bool number_char(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// nlohmann's escaping of a token for messages (lexer::get_token_string):
// control characters become "<U+00XX>".
std::size_t escaped_length(char c) { return static_cast<unsigned char>(c) <= 0x1F ? 8 : 1; }

// Builds an ordered_json document from nlohmann's SAX events (as its own DOM
// builder does), rejecting duplicate keys and deep nesting, and keeping the
// text of top-level member numbers.
class Builder {
 public:
  using number_integer_t = Value::number_integer_t;
  using number_unsigned_t = Value::number_unsigned_t;
  using number_float_t = Value::number_float_t;
  using string_t = Value::string_t;
  using binary_t = Value::binary_t;

  Builder(std::string_view text, const ParseOptions& opt, Document& doc)
      : text_(text), opt_(opt), doc_(doc) {}

  std::size_t consumed = 0;  // bytes taken by the reader so far

  bool null() { return put(nullptr); }
  bool boolean(bool b) { return put(b); }
  bool number_integer(number_integer_t v) { return put_number(v); }
  bool number_unsigned(number_unsigned_t v) { return put_number(v); }
  bool number_float(number_float_t v, const string_t& s) {
    record_number_text(s);
    return put(v);
  }
  bool string(string_t& s) { return put(std::move(s)); }
  bool binary(binary_t&) { return fail_at(consumed, "binary values are not JSON"); }

  bool start_object(std::size_t) { return open(Value::object()); }
  bool key(string_t& k) {
    Value& obj = *stack_.back();
    if (obj.contains(k)) return fail_at(key_start(), "duplicate key " + quote(k));
    key_ = std::move(k);
    return true;
  }
  bool end_object() {
    stack_.pop_back();
    return true;
  }
  bool start_array(std::size_t) { return open(Value::array()); }
  bool end_array() {
    stack_.pop_back();
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& ex) {
    // position counts the bytes read, the end of input included; the token
    // in error (escaped in last_token) ends there.
    const std::size_t end = std::min(position, text_.size());
    std::size_t len = 0, start = end;
    if (position <= text_.size())  // at the end of input, the column is one past the last byte
      while (start > 0 && len < last_token.size()) len += escaped_length(text_[--start]);
    // The reader's token text may begin with the separators and whitespace before the token.
    while (start + 1 < end && std::string_view(" \t\r\n,:").find(text_[start]) != std::string_view::npos)
      ++start;
    // A structural character in error is its own token.
    if (end > 0 && position <= text_.size() &&
        std::string_view("[]{}:,").find(text_[end - 1]) != std::string_view::npos)
      start = end - 1;
    return fail_at(start, problem(ex, last_token));
  }

  [[noreturn]] void raise() const { throw ParseError(error_line_, error_column_, error_problem_); }
  bool failed() const { return failed_; }

 private:
  static std::string problem(const nlohmann::detail::exception& ex, const std::string& token) {
    if (ex.id == 406) return "number " + token + " is outside the range of a double";
    // "[json.exception.parse_error.101] parse error at line 1, column 3: syntax error while parsing value - ..."
    std::string m = ex.what();
    if (const auto p = m.find(": "); p != std::string::npos && m.compare(0, 16, "[json.exception.") == 0)
      m = m.substr(p + 2);
    // "syntax error while parsing value - unexpected ..." -> "unexpected ..."
    if (const auto d = m.find(" - "); m.compare(0, 13, "syntax error ") == 0 && d != std::string::npos)
      m = m.substr(d + 3);
    return m;
  }

  bool fail_at(std::size_t pos, const std::string& what) {
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < pos && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    }
    failed_ = true;
    error_line_ = line;
    error_column_ = pos - line_start + 1;
    error_problem_ = what;
    return false;
  }

  // The opening quote of the key just read (the reader stopped at its closing quote).
  std::size_t key_start() const {
    std::size_t i = consumed >= 2 ? consumed - 2 : 0;
    for (;; --i) {
      if (text_[i] == '"') {
        std::size_t backslashes = 0;
        while (i > backslashes && text_[i - 1 - backslashes] == '\\') ++backslashes;
        if (backslashes % 2 == 0) return i;
      }
      if (i == 0) return 0;
    }
  }

  template <class N>
  bool put_number(N v) {
    // The reader has taken the number and, unless it ends the input, the byte after it.
    std::size_t end = std::min(consumed, text_.size());
    if (end > 0 && !number_char(text_[end - 1])) --end;
    std::size_t start = end;
    while (start > 0 && number_char(text_[start - 1])) --start;
    record_number_text(std::string(text_.substr(start, end - start)));
    return put(v);
  }

  void record_number_text(const std::string& s) {
    if (stack_.size() == 1 && stack_.back()->is_object()) doc_.number_text[key_] = s;
  }

  bool open(Value v) {
    if (static_cast<int>(stack_.size()) >= opt_.max_depth)
      return fail_at(consumed - 1, "nesting deeper than " + std::to_string(opt_.max_depth) + " levels");
    Value* slot = place(std::move(v));
    stack_.push_back(slot);
    return true;
  }

  template <class V>
  bool put(V&& v) {
    place(Value(std::forward<V>(v)));
    return true;
  }

  Value* place(Value v) {
    if (stack_.empty()) {
      doc_.value = std::move(v);
      return &doc_.value;
    }
    Value& top = *stack_.back();
    if (top.is_array()) {
      top.push_back(std::move(v));
      return &top.back();
    }
    Value& slot = top[key_];
    slot = std::move(v);
    return &slot;
  }

  std::string_view text_;
  const ParseOptions& opt_;
  Document& doc_;
  std::vector<Value*> stack_;
  std::string key_;
  bool failed_ = false;
  std::size_t error_line_ = 0, error_column_ = 0;
  std::string error_problem_;
};

}  // namespace

Document parse_document(std::string_view text, const ParseOptions& options) {
  Document doc;
  Builder b(text, options, doc);
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw ParseError(
        1 + static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')),
        text.size() - (text.rfind('\n') == std::string_view::npos ? 0 : text.rfind('\n') + 1) + 1,
        "empty input: expected a JSON value");
  }
  const CountingIterator first(text.data(), &b.consumed), last(text.data() + text.size(), nullptr);
  const bool ok = Value::sax_parse(first, last, &b, nlohmann::detail::input_format_t::json, /*strict=*/true);
  if (!ok || b.failed()) b.raise();
  return doc;
}

Value parse(std::string_view text, const ParseOptions& options) {
  return parse_document(text, options).value;
}

Value number(double d) {
  if (!std::isfinite(d)) return nullptr;
  constexpr double kExactIntegers = 9007199254740992.0;  // 2^53
  if (d == std::trunc(d) && std::fabs(d) < kExactIntegers && !(d == 0 && std::signbit(d)))
    return static_cast<std::int64_t>(d);
  return d;
}

std::string write(const Value& v) {
  return v.dump(-1, ' ', false, nlohmann::detail::error_handler_t::replace);
}

std::string number_text(double d) {
  if (!std::isfinite(d)) return "null";
  if (d == 0) return std::signbit(d) ? "-0" : "0";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, d);
  return std::string(buf, r.ptr);
}

std::string quote(std::string_view s) {
  return Value(std::string(s)).dump(-1, ' ', false, nlohmann::detail::error_handler_t::replace);
}

const char* kind_name(const Value& v) {
  switch (v.type()) {
    case Value::value_t::null:
      return "null";
    case Value::value_t::boolean:
      return "boolean";
    case Value::value_t::number_integer:
    case Value::value_t::number_unsigned:
    case Value::value_t::number_float:
      return "number";
    case Value::value_t::string:
      return "string";
    case Value::value_t::array:
      return "array";
    case Value::value_t::object:
      return "object";
    default:
      return "?";
  }
}

}  // namespace sepax::cli::json
