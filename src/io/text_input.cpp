// src/io/text_input.cpp -- see text_input.hpp.
#include "io/text_input.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include <sepax/error.hpp>

namespace sepax::cli::io {

void fail_at(const std::string& file, std::size_t line, const std::string& what) {
  throw InvalidInput(ErrorCode::Parse, file + ":" + std::to_string(line) + ": " + what);
}

std::string lower_ascii(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool LineReader::next(std::string& line) {
  if (!std::getline(in_, line)) {
    if (in_.bad()) fail_at(file_, line_ + 1, "read error");
    return false;
  }
  ++line_;
  // a UTF-8 byte order mark before the first line (editors on Windows write one) is not content
  if (line_ == 1 && line.starts_with(kUtf8Bom)) line.erase(0, kUtf8Bom.size());
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.find('\0') != std::string::npos) fail("NUL byte in text (is this a binary file?)");
  return true;
}

std::vector<std::string_view> tokens(std::string_view line, bool commas_separate) {
  const auto hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> out;
  std::size_t i = 0;
  const auto sep = [&](char c) {
    return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r' || (commas_separate && c == ',');
  };
  while (i < line.size()) {
    while (i < line.size() && sep(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !sep(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::string shown(std::string_view token) {
  std::string s;
  for (const char c : token.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(c);
    s += (u >= 0x20 && u < 0x7f) ? c : '?';
  }
  if (token.size() > 40) s += "...";
  return "'" + s + "'";
}

std::optional<double> quick_double(std::string_view t) {
  double v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v, std::chars_format::general);
  if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
    return std::nullopt;
  return v;
}

std::optional<long long> quick_integer(std::string_view t) {
  long long v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

double parse_double(const TextPlace& reader, std::string_view token, const std::string& what) {
  std::string_view t = token;
  if (!t.empty() && t[0] == '+') t.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v, std::chars_format::general);
  if (t.empty() || (!t.empty() && t[0] == '+')) reader.fail("bad number " + shown(token) + " for " + what);
  if (r.ec == std::errc::result_out_of_range) {
    reader.fail("number " + shown(token) + " for " + what + " is out of the range of a double");
  }
  if (r.ec != std::errc() || r.ptr != t.data() + t.size()) {
    reader.fail("bad number " + shown(token) + " for " + what);
  }
  if (!std::isfinite(v)) reader.fail(what + " is " + shown(token) + ": NaN and infinity are not allowed");
  return v;
}

long long parse_integer(const TextPlace& reader, std::string_view token, const std::string& what) {
  std::string_view t = token;
  if (!t.empty() && t[0] == '+') t.remove_prefix(1);
  long long v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || t[0] == '+') reader.fail("bad integer " + shown(token) + " for " + what);
  if (r.ec == std::errc::result_out_of_range) reader.fail(what + " " + shown(token) + " is too large");
  if (r.ec != std::errc() || r.ptr != t.data() + t.size()) {
    reader.fail("bad integer " + shown(token) + " for " + what);
  }
  return v;
}

long long parse_count(const TextPlace& reader, std::string_view token, const std::string& what,
                      long long max) {
  const long long v = parse_integer(reader, token, what);
  if (v < 0) reader.fail(what + " is negative (" + std::to_string(v) + ")");
  if (v > max)
    reader.fail(what + " " + std::to_string(v) + " is too large (at most " + std::to_string(max) + ")");
  return v;
}

}  // namespace sepax::cli::io
