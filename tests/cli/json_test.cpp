// Tests for src/json/json.cpp: the strict JSON reader and writer.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "json/json.hpp"

using namespace sepax::cli;

namespace {
std::string roundtrip(const std::string& text) { return json::write(json::parse(text)); }
}  // namespace

TEST_CASE("json: canonical texts survive parse + write unchanged", "[json]") {
  const char* texts[] = {
      "null", "true", "false", "0", "-0", "12", "-3.25", "1e+20", "1.5E-7", "12345678901234567890",
      "\"\"", "\"plain\"", "[]", "{}", "[1,2,[3,[4,{}]]]", "{\"a\":1,\"b\":[true,false,null],\"c\":{\"d\":\"e\"}}",
      "\"tab\\tnew\\nquote\\\"back\\\\\"", "\"caf\xc3\xa9\"", "\"\xf0\x9f\x98\x80\""};
  for (const char* t : texts) {
    INFO(t);
    CHECK(roundtrip(t) == t);
  }
}

TEST_CASE("json: whitespace is allowed around tokens and dropped by the writer", "[json]") {
  CHECK(roundtrip(" \t\r\n{ \"a\" : [ 1 , 2 ] , \"b\" : null }\n ") == "{\"a\":[1,2],\"b\":null}");
}

TEST_CASE("json: values and accessors", "[json]") {
  const json::Value v = json::parse(R"({"id": 7, "name": "x", "pts": [[1, 2.5, -3e2]], "ok": true})");
  REQUIRE(v.is_object());
  REQUIRE(v.find("id"));
  CHECK(v.find("id")->as_double() == 7);
  CHECK(v.find("id")->as_number().text == "7");
  CHECK(v.find("name")->as_string() == "x");
  CHECK(v.find("ok")->as_bool());
  CHECK(v.find("missing") == nullptr);
  const auto& p = v.find("pts")->as_array().at(0).as_array();
  CHECK(p.at(0).as_double() == 1);
  CHECK(p.at(1).as_double() == 2.5);
  CHECK(p.at(2).as_double() == -300);
  CHECK(json::parse("[1]").find("x") == nullptr);  // not an object
  CHECK(std::string(json::kind_name(json::parse("[]"))) == "array");
}

TEST_CASE("json: escapes decode to UTF-8, surrogate pairs combine", "[json]") {
  CHECK(json::parse(R"("\u0041\u00e9\u20ac")").as_string() == "A\xc3\xa9\xe2\x82\xac");
  CHECK(json::parse(R"("\ud83d\ude00")").as_string() == "\xf0\x9f\x98\x80");
  CHECK(json::parse(R"("\/\b\f\r")").as_string() == "/\b\f\r");
  CHECK(json::parse(R"("\u0000")").as_string() == std::string(1, '\0'));
}

TEST_CASE("json: the writer escapes control characters and reads them back", "[json]") {
  std::string s;
  for (int c = 0; c < 0x80; ++c) s += static_cast<char>(c);
  s += "\xc3\xa9";
  const std::string text = json::quote(s);
  for (const char c : text) CHECK(static_cast<unsigned char>(c) >= 0x20);
  CHECK(json::parse(text).as_string() == s);
}

TEST_CASE("json: number_text is the shortest text that reads back as the same double", "[json]") {
  std::mt19937_64 rng(12345);
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t bits = rng();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) continue;
    const std::string t = json::number_text(d);
    const json::Value v = json::parse(t);
    REQUIRE(v.is_number());
    REQUIRE(v.as_double() == d);
    REQUIRE(std::signbit(v.as_double()) == std::signbit(d));
  }
  CHECK(json::number_text(0.1) == "0.1");
  CHECK(json::number_text(std::numeric_limits<double>::denorm_min()) == "5e-324");
  CHECK(json::number_text(std::numeric_limits<double>::quiet_NaN()) == "null");
  CHECK(json::number_text(std::numeric_limits<double>::infinity()) == "null");
  CHECK(json::write(json::Value(-std::numeric_limits<double>::infinity())) == "null");
}

