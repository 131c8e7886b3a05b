// Tests for src/commands/batch.cpp: JSON lines in, JSON lines out.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "commands/batch.hpp"
#include "commands/sat_runner.hpp"
#include "io/shape_source.hpp"
#include "json/json.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

// "[[x,y,z],...]" for the vertices of a built-in shape moved by t.
std::string points_of(const char* spec, double tx, double ty, double tz) {
  const auto d = io::builtin_shape(spec);
  json::Value pts = json::Value::array();
  for (const auto& v : d.vertices) pts.push_back(json::Value::array({v[0] + tx, v[1] + ty, v[2] + tz}));
  return json::write(pts);
}

// The text of the last run_lines output (ids are checked as written there).
std::string& last_output() {
  static std::string s;
  return s;
}

std::vector<json::Value> run_lines(const std::string& input, BatchSummary* sum = nullptr,
                                   const RunConfig& cfg = RunConfig{}) {
  std::istringstream in(input);
  std::ostringstream out;
  BatchOptions opt;
  opt.cfg = cfg;
  const BatchSummary s = run_batch(in, out, opt);
  last_output() = out.str();
  if (sum) *sum = s;
  std::vector<json::Value> lines;
  std::istringstream back(out.str());
  std::string line;
  while (std::getline(back, line)) lines.push_back(json::parse(line));  // every output line is valid JSON
  return lines;
}

std::string error_of(const json::Value& v) {
  REQUIRE(v.contains("error"));
  return v.at("error").get<std::string>();
}

}  // namespace

TEST_CASE("batch: bad lines give an error object naming the problem and the run goes on", "[batch]") {
  const std::string good_pts = "[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]";
  const struct {
    std::string line;
    const char* id;  // expected id as JSON text
    const char* problem;
  } cases[] = {
      {"{\"id\": 1, \"a\": " + good_pts + ", \"b\": ", "null",
       "invalid JSON at column 56: unexpected end of input"},
      {"not json", "null", "invalid JSON at column 1"},
      {"[1, 2]", "null", "expected a JSON object, got array"},
      {"{\"a\": " + good_pts + ", \"b\": " + good_pts + "}", "null", "missing key \"id\""},
      {"{\"id\": [1], \"a\": " + good_pts + ", \"b\": " + good_pts + "}", "null",
       "\"id\" must be a number or a string, got array"},
      {"{\"id\": \"x\", \"b\": " + good_pts + "}", "\"x\"", "missing key \"a\""},
      {"{\"id\": 7, \"a\": " + good_pts + "}", "7", "missing key \"b\""},
      {"{\"id\": 7, \"a\": {}, \"b\": " + good_pts + "}", "7", "a: expected an array of points"},
      {"{\"id\": 7, \"a\": [], \"b\": " + good_pts + "}", "7", "a: no points"},
      {"{\"id\": 7, \"a\": [[0,0]], \"b\": " + good_pts + "}", "7", "a[0]: expected a point [x, y, z]"},
      {"{\"id\": 7, \"a\": " + good_pts + ", \"b\": [[0,0,0],[1,\"0\",0]]}", "7",
       "b[1]: coordinate 1 is string, not a number"},
      {"{\"id\": 7, \"a\": " + good_pts + ", \"b\": [[0,0,0],[1,null,0]]}", "7", "coordinate 1 is null"},
      {"{\"id\": 1e999, \"a\": [], \"b\": []}", "null", "outside the range of a double"},
  };
  std::string input;
  for (const auto& c : cases) input += c.line + "\n";
  BatchSummary sum;
  const auto out = run_lines(input, &sum);
  REQUIRE(out.size() == std::size(cases));
  CHECK(sum.queries == std::size(cases));
  CHECK(sum.errors == std::size(cases));
  for (std::size_t i = 0; i < out.size(); ++i) {
    INFO("line " << i + 1 << ": " << cases[i].line);
    CHECK(json::write(out[i].at("id")) == cases[i].id);
    CHECK_THAT(last_output(), Catch::Contains(std::string("{\"id\":") + cases[i].id + ","));
    const std::string e = error_of(out[i]);
    CHECK_THAT(e, Catch::StartsWith("line " + std::to_string(i + 1) + ": "));
    CHECK_THAT(e, Catch::Contains(cases[i].problem));
    CHECK_FALSE(out[i].contains("overlap"));
  }
}

