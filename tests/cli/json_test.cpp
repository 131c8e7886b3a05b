// Tests for src/json/json.cpp: nlohmann-json with what the batch format adds
// (duplicate keys, depth limit, line/column errors, numbers kept as written).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "json/json.hpp"

using namespace sepax::cli;

TEST_CASE("json: compact output keeps key order; integral doubles are written without a fraction", "[json]") {
  CHECK(json::write(json::parse(" \t\r\n{ \"b\" : [ 1 , 2 ] , \"a\" : null }\n ")) ==
        "{\"b\":[1,2],\"a\":null}");
  CHECK(json::write(json::Value::array({json::number(1), json::number(2.5), json::number(1e300)})) ==
        "[1,2.5,1e+300]");
  CHECK(json::write(json::number(std::numeric_limits<double>::infinity())) == "null");
  CHECK(json::write(json::number(std::numeric_limits<double>::quiet_NaN())) == "null");
  CHECK(std::signbit(json::parse(json::write(json::number(-0.0))).get<double>()));
}

TEST_CASE("json: numbers of the top-level object keep their text as written", "[json]") {
  const json::Document d =
      json::parse_document(R"({"id": -0.5e1, "n": 12345678901234567890, "z": -0, "x": [1.50]})");
  CHECK(d.number_text.at("id") == "-0.5e1");
  CHECK(d.number_text.at("n") == "12345678901234567890");
  CHECK(d.number_text.at("z") == "-0");
  CHECK(d.number_text.count("x") == 0);  // not a number member
  CHECK(json::parse_document("{\"id\":7}").number_text.at("id") == "7");
  CHECK(d.value.at("id").get<double>() == -5);
}

TEST_CASE("json: escapes decode to UTF-8, surrogate pairs combine", "[json]") {
  CHECK(json::parse(R"("\u0041\u00e9\u20ac")").get<std::string>() == "A\xc3\xa9\xe2\x82\xac");
  CHECK(json::parse(R"("\ud83d\ude00")").get<std::string>() == "\xf0\x9f\x98\x80");
  std::string s;
  for (int c = 0; c < 0x80; ++c) s += static_cast<char>(c);
  const std::string text = json::quote(s);
  for (const char c : text) CHECK(static_cast<unsigned char>(c) >= 0x20);
  CHECK(json::parse(text).get<std::string>() == s);
}

TEST_CASE("json: number_text is the shortest text that reads back as the same double", "[json]") {
  std::mt19937_64 rng(12345);
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t bits = rng();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) continue;
    const json::Value v = json::parse(json::number_text(d));
    REQUIRE(v.is_number());
    REQUIRE(v.get<double>() == d);
    REQUIRE(std::signbit(v.get<double>()) == std::signbit(d));
  }
  CHECK(json::number_text(0.1) == "0.1");
  CHECK(json::number_text(std::numeric_limits<double>::denorm_min()) == "5e-324");
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
      {"{", 1, 2, "end of input"},
      {"[1 2]", 1, 4, "expected ']'"},
      {"01", 1, 2, ""},
      {"NaN", 1, 1, ""},
      {"\"\\ud800\"", 1, 1, "surrogate"},
      {"\"a\tb\"", 1, 1, "control character"},
      {"\"\xff\"", 1, 1, "UTF-8"},
      {"{\"a\":1,\"a\":2}", 1, 8, "duplicate key \"a\""},
      {"{\"a\":{\"b\\\"\":1,\"b\\\"\":2}}", 1, 15, "duplicate key"},
      {"1 2", 1, 3, "expected end of input"},
      {"1e400", 1, 1, "outside the range of a double"},
      {"[\n1,\n  ]", 3, 3, ""},
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

TEST_CASE("json: nesting depth is limited", "[json]") {
  const auto nested = [](int depth) {
    return std::string(static_cast<std::size_t>(depth), '[') +
           std::string(static_cast<std::size_t>(depth), ']');
  };
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
  CHECK(std::string(json::kind_name(json::parse("[]"))) == "array");
}
