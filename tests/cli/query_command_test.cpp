// Tests for src/commands/query_command.cpp (and the output formats of
// query_output.cpp): option parsing, text and JSON output, exit statuses.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "cli/cli_test_support.hpp"
#include "commands/query_command.hpp"
#include "commands/sat_runner.hpp"
#include "io/shape_source.hpp"
#include "json/json.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

using Run = test::CommandRun;
using test::temp_file;

using test::info;
using test::query;

}  // namespace

TEST_CASE("query: text output reports overlap, separation, feature, normal and stats", "[query]") {
  const Run r = query({"cube", "cube", "--pose", "2.5", "0", "0"});
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK_THAT(r.out, Catch::Contains("overlap:    no\n"));
  CHECK_THAT(r.out, Catch::Contains("separation: 0.5\n"));
  CHECK_THAT(r.out, Catch::Contains("feature:    faceA: face "));
  CHECK_THAT(r.out, Catch::Contains("normal:     1 0 0"));
  CHECK_THAT(r.out, Catch::Contains("arithmetic: double, algorithm gauss, plain policy"));
  CHECK_THAT(r.out, Catch::Contains("stats:      12 face axes, 144 edge pairs"));
  CHECK_THAT(r.out, Catch::Contains("A:          cube (8 vertices, 12 edges, 6 faces)"));
  const Run o = query({"cube", "tetra", "--pose", "0.5", "0", "0", "--number", "exact"});
  CHECK(o.status == 0);
  CHECK_THAT(o.out, Catch::Contains("overlap:    yes\n"));
}

TEST_CASE("query: --json prints one object whose values match run_sat", "[query]") {
  const std::vector<std::vector<std::string>> arg_sets = {
      {"prism:5", "tetra", "--pose", "1.2", "0.3", "-0.4", "0.9", "0.1", "-0.3", "0.2", "--json"},
      {"--json", "box:1,0.5,0.25", "polygon:6", "--number", "exact", "--algorithm", "brute", "--pose", "0",
       "0", "0.75"},
      {"triangle", "cube", "--number=float", "--algorithm=gauss", "--json", "--pose", "0.2", "0.2", "1.5",
       "1", "1", "0", "0"},
  };
  for (const auto& args : arg_sets) {
    INFO(args[0] << " " << args[1]);
    const Run r = query(args);
    REQUIRE(r.status == 0);
    REQUIRE(r.out.back() == '\n');
    REQUIRE(r.out.find('\n') == r.out.size() - 1);  // one line
    const json::Value v = json::parse(r.out);
    std::vector<std::string> keys;
    for (const auto& kv : v.items()) keys.push_back(kv.key());
    CHECK(keys == std::vector<std::string>{"overlap", "separation", "feature", "normal", "number",
                                           "algorithm", "policy", "stats", "manifold"});
    // recompute with the library entry point
    RunConfig cfg;
    std::optional<Pose> pose;
    std::vector<std::string> shapes;
    for (std::size_t i = 0; i < args.size(); ++i) {
      if (args[i] == "--number")
        cfg.number = *parse_number_kind(args[++i]);
      else if (args[i] == "--number=float")
        cfg.number = NumberKind::Float;
      else if (args[i] == "--algorithm")
        cfg.algorithm = *parse_algorithm_kind(args[++i]);
      else if (args[i] == "--pose") {
        double x[7] = {0, 0, 0, 1, 0, 0, 0};
        int n = 0;
        const auto is_number = [](const std::string& t) { return !t.empty() && !t.starts_with("--"); };
        while (n < 7 && i + 1 < args.size() && is_number(args[i + 1])) x[n++] = std::stod(args[++i]);
        pose = Pose::make(Vec3<double>(x[0], x[1], x[2]), {x[3], x[4], x[5], x[6]});
      } else if (!args[i].starts_with("--"))
        shapes.push_back(args[i]);
    }
    const RunOutcome ref =
        run_sat(io::load_shape(shapes[0]), io::load_shape(shapes[1]), pose ? &*pose : nullptr, cfg);
    CHECK(v.at("overlap").get<bool>() == ref.overlap);
    CHECK(v.at("separation").get<double>() == ref.separation);
    CHECK(v.at("feature").at("type").get<std::string>() == type_name(ref.feature.type));
    // the contact manifold: same kind and the same points, ids and separations
    const json::Value& m = v.at("manifold");
    CHECK(m.at("kind").get<std::string>() == ref.manifold.kind);
    REQUIRE(m.at("points").size() == ref.manifold.points.size());
    for (std::size_t k = 0; k < ref.manifold.points.size(); ++k) {
      const json::Value& p = m.at("points")[k];
      CHECK(p.at("id").get<std::string>() == ref.manifold.points[k].id);
      CHECK(p.at("separation").get<double>() == ref.manifold.points[k].separation);
      CHECK(p.at("position")[2].get<double>() == ref.manifold.points[k].position[2]);
    }
    CHECK(v.at("feature").at("a").get<double>() == ref.feature.a);
    CHECK(v.at("feature").at("b").get<double>() == ref.feature.b);
    const auto& n = v.at("normal");
    REQUIRE(n.size() == 3);
    for (int c = 0; c < 3; ++c) CHECK(n[static_cast<std::size_t>(c)].get<double>() == ref.normal[c]);
    CHECK(v.at("number").get<std::string>() == name(cfg.number));
    CHECK(v.at("algorithm").get<std::string>() == name(cfg.algorithm));
    CHECK(v.at("policy").get<std::string>() == "plain");
    CHECK(v.at("stats").at("face_axes").get<double>() == static_cast<double>(ref.stats.face_axes));
  }
}

