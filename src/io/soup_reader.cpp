// src/io/soup_reader.cpp -- see soup_reader.hpp.
#include "io/soup_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <sepax/error.hpp>

#include "io/open_file.hpp"
#include "io/text_input.hpp"

namespace sepax::cli::io {

namespace {

using Point = CGAL::Simple_cartesian<double>::Point_3;

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw InvalidInput(ErrorCode::Parse, name + ": " + what);
}

template <class Read>
ShapeData soup(const std::string& name, const char* format, Read&& read) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  try {
    ok = read(points, polygons);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    fail(name, std::string("not a readable ") + format + " file (" + e.what() + ")");
  }
  if (!ok)
    fail(name, std::string("not a readable ") + format + " file (the reader stopped on malformed content)");
  if (points.empty()) fail(name, "no vertices in the file");
  ShapeData out;
  out.kind = polygons.empty() ? ShapeData::Kind::Points : ShapeData::Kind::Faces;
  out.name = name;
  out.from_file = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(p[c])) {
        fail(name, "coordinate " + std::string(1, "xyz"[c]) + " of vertex " + std::to_string(i) +
                       " is not finite: NaN and infinity are not allowed");
      }
    }
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const auto& poly = polygons[f];
    if (poly.size() < 3) {
      fail(name, "face " + std::to_string(f) + " has " + std::to_string(poly.size()) +
                     " vertices; a face needs at least 3");
    }
    std::vector<int> loop;
    for (const std::size_t i : poly) {
      if (i >= points.size()) {
        fail(name, "face " + std::to_string(f) + ": vertex index " + std::to_string(i) +
                       " is out of range (the file has " + std::to_string(points.size()) + " vertices)");
      }
      loop.push_back(static_cast<int>(i));
    }
    out.faces.push_back(std::move(loop));
  }
  out.face_lines.assign(out.faces.size(), 0);
  return out;
}

/// The bytes of an STL file as CGAL's read_STL should see them.  CGAL reads a file as ASCII only when it
/// starts with "solid" and a space or line end, and anything else as binary, so an ASCII file whose first
/// line is "solid<TAB>name" or "SOLID name", or that starts with a UTF-8 byte order mark, would be read
/// as binary garbage.  Here: a file is ASCII when its first word is "solid" in any case, followed by
/// white space, and it cannot be a binary file (a binary STL of N triangles, N the little-endian count
/// at byte 80, has at least 84 + 50 N bytes; a binary header may start with "solid" too, and is then left
/// to CGAL as it is).  An ASCII file is given to CGAL without the mark, its first word "solid" and a
/// space, and its keywords in lower case (CGAL compares them exactly).
std::string stl_for_cgal(std::string b) {
  std::size_t start = b.size() - without_bom(b).size();
  start = std::min(b.find_first_not_of(" \t\r\n", start), b.size());
  const std::string word = lower_ascii(b.substr(start, 5));
  const char after = start + 5 < b.size() ? b[start + 5] : '\n';
  const bool ascii = word == "solid" && std::isspace(static_cast<unsigned char>(after));
  bool binary = false;
  if (b.size() >= 84) {
    std::uint64_t n = 0;
    for (int k = 3; k >= 0; --k)
      n = (n << 8) | static_cast<unsigned char>(b[80 + static_cast<std::size_t>(k)]);
    binary = 84 + 50 * n <= b.size();
  }
  if (!ascii || binary) return b;
  b = lower_ascii(b.substr(start));
  if (b.size() > 5) b[5] = ' ';
  return b;
}

}  // namespace

ShapeData read_stl(std::istream& in, const std::string& name) {
  std::istringstream bytes(stl_for_cgal(std::string(std::istreambuf_iterator<char>(in), {})));
  return soup(name, "STL", [&](auto& points, auto& polygons) {
    return CGAL::IO::read_STL(bytes, points, polygons, CGAL::parameters::verbose(false));
  });
}

ShapeData read_stl_file(const std::string& path) {
  auto in = open_input(path);
  return read_stl(in, path);
}

}  // namespace sepax::cli::io