TEST_CASE("json: numbers made in code are written from their value, parsed ones from their text", "[json]") {
  CHECK(json::write(json::Value(json::Array{1, 2.5, -0.0, 1e300})) == "[1,2.5,-0,1e+300]");
  CHECK(json::write(json::parse("[1.50, 2E3]")) == "[1.50,2E3]");
  CHECK(json::parse("1.50").as_double() == 1.5);
}

namespace {
struct Bad {
  const char* text;
  std::size_t line, column;
  const char* problem;  // a substring of the message
};
}  // namespace

TEST_CASE("json: malformed input is rejected with line, column and the problem", "[json]") {
  const Bad cases[] = {
      {"", 1, 1, "empty input"},
      {"   ", 1, 4, "empty input"},
      {"{", 1, 2, "unexpected end of input"},
      {"[1,]", 1, 4, "expected a JSON value"},
      {"[1 2]", 1, 4, "expected ',' or ']'"},
      {"{\"a\" 1}", 1, 6, "expected ':'"},
      {"{\"a\":1,}", 1, 8, "expected a string key"},
      {"{a:1}", 1, 2, "expected a string key"},
      {"01", 1, 1, "leading zeros"},
      {"1.", 1, 3, "digit after '.'"},
      {"-", 1, 2, "expected a digit"},
      {"1e", 1, 3, "exponent"},
      {"+1", 1, 1, "expected a JSON value"},
      {"NaN", 1, 1, "expected a JSON value"},
      {"Infinity", 1, 1, "expected a JSON value"},
      {"tru", 1, 1, "expected 'true'"},
      {"nul", 1, 1, "expected 'null'"},
      {"\"abc", 1, 1, "unterminated string"},
      {"\"a\\x\"", 1, 3, "invalid escape"},
      {"\"\\u12g4\"", 1, 6, "hex digit"},
      {"\"\\u12\"", 1, 4, "hex digit"},
      {"\"\\ud800\"", 1, 2, "high surrogate"},
      {"\"\\ud800\\u0041\"", 1, 2, "high surrogate"},
      {"\"\\udc00\"", 1, 2, "lone low surrogate"},
      {"\"a\tb\"", 1, 3, "raw control character"},
      {"\"\xff\"", 1, 2, "invalid UTF-8"},
      {"\"\xc0\xaf\"", 1, 2, "invalid UTF-8"},
      {"\"\xed\xa0\x80\"", 1, 2, "invalid UTF-8"},
      {"\"\xe2\x82\"", 1, 2, "invalid UTF-8"},
      {"{\"a\":1,\"a\":2}", 1, 8, "duplicate key"},
      {"1 2", 1, 3, "after the JSON value"},
      {"[1]x", 1, 4, "after the JSON value"},
      {"1e400", 1, 1, "outside the range"},
      {"-1e400", 1, 1, "outside the range"},
      {"[\n1,\n  ]", 3, 3, "expected a JSON value"},
  };
  for (const Bad& b : cases) {
    INFO("input: " << b.text);
    try {
      (void)json::parse(b.text);
      FAIL("accepted malformed JSON");
    } catch (const json::ParseError& e) {
      CHECK(e.line() == b.line);
      CHECK(e.column() == b.column);
      CHECK_THAT(e.what(), Catch::Contains(b.problem));
      CHECK_THAT(e.what(), Catch::StartsWith("line " + std::to_string(b.line) + ", column "));
    }
  }
}

TEST_CASE("json: nesting depth is limited, so hostile input cannot exhaust the stack", "[json]") {
  const auto nested = [](int depth) { return std::string(static_cast<std::size_t>(depth), '[') + std::string(static_cast<std::size_t>(depth), ']'); };
  json::ParseOptions opt;
  opt.max_depth = 64;
  CHECK_NOTHROW(json::parse(nested(64), opt));
  CHECK_THROWS_WITH(json::parse(nested(65), opt), Catch::Contains("nesting deeper than 64"));
  CHECK_THROWS_AS(json::parse(nested(1000000)), json::ParseError);
  std::string objs;
  for (int i = 0; i < 100; ++i) objs += "{\"k\":";
  objs += "1";
  objs += std::string(100, '}');
  CHECK_THROWS_WITH(json::parse(objs), Catch::Contains("nesting deeper"));
}