TEST_CASE("query: usage errors exit 2 with a message", "[query]") {
  const struct {
    std::vector<std::string> args;
    const char* problem;
  } cases[] = {
      {{}, "expected two shapes A and B, got 0"},
      {{"cube"}, "expected two shapes A and B, got 1"},
      {{"cube", "cube", "tetra"}, "got 3"},
      {{"cube", "cube", "--frobnicate"}, "unknown option '--frobnicate'"},
      {{"cube", "cube", "--number"}, "--number needs a value"},
      {{"cube", "cube", "--number", "quad"}, "unknown number type 'quad'"},
      {{"cube", "cube", "--algorithm", "fast"}, "unknown algorithm 'fast'"},
      {{"cube", "cube", "--pose", "1", "2"}, "--pose needs 3 numbers"},
      {{"cube", "cube", "--pose", "1", "x", "2"}, "'x' is not a number"},
      {{"cube", "cube", "--pose", "1", "2", "3", "1", "0"}, "needs 4 numbers"},
      {{"cube", "cube", "--pose", "1", "2", "3", "0", "0", "0", "0"}, "quaternion is zero"},
      {{"cube", "cube", "--pose", "1", "2", "3", "1", "0", "0", "0", "5"}, "--pose takes 3 numbers"},
      {{"cube", "--pose", "1", "2", "3", "1", "0", "0", "0", "5", "6", "cube"},
       "or 7 (tx ty tz qw qx qy qz), not 9"},
      {{"cube", "cube", "--number", "float", "--number", "double"}, "--number is given more than once"},
      {{"cube", "cube", "--pose", "1", "2", "3", "--pose", "1", "2", "3"}, "--pose is given more than once"},
      {{"cube", "cube", "--pose", "1", "2", "nan"}, "not finite"},
      {{"cube", "cube", "--number", "exact", "--robust"}, "--robust applies to --number float or double"},
      {{"--batch"}, "--batch needs a file name"},
      {{"--batch", "-", "cube"}, "--batch takes no shape arguments"},
      {{"--batch", "-", "--pose", "1", "0", "0"}, "--pose cannot be used with --batch"},
  };
  for (const auto& c : cases) {
    INFO(c.problem);
    const Run r = query(c.args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Catch::StartsWith("sepax query: ") && Catch::Contains(c.problem) &&
                          Catch::Contains("sepax query --help"));
  }
}

TEST_CASE("query: --help lists the options and the built-in shapes", "[query]") {
  const Run r = query({"--help"});
  CHECK(r.status == 0);
  for (const char* s :
       {"--pose", "--number", "--algorithm", "--robust", "--json", "--batch", "box:HX,HY,HZ", "polygon:N"}) {
    CHECK_THAT(r.out, Catch::Contains(s));
  }
}

