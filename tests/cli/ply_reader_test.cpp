// Tests for src/io/ply_reader.cpp: ASCII and binary PLY, what is kept and
// what is read past, and malformed files as errors naming the problem.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <sepax/error.hpp>

#include "cli/cli_test_support.hpp"
#include "io/ply_reader.hpp"

using namespace sepax;
using namespace sepax::cli;

namespace {

const std::string kData = std::string(SEPAX_SOURCE_DIR) + "/tests/data/";

io::ShapeData read(const std::string& text, const std::string& name = "t.ply") {
  std::istringstream in(text);
  return io::read_ply(in, name);
}

/// Appends x's bytes in the given byte order.
template <class X>
void put(std::string& s, X x, bool big) {
  char b[sizeof(X)];
  std::memcpy(b, &x, sizeof(X));
  if (big) std::reverse(b, b + sizeof(X));
  s.append(b, sizeof(X));
}

/// A binary unit square (4 vertices with double coordinates and a colour, one face with a flag and
/// ushort indices, an edge element read past) in the given byte order.
std::string binary_square(bool big) {
  std::string s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\ncomment a square\nelement vertex 4\nproperty double x\nproperty double y\n"
                  "property double z\nproperty uchar red\nelement face 1\nproperty uchar flags\n"
                  "property list uchar ushort vertex_indices\nelement edge 1\nproperty int vertex1\n"
                  "property int vertex2\nend_header\n";
  const double xyz[12] = {0, 0, 0.1, 1, 0, 0.1, 1, 1, 0.1, 0, 1, 0.1};
  for (int v = 0; v < 4; ++v) {
    for (int c = 0; c < 3; ++c) put(s, xyz[3 * v + c], big);
    put(s, static_cast<std::uint8_t>(200), big);
  }
  put(s, static_cast<std::uint8_t>(7), big);
  put(s, static_cast<std::uint8_t>(4), big);
  for (std::uint16_t i = 0; i < 4; ++i) put(s, i, big);
  put(s, std::int32_t{0}, big);
  put(s, std::int32_t{1}, big);
  return s;
}

const std::string kVertexHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
const std::string kFaceHeader = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

}  // namespace

TEST_CASE("ply reader: the triangulated cube of tests/data, from a file and a stream", "[ply]") {
  for (const io::ShapeData& d :
       {io::read_ply_file(kData + "cube.ply"), read(test::file_text(kData + "cube.ply"))}) {
    CHECK(d.kind == io::ShapeData::Kind::Faces);
    CHECK(d.from_file);
    REQUIRE(d.vertices.size() == 8);
    REQUIRE(d.faces.size() == 12);
    for (const auto& v : d.vertices)
      for (int c = 0; c < 3; ++c) CHECK(std::abs(v[c]) == 1);  // (the normals nx, ny, nz are read past)
    for (const auto& f : d.faces) {
      CHECK(f.size() == 3);
      for (const int i : f) CHECK((i >= 0 && i < 8));
    }
    REQUIRE(d.face_lines.size() == 12);
  }
  // ASCII faces keep their lines: the first face is on the line after the 8 vertex lines
  const auto d = io::read_ply_file(kData + "cube.ply");
  CHECK(d.face_lines[0] == d.face_lines[1] - 1);
}

TEST_CASE("ply reader: binary of both byte orders, other properties and elements read past", "[ply]") {
  for (const bool big : {false, true}) {
    INFO((big ? "big endian" : "little endian"));
    const io::ShapeData d = read(binary_square(big), "square.ply");
    REQUIRE(d.vertices.size() == 4);
    CHECK(d.vertices[2] == Vec3<double>(1, 1, 0.1));  // doubles kept exactly
    REQUIRE(d.faces.size() == 1);
    CHECK(d.faces[0] == std::vector<int>{0, 1, 2, 3});
    CHECK(d.kind == io::ShapeData::Kind::Faces);
  }
}

TEST_CASE("ply reader: a float property's ASCII value is the float a binary file would hold", "[ply]") {
  const std::string body = "end_header\n0.1 0.2 0.3\n";
  const auto f = read(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\n" +
      body);
  CHECK(f.vertices[0] == Vec3<double>(double(0.1f), double(0.2f), double(0.3f)));
  const auto d = read(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
      "property double z\n" +
      body);
  CHECK(d.vertices[0] == Vec3<double>(0.1, 0.2, 0.3));
  // a vertex element alone is a point set (a scanner's point cloud)
  CHECK(f.kind == io::ShapeData::Kind::Points);
  CHECK(f.faces.empty());
  // CRLF line ends, comments and obj_info
  const auto crlf = read(
      "ply\r\nformat ascii 1.0\r\ncomment x\r\nobj_info y\r\nelement vertex 1\r\n"
      "property float x\r\nproperty float y\r\nproperty float z\r\nend_header\r\n1 2 3\r\n");
  CHECK(crlf.vertices[0] == Vec3<double>(1, 2, 3));
}

