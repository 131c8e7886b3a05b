// Tests of the program on mesh files as users have them (src/io/ readers and
// shape_source.cpp, through the query and info verbs): a V-HACD-style
// decomposition queried piece against piece, pieces far from the origin in
// float (re-centred exactly, answered in world coordinates), hull:, and
// shapes read from standard input.
#include <catch2/catch.hpp>

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"
#include "commands/query_command.hpp"
#include "commands/sat_runner.hpp"
#include "io/shape_source.hpp"
#include "json/json.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

using Run = test::CommandRun;

const std::string kData = std::string(SEPAX_SOURCE_DIR) + "/tests/data/";
const std::string kPieces = kData + "vhacd_pieces.obj";

using test::info;
using test::query;

}  // namespace

TEST_CASE("mesh files: a V-HACD-style decomposition is queried piece against piece", "[mesh]") {
  // info lists the pieces; a query without a selector names them
  const Run list = info({kPieces});
  CHECK(list.status == 0);
  CHECK_THAT(list.out, Catch::Contains("3 objects") && Catch::Contains("0  convex_0: 8 vertices, 12 faces") &&
                           Catch::Contains("2  convex_2: 14 vertices"));
  const Run none = query({kPieces, "cube"});
  CHECK(none.status != 0);  // an unreadable input (its code: docs/cli.md)
  CHECK_THAT(none.err, Catch::Contains("holds 3 objects (0 'convex_0', 1 'convex_1', 2 'convex_2')"));
  const Run bad = query({kPieces + "#convex_9", "cube"});
  CHECK(bad.status != 0);
  CHECK_THAT(bad.err, Catch::Contains("no object 'convex_9'"));

  // convex_0 and convex_1 are 0.4-unit boxes at x = 150 overlapping by 0.01
  // along x; convex_2 sits 0.165 above convex_0.  Every number type and
  // policy agrees; the contacts are reported where the pieces are.
  for (const char* number : {"float", "double", "exact"}) {
    for (const bool robust : {false, true}) {
      if (robust && std::string(number) == "exact") continue;
      INFO(number << (robust ? " robust" : ""));
      std::vector<std::string> args{kPieces + "#convex_0", kPieces + "#1", "--json", "--number", number};
      if (robust) args.push_back("--robust");
      const Run r = query(args);
      REQUIRE(r.status == 0);
      const json::Value v = json::parse(r.out);
      CHECK(v.at("overlap").get<bool>());
      CHECK(v.at("separation").get<double>() == Approx(-0.01).margin(1e-5));
      CHECK(json::write(v.at("normal")) == "[1,0,0]");
      const auto& points = v.at("manifold").at("points");
      REQUIRE(points.size() == 4);
      for (const auto& p : points) {
        const auto& x = p.at("position");
        CHECK(x[0].get<double>() == Approx(150.395).margin(1e-4));
        CHECK(std::abs(x[1].get<double>() + 37.1) <= 0.15 + 1e-5);
        CHECK(std::abs(x[2].get<double>() - 88.2) <= 0.15 + 1e-5);
      }
      args[1] = kPieces + "#convex_2";
      const Run s = query(args);
      REQUIRE(s.status == 0);
      const json::Value w = json::parse(s.out);
      CHECK_FALSE(w.at("overlap").get<bool>());
      CHECK(w.at("separation").get<double>() == Approx(0.165).margin(1e-5));
    }
  }
}