TEST_CASE("batch: good lines are answered like query, ids echoed exactly as written", "[batch]") {
  if (!hull_builder_available()) {
    WARN("this build has no hull builder: test not run");
    return;
  }
  const std::string cube_at_origin = points_of("cube", 0, 0, 0);
  const std::string input =
      "{\"id\": 12345678901234567890, \"a\": " + cube_at_origin + ", \"b\": " + points_of("cube", 2.5, 0, 0) +
      "}\n"
      "\n"  // blank lines are skipped
      "   \r\n"
      "{\"b\": " +
      points_of("tetra", 0.5, 0.25, 0) + ", \"id\": \"overlapping \\\"pair\\\"\", \"a\": " + cube_at_origin +
      ", \"note\": \"extra keys are ignored\"}\r\n"
      "{\"id\": -0.5e1, \"a\": [[0,0,0],[1,1,1],[2,2,2]], \"b\": " +
      cube_at_origin +
      "}\n"
      "{\"id\": 3, \"a\": " +
      points_of("prism:6", 0, 0, 0) + ", \"b\": " + points_of("prism:6", 0.3, 0.1, 2.0) +
      "}";  // no final newline
  BatchSummary sum;
  const auto out = run_lines(input, &sum);
  REQUIRE(out.size() == 4);
  CHECK(sum.queries == 4);
  CHECK(sum.errors == 1);

  CHECK(json::write(out[0].at("id")) == "12345678901234567890");
  CHECK_FALSE(out[0].at("overlap").get<bool>());
  CHECK(out[0].at("separation").get<double>() == 0.5);
  CHECK(json::write(out[0].at("normal")) == "[1,0,0]");
  CHECK(out[0].at("feature").at("type").get<std::string>() == "faceA");

  CHECK(out[1].at("id").get<std::string>() == "overlapping \"pair\"");
  CHECK(out[1].at("overlap").get<bool>());
  CHECK(out[1].at("separation").get<double>() < 0);

  CHECK_THAT(last_output(), Catch::Contains("{\"id\":-0.5e1,\"error\":"));  // as written
  CHECK_THAT(error_of(out[2]), Catch::Contains("line 5: a: "));

  // the same query through run_sat on the same point sets
  const auto& f = out[3].at("feature");
  io::ShapeData a, b;
  a.kind = b.kind = io::ShapeData::Kind::Points;
  a.vertices = io::builtin_shape("prism:6").vertices;
  for (const auto& v : a.vertices) b.vertices.push_back(v + Vec3<double>(0.3, 0.1, 2.0));
  const RunOutcome r = run_sat(a, b, nullptr, RunConfig{});
  CHECK(out[3].at("overlap").get<bool>() == r.overlap);
  CHECK(out[3].at("separation").get<double>() == r.separation);
  CHECK(f.at("type").get<std::string>() == type_name(r.feature.type));
  CHECK(f.at("a").get<double>() == r.feature.a);
  CHECK(f.at("b").get<double>() == r.feature.b);
  CHECK(json::write(out[3].at("normal")) ==
        json::write(json::Value::array(
            {json::number(r.normal[0]), json::number(r.normal[1]), json::number(r.normal[2])})));
  // output keys, in order
  std::vector<std::string> keys;
  for (const auto& kv : out[3].items()) keys.push_back(kv.key());
  CHECK(keys == std::vector<std::string>{"id", "overlap", "separation", "feature", "normal", "manifold"});
}

TEST_CASE("batch: every number type answers, exact and double agree on clear cases", "[batch]") {
  if (!hull_builder_available()) {
    WARN("this build has no hull builder: test not run");
    return;
  }
  std::string input;
  for (int i = 0; i < 6; ++i) {
    const double t = 1.05 + 0.5 * i;  // 1.05 .. 3.55: overlapping and separated, never touching
    input += "{\"id\": " + std::to_string(i) + ", \"a\": " + points_of("tetra", 0, 0, 0) +
             ", \"b\": " + points_of("cube", t, 0.1, -0.2) + "}\n";
  }
  RunConfig exact, fl;
  exact.number = NumberKind::Exact;
  fl.number = NumberKind::Float;
  const auto d = run_lines(input);
  const auto e = run_lines(input, nullptr, exact);
  const auto f = run_lines(input, nullptr, fl);
  REQUIRE(d.size() == 6);
  REQUIRE(e.size() == 6);
  REQUIRE(f.size() == 6);
  for (std::size_t i = 0; i < 6; ++i) {
    INFO(i);
    CHECK(d[i].at("overlap").get<bool>() == e[i].at("overlap").get<bool>());
    CHECK(f[i].at("overlap").get<bool>() == e[i].at("overlap").get<bool>());
    CHECK(d[i].at("separation").get<double>() == Approx(e[i].at("separation").get<double>()).margin(1e-12));
  }
}

TEST_CASE("batch: --jobs N gives the same output, line for line, as --jobs 1", "[batch][jobs]") {
  std::string input;
  for (int i = 0; i < 40; ++i) {
    const double t = 0.9 + 0.07 * i;
    input += "{\"id\": " + std::to_string(i) + ".50, \"a\": " + points_of("prism:5", 0, 0, 0) +
             ", \"b\": " + points_of("tetra", t, 0.1, -0.2) + "}\n";
    if (i % 7 == 3) input += "{\"id\": " + std::to_string(i) + ", \"a\": [[0,0,0]], \"b\": []}\n\n";
  }
  std::string outputs[3];
  BatchSummary sums[3];
  const int jobs[3] = {1, 3, 0};
  for (int k = 0; k < 3; ++k) {
    std::istringstream in(input);
    std::ostringstream out;
    BatchOptions opt;
    opt.jobs = jobs[k];
    sums[k] = run_batch(in, out, opt);
    outputs[k] = out.str();
  }
  CHECK(sums[0].queries == 46);
  CHECK(sums[0].errors == 6);
  CHECK_THAT(outputs[0], Catch::Contains("{\"id\":0.50,\"overlap\":"));
  for (int k = 1; k < 3; ++k) {
    INFO("jobs " << jobs[k]);
    CHECK(outputs[k] == outputs[0]);
    CHECK(sums[k].queries == sums[0].queries);
    CHECK(sums[k].errors == sums[0].errors);
  }
}