TEST_CASE("query: bad input files exit 3 naming FILE:LINE; --json adds an error object", "[query]") {
  const std::string bad = temp_file("bad.off", "OFF\n4 4 6\n1 1 1\n1 -1 -1\n-1 1 oops\n");
  const Run r = query({"cube", bad});
  CHECK(r.status == 3);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::Contains(bad + ":5: bad number 'oops' for coordinate z of vertex 2"));
  const Run j = query({bad, "cube", "--json"});
  CHECK(j.status == 3);
  const json::Value v = json::parse(j.out);
  CHECK_THAT(v.at("error").get<std::string>(), Catch::Contains(bad + ":5: "));
  const Run m = query({"cube", "/nonexistent/dir/shape.obj"});
  CHECK(m.status == 3);
  CHECK_THAT(m.err, Catch::Contains("/nonexistent/dir/shape.obj: cannot open"));
  const Run s = query({"cube", "box:1,2"});
  CHECK(s.status == 3);
  CHECK_THAT(s.err, Catch::Contains("shape 'box:1,2'"));
  std::filesystem::remove(bad);
}

TEST_CASE("query: files and built-ins give the same answer", "[query]") {
  const std::string off = temp_file("tet.off",
                                    "OFF\n4 4 6\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n"
                                    "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  const Run a = query(
      {"cube", off, "--pose", "1.5", "0.5", "0.25", "3", "1", "2", "0.5", "--json", "--number", "exact"});
  const Run b = query(
      {"cube", "tetra", "--pose", "1.5", "0.5", "0.25", "3", "1", "2", "0.5", "--json", "--number", "exact"});
  CHECK(a.status == 0);
  CHECK(a.out == b.out);
  std::filesystem::remove(off);
  // a file with one face is that face, double-sided: the built-in triangle
  const std::string obj = temp_file("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  for (const char* number : {"float", "exact"}) {
    const Run c = query({obj, "cube", "--pose", "0.25", "0.25", "0.5", "--json", "--number", number});
    const Run d = query({"triangle", "cube", "--pose", "0.25", "0.25", "0.5", "--json", "--number", number});
    CHECK(c.status == 0);
    CHECK(c.out == d.out);
  }
  std::filesystem::remove(obj);
}

TEST_CASE("query: --batch reads JSON lines from stdin or a file", "[query]") {
  if (!hull_builder_available()) {
    WARN("this build has no hull builder: test not run");
    return;
  }
  const std::string lines =
      "{\"id\": 1, \"a\": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], \"b\": [[2,0,0],[3,0,0],[2,1,0],[2,0,1]]}\n"
      "{\"id\": 2, \"a\": [[0,0,0]], \"b\": [[2,0,0],[3,0,0],[2,1,0],[2,0,1]]}\n";
  const Run r = query({"--batch", "-"}, lines);
  CHECK(r.status == 1);  // one line failed
  CHECK_THAT(r.err, Catch::Contains("1 of 2 queries failed"));
  std::istringstream out(r.out);
  std::string l1, l2;
  REQUIRE(std::getline(out, l1));
  REQUIRE(std::getline(out, l2));
  CHECK(json::parse(l1).at("separation").get<double>() == 1);
  CHECK(json::parse(l2).contains("error"));
  const std::string file = temp_file("batch.jsonl", lines.substr(0, lines.find('\n') + 1));
  const Run f = query({"--batch", file, "--number", "exact"});
  CHECK(f.status == 0);
  CHECK(json::parse(f.out).at("separation").get<double>() == 1);
  std::filesystem::remove(file);
  const Run missing = query({"--batch", "/nonexistent/b.jsonl"});
  CHECK(missing.status == 3);
  CHECK_THAT(missing.err, Catch::Contains("/nonexistent/b.jsonl: cannot open"));
}

TEST_CASE("info: counts of built-ins and errors", "[query]") {
  const Run r = info({"prism:6"});
  CHECK(r.status == 0);
  CHECK(r.out == "prism:6: 12 vertices, 18 edges, 8 faces [double]\n");
  const Run p = info({"polygon:5", "--number", "exact", "--json"});
  CHECK(p.status == 0);
  const json::Value v = json::parse(p.out);
  CHECK(v.at("vertices").get<double>() == 5);
  CHECK(v.at("faces").get<double>() == 2);
  CHECK(v.at("flat").get<bool>());
  CHECK(info({}).status == 2);
  CHECK(info({"cube", "--robust"}).status == 2);
  CHECK(info({"nothing.stl"}).status == 3);
}