TEST_CASE("mesh files: a 0.4-unit piece 150 units from the origin works in float", "[mesh]") {
  // Points of that piece: the hull builder alone refuses them in float
  // ("too far for float to resolve") at their world coordinates.
  for (const char* spec : {"#convex_2", "#2"}) {
    const io::ShapeData piece = io::load_shape(kPieces + spec);
    const ShapeCounts c = shape_counts(piece, NumberKind::Float);
    CHECK(c.vertices == 14);
    CHECK(c.faces == 24);
    io::ShapeData points = io::load_shape("hull:" + kPieces + spec);
    CHECK(points.kind == io::ShapeData::Kind::Points);
    CHECK(shape_counts(points, NumberKind::Float).faces == 24);
  }
  // piece against piece: both are built in one frame, re-centred near them
  const Run r =
      query({"hull:" + kPieces + "#convex_2", kPieces + "#convex_0", "--number", "float", "--json"});
  REQUIRE(r.status == 0);
  const json::Value v = json::parse(r.out);
  CHECK(v.at("separation").get<double>() == Approx(0.165).margin(1e-5));
  // touching pieces: the contact points are at the pieces' world position
  const Run t = query({"hull:" + kPieces + "#convex_2", kPieces + "#convex_0", "--number", "float", "--pose",
                       "0", "0", "0.165", "--json"});
  REQUIRE(t.status == 0);
  const json::Value w = json::parse(t.out);
  CHECK(std::abs(w.at("separation").get<double>()) <= 1e-4);
  for (const auto& p : w.at("manifold").at("points")) {
    CHECK(p.at("position")[0].get<double>() == Approx(150.2).margin(0.25));
    CHECK(p.at("position")[2].get<double>() == Approx(88.565).margin(1e-3));
  }
}

TEST_CASE("mesh files: a small piece far from the origin against a shape at the origin, in float", "[mesh]") {
  // No one frame is near both: each is built around its own exact centre and
  // the piece is expressed in the cube's frame (rounded to float once).
  for (const char* piece : {"#convex_2", "#convex_0"}) {
    INFO(piece);
    const std::vector<std::string> args{"cube", "hull:" + kPieces + piece, "--json", "--robust"};
    std::vector<std::string> in_float = args, in_double = args;
    in_float.insert(in_float.end(), {"--number", "float"});
    in_double.insert(in_double.end(), {"--number", "double"});
    const Run f = query(in_float);
    const Run d = query(in_double);
    REQUIRE(f.status == 0);
    REQUIRE(d.status == 0);
    const json::Value vf = json::parse(f.out), vd = json::parse(d.out);
    CHECK_FALSE(vf.at("overlap").get<bool>());
    const double sep = vd.at("separation").get<double>();
    CHECK(sep > 140);
    // float rounds coordinates near 150 by up to 2^-17 ~ 7.6e-6, which turns
    // the normals of the piece's faces (about 0.2 across) by up to ~1e-4 rad
    // together: along an axis 173 units long, a separation within 1e-4 of it
    CHECK(vf.at("separation").get<double>() == Approx(sep).margin(1e-4 * sep));
    CHECK(json::write(vf.at("feature").at("type")) == json::write(vd.at("feature").at("type")));
  }
  // and the other way round, with a contact far from the origin: the cube
  // moved next to the piece, touching its face at x = 150
  const Run t =
      query({kPieces + "#convex_0", "cube", "--pose", "149", "-37.1", "88.2", "--number", "float", "--json"});
  REQUIRE(t.status == 0);
  const json::Value w = json::parse(t.out);
  CHECK(w.at("overlap").get<bool>());
  CHECK(w.at("separation").get<double>() == Approx(0).margin(1e-4));
  const auto& points = w.at("manifold").at("points");
  REQUIRE_FALSE(points.empty());
  for (const auto& p : points) CHECK(p.at("position")[0].get<double>() == Approx(150).margin(1e-4));
}

TEST_CASE("mesh files: hull: makes any mesh or point file its convex hull", "[mesh]") {
  const std::string dent = test::temp_file(
      "dent.obj",
      "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nv 0 0 0.5\n"
      "f 1 4 3\nf 1 3 2\nf 5 6 9\nf 6 7 9\nf 7 8 9\nf 8 5 9\nf 1 2 6\nf 1 6 5\nf 3 4 8\nf 3 8 7\nf 1 5 8\n"
      "f 1 8 4\nf 2 3 7\nf 2 7 6\n");
  const Run refused = query({dent, "cube"});
  CHECK(refused.status != 0);
  CHECK_THAT(refused.err, Catch::Contains("not convex") && Catch::Contains("hull:FILE"));
  const Run hulled = query({"hull:" + dent, "cube", "--pose", "2.5", "0", "0", "--json"});
  REQUIRE(hulled.status == 0);
  CHECK(json::parse(hulled.out).at("separation").get<double>() == 0.5);
  const Run i = info({"hull:" + kData + "cube.stl", "--number", "exact"});
  CHECK(i.status == 0);
  CHECK_THAT(i.out, Catch::Contains("8 vertices, 12 edges, 6 faces"));
  CHECK(info({"hull:cube"}).status == 0);
}

