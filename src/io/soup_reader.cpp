// src/io/soup_reader.cpp -- see soup_reader.hpp.
#include "io/soup_reader.hpp"

#include <cmath>
#include <cstddef>
#include <exception>
#include <vector>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <sepax/error.hpp>

#include "io/open_file.hpp"

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

}  // namespace

ShapeData read_stl(std::istream& in, const std::string& name) {
  return soup(name, "STL", [&](auto& points, auto& polygons) {
    return CGAL::IO::read_STL(in, points, polygons, CGAL::parameters::verbose(false));
  });
}

ShapeData read_stl_file(const std::string& path) {
  auto in = open_input(path);
  return read_stl(in, path);
}

}  // namespace sepax::cli::io