TEST_CASE("ply reader: malformed files are errors naming the file and the problem", "[ply]") {
  const std::string tri = kVertexHeader + kFaceHeader + "0 0 0\n1 0 0\n0 1 0\n";
  std::string nan_binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n";
  for (const float x : {0.0f, 1.0f, 2.0f, 3.0f, std::numeric_limits<float>::quiet_NaN(), 5.0f})
    put(nan_binary, x, false);
  std::string huge_list =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list int int vertex_indices\nend_header\n";
  for (int i = 0; i < 3; ++i) put(huge_list, 0.0f, false);
  put(huge_list, std::int32_t{2000000000}, false);
  put(huge_list, std::int32_t{0}, false);
  const struct {
    const char* name;
    std::string text;
    const char* problem;
  } cases[] = {
      {"garbage", "this is not a ply file\n", ":1: not a readable PLY file: the first line is not 'ply'"},
      {"empty", "", ":1: not a readable PLY file: the file is empty"},
      {"no format", "ply\nformat\n", ":2: not a readable PLY file: the second line is not"},
      {"unknown format", "ply\nformat ebcdic 1.0\n", ":2: unknown PLY format 'ebcdic'"},
      {"no end_header", kVertexHeader, ":6: not a readable PLY file: no end_header line"},
      {"header only", "ply\nformat ascii 1.0\nend_header\n", "t.ply: no vertices in the file"},
      {"property first", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n",
       ":3: a property line before any element line"},
      {"unknown line", "ply\nformat ascii 1.0\nelemnt vertex 1\nend_header\n",
       ":3: unknown header line 'elemnt'"},
      {"unknown type", "ply\nformat ascii 1.0\nelement vertex 1\nproperty flt x\nend_header\n",
       ":4: unknown property type 'flt'"},
      {"float count type",
       "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n",
       ":4: a list's count type must be an integer type, not 'float'"},
      {"bad count", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", ":3: bad count '-3'"},
      {"count beyond the file",
       "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nend_header\n0\n",
       ":3: element 'vertex' declares 4000000000 instances, more than the 2 bytes after the header hold"},
      {"instances without properties", "ply\nformat ascii 1.0\nelement vertex 5\nend_header\n1 2 3\n",
       ":3: element 'vertex' has instances but no properties"},
      {"no z",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
       ":3: element 'vertex' needs the properties x, y and z"},
      {"no index list",
       kVertexHeader + "element face 1\nproperty int flags\nend_header\n0 0 0\n1 0 0\n0 1 0\n1\n",
       ":7: element 'face' has no vertex_indices (or vertex_index) list"},
      {"float indices",
       kVertexHeader + "element face 1\nproperty list uchar float vertex_indices\nend_header\n0 0 0\n1 0 0\n"
                       "0 1 0\n3 0 1 2\n",
       ":7: the face's vertex index list must hold integers"},
      {"face first",
       "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nelement vertex 3\n"
       "property float x\nproperty float y\nproperty float z\nend_header\n3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n",
       ":3: element 'face' comes before element 'vertex'"},
      {"truncated", kVertexHeader + kFaceHeader + "0 0 0\n1 0 0\n", ":12: the file ends before vertex 2"},
      {"no face line", tri, ":13: the file ends before face 0"},
      {"bad index", tri + "3 0 1 7\n",
       ":13: face 0: vertex index 7 is out of range (the file has 3 vertices)"},
      {"negative index", tri + "3 0 -1 2\n", ":13: face 0: vertex index -1 is negative"},
      {"two vertices", tri + "2 0 1\n", ":13: face 0 has 2 vertices; a face needs at least 3"},
      {"huge ASCII count", tri + "2000000000 0 1 2\n",
       ":13: face 0's list vertex_indices counts 2000000000 values; its line has 3 after the count"},
      {"negative ASCII count", tri + "-3 0 1 2\n",
       ":13: the count of list vertex_indices of face 0 is negative (-3)"},
      {"extra values", kVertexHeader + kFaceHeader + "0 0 0 9\n", ":10: vertex 0 has 1 value(s) more"},
      {"too few values", kVertexHeader + kFaceHeader + "0 0\n", ":10: vertex 0 has too few values (2)"},
      {"uchar beyond its range",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty uchar z\n"
       "end_header\n0 0 300\n",
       ":8: value 300 for coordinate z of vertex 0 is out of the range of its type uchar (0 to 255)"},
      {"negative uint",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty uint x\nproperty float y\n"
       "property float z\nend_header\n-1 0 0\n",
       ":8: value -1 for coordinate x of vertex 0 is out of the range of its type uint (0 to 4294967295)"},
      {"fraction in an int",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty float y\n"
       "property float z\nend_header\n1.5 0 0\n",
       ":8: "},
      {"colour beyond uchar", kVertexHeader + "property uchar red\n" + kFaceHeader + "0 0 0 256\n",
       ":11: value 256 for property red of vertex 0 is out of the range of its type uchar"},
      {"uchar count beyond its range",
       tri + "256" +
           [] {
             std::string v;
             for (int i = 0; i < 256; ++i) v += " " + std::to_string(i % 3);
             return v;
           }() +
           "\n",
       ":13: value 256 for the count of list vertex_indices of face 0 is out of the range of its type uchar"},
      {"NaN", kVertexHeader + kFaceHeader + "0 nan 0\n",
       ":10: coordinate y of vertex 0 is 'nan': NaN and infinity are not allowed"},
      {"beyond a float", kVertexHeader + kFaceHeader + "1e39 0 0\n",
       ":10: number '1e39' for coordinate x of vertex 0 is out of the range of a float"},
      {"bad number", kVertexHeader + kFaceHeader + "0 zero 0\n", ":10: bad number 'zero' for coordinate y"},
      {"NUL in text", kVertexHeader + kFaceHeader + std::string("0 0\0 0\n", 7), ":10: NUL byte in text"},
      {"binary NaN", nan_binary, "t.ply: coordinate y of vertex 1 is not finite"},
      {"binary truncated", binary_square(false).substr(0, binary_square(false).size() - 30),
       "t.ply: the binary data ends inside vertex 3"},
      {"more data than declared", tri + "3 0 1 2\n\n1 1 1\n",
       ":15: more data than the header declares (vertex 3, face 1)"},
      {"binary bytes after the data", binary_square(false) + "abc",
       "t.ply: 3 bytes after the data the header declares (vertex 4, face 1, edge 1)"},
      {"binary huge list", huge_list,
       "t.ply: the count of list vertex_indices of face 0 (2000000000) is more than the data left holds"},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    try {
      (void)read(c.text);
      FAIL("accepted a malformed file");
    } catch (const InvalidInput& e) {
      CHECK(e.code() == ErrorCode::Parse);
      CHECK_THAT(e.what(), Catch::StartsWith("t.ply") && Catch::Contains(c.problem));
    }
  }
  CHECK_THROWS_WITH(io::read_ply_file("/nonexistent/x.ply"),
                    Catch::StartsWith("/nonexistent/x.ply: cannot open"));
}

TEST_CASE("ply reader: mutated files are read or refused, never a crash or an unbounded read", "[ply]") {
  // Random edits of the ASCII cube (tokens replaced by others, bytes changed, cut or repeated) and of
  // the binary square (bytes changed, cut): every one is a shape or an InvalidInput(Parse).
  const std::string ascii = test::file_text(kData + "cube.ply");
  const std::string binary = binary_square(false);
  const char* tokens[] = {"nan",        "inf",        "1e39",
                          "-1",         "0",          "255",
                          "2000000000", "4294967296", "18446744073709551615",
                          "property",   "element",    "list",
                          "end_header", "",           "x"};
  std::mt19937 rng(12345);
  int read_ok = 0, refused = 0;
  for (int it = 0; it < 3000; ++it) {
    std::string s = it % 2 == 0 ? ascii : binary;
    const int kind = static_cast<int>(rng() % 3);
    if (kind == 0 && it % 2 == 0) {
      for (int k = 0; k < 3; ++k) {
        const std::size_t at = rng() % s.size();
        const std::size_t end = std::min(s.find_first_of(" \n", at), s.size());
        s.replace(at, end - at, tokens[rng() % std::size(tokens)]);
      }
    } else if (kind <= 1) {
      for (int k = 0; k < 4; ++k) s[rng() % s.size()] = static_cast<char>(rng() % 256);
    } else {
      s.resize(rng() % s.size());
    }
    try {
      const io::ShapeData d = read(s);
      ++read_ok;
      for (const auto& f : d.faces)
        for (const int i : f) CHECK((i >= 0 && static_cast<std::size_t>(i) < d.vertices.size()));
      for (const auto& v : d.vertices) CHECK(v.allFinite());
    } catch (const InvalidInput& e) {
      ++refused;
      CHECK(e.code() == ErrorCode::Parse);
    }
  }
  CHECK(read_ok > 0);
  CHECK(refused > 0);
}

TEST_CASE("ply reader: blank lines and white space after the data are read past", "[ply]") {
  const std::string tri = kVertexHeader + kFaceHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  CHECK(read(tri + "\n  \n\t\n").faces.size() == 1);
  CHECK(read(binary_square(true) + "\n").faces.size() == 1);
  CHECK(read(binary_square(false) + "\r\n").vertices.size() == 4);
}