TEST_CASE("mesh files: an ASCII STL is ASCII whatever follows 'solid' and in any case", "[mesh]") {
  // CGAL's reader takes only "solid" and a space or line end for ASCII, and read these as binary garbage
  const std::string stl = test::file_text(kData + "cube.stl");
  REQUIRE(stl.starts_with("solid cube\n"));
  std::string upper = stl;
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"tab.stl", "solid\tcube\n" + stl.substr(11)},
           {"bare.stl", "solid\n" + stl.substr(11)},
           {"upper.stl", upper},
           {"bom.stl", "\xEF\xBB\xBF" + stl},
           {"indented.stl", "\n  " + stl},
       }) {
    INFO(name);
    const std::string path = test::temp_file(name, text);
    const Run r = info({path});
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("8 vertices, 12 edges, 6 faces"));
    const Run q = query({"hull:" + path, "cube", "--pose", "2.5", "0", "0", "--json"});
    REQUIRE(q.status == 0);
    CHECK(json::parse(q.out).at("separation").get<double>() == 0.5);
  }
  // a binary STL whose header starts with "solid " stays binary
  std::string bin = test::file_text(kData + "cube_binary.stl");
  bin.replace(0, 11, "solid cube ");
  const Run b = info({test::temp_file("solid_header.stl", bin)});
  CHECK(b.status == 0);
  CHECK_THAT(b.out, Catch::Contains("8 vertices, 12 edges, 6 faces"));
}

TEST_CASE("mesh files: - reads a shape from standard input", "[mesh]") {
  const std::string cube_off = test::file_text(kData + "cube.off");
  const Run ref = query({kData + "cube.off", "cube", "--pose", "2.5", "0", "0", "--json"});
  REQUIRE(ref.status == 0);
  // the format guessed from the content, or named
  for (const auto& [spec, text] : std::vector<std::pair<std::string, std::string>>{
           {"-", cube_off},
           {"-:off", cube_off},
           {"-", test::file_text(kData + "cube_tri.obj")},
           {"-", test::file_text(kData + "cube.ply")},
           {"-", test::file_text(kData + "cube.stl")},
           {"-:stl", test::file_text(kData + "cube_binary.stl")},
           {"-", "\xEF\xBB\xBF" + test::file_text(kData + "cube.stl")},      // a byte order mark
           {"-", "\xEF\xBB\xBF" + test::file_text(kData + "cube_tri.obj")},  // (read by name, skipped)
           {"-", "# points\n1 1 1\n1 1 -1\n1 -1 1\n1 -1 -1\n-1 1 1\n-1 1 -1\n-1 -1 1\n-1 -1 -1\n"},
           {"-:pts", "1 1 1\n1 1 -1\n1 -1 1\n1 -1 -1\n-1 1 1\n-1 1 -1\n-1 -1 1\n-1 -1 -1\n"},
       }) {
    INFO(spec << " " << text.substr(0, 20));
    const Run r = query({spec, "cube", "--pose", "2.5", "0", "0", "--json"}, text);
    REQUIRE(r.status == 0);
    CHECK(json::parse(r.out).at("separation").get<double>() == 0.5);
  }
  // one object of an OBJ on standard input
  const Run piece = query({"-#convex_1", kPieces + "#convex_0", "--json"}, test::file_text(kPieces));
  REQUIRE(piece.status == 0);
  CHECK(json::parse(piece.out).at("separation").get<double>() == Approx(-0.01).margin(1e-9));
  // errors: empty, read twice, not recognisable, an unknown format name, bad content
  CHECK_THAT(query({"-", "cube"}).err, Catch::Contains("standard input: nothing to read"));
  CHECK_THAT(query({"-", "-"}, cube_off).err, Catch::Contains("already read"));
  CHECK_THAT(query({"-", "cube"}, "hello\n").err,
             Catch::Contains("cannot tell the format") && Catch::Contains("-:off"));
  CHECK_THAT(query({"-:dxf", "cube"}, cube_off).err, Catch::Contains("unknown format 'dxf'"));
  CHECK_THAT(query({"-:off", "cube"}, "OFF\n8 6\n1 1\n").err, Catch::Contains("standard input:3: "));
}
