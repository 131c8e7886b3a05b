// src/io/shape_source.cpp -- see shape_source.hpp.
#include "io/shape_source.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>

#include <sepax/shapes.hpp>

#include "io/obj_reader.hpp"
#include "io/off_reader.hpp"
#include "io/points_reader.hpp"

namespace sepax::cli::io {

namespace {

[[noreturn]] void bad(const std::string& spec, const std::string& what) {
  throw InvalidInput(ErrorCode::Parse, "shape '" + spec + "': " + what);
}

ShapeData from_polyhedron(const ConvexPolyhedron<double>& p, const std::string& name) {
  ShapeData d;
  d.kind = ShapeData::Kind::Faces;
  d.name = name;
  d.vertices = p.vertices();
  for (int f = 0; f < p.face_count(); ++f) d.faces.push_back(p.face_vertices(f));
  d.face_lines.assign(d.faces.size(), 0);
  return d;
}

double positive_number(const std::string& spec, std::string_view s, const char* what) {
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size()) {
    bad(spec, std::string("bad number '") + std::string(s) + "' for " + what);
  }
  if (!std::isfinite(v) || !(v > 0)) bad(spec, std::string(what) + " must be a positive finite number");
  return v;
}

int side_count(const std::string& spec, std::string_view s) {
  int n = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), n);
  if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size()) {
    bad(spec, "bad side count '" + std::string(s) + "' (expected an integer)");
  }
  if (n < 3 || n > 1000) bad(spec, "the side count must be between 3 and 1000, got " + std::to_string(n));
  return n;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

namespace {
ShapeData builtin_shape_unnamed(const std::string& spec);
}  // namespace

bool is_builtin_shape(const std::string& spec) {
  return spec == "cube" || spec == "tetra" || spec == "triangle" || spec.starts_with("box:") ||
         spec.starts_with("prism:") || spec.starts_with("polygon:");
}

ShapeData builtin_shape(const std::string& spec) {
  // The shapes' own validation (a box too thin for its normals to be more
  // than rounding noise, ...) names the shape like the parse errors do.
  try {
    return builtin_shape_unnamed(spec);
  } catch (const InvalidInput& e) {
    if (std::string_view(e.what()).starts_with("shape '")) throw;
    throw InvalidInput(e.code(), "shape '" + spec + "': " + e.what());
  }
}

namespace {

ShapeData builtin_shape_unnamed(const std::string& spec) {
  if (spec == "cube") return from_polyhedron(shapes::cube<double>(), spec);
  if (spec == "tetra") return from_polyhedron(shapes::tetrahedron<double>(), spec);
  if (spec == "triangle") {
    return from_polyhedron(shapes::triangle<double>(Vec3<double>(0, 0, 0), Vec3<double>(1, 0, 0),
                                                    Vec3<double>(0, 1, 0)),
                           spec);
  }
  if (spec.starts_with("box:")) {
    const std::string_view args = std::string_view(spec).substr(4);
    double h[3];
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
      const std::size_t comma = args.find(',', start);
      if ((i < 2) != (comma != std::string_view::npos)) bad(spec, "expected box:HX,HY,HZ (three half extents)");
      const std::string_view part = args.substr(start, i < 2 ? comma - start : std::string_view::npos);
      h[i] = positive_number(spec, part, i == 0 ? "HX" : i == 1 ? "HY" : "HZ");
      start = comma + 1;
    }
    return from_polyhedron(shapes::box<double>(h[0], h[1], h[2]), spec);
  }
  if (spec.starts_with("prism:")) {
    return from_polyhedron(shapes::prism<double>(side_count(spec, std::string_view(spec).substr(6))), spec);
  }
  if (spec.starts_with("polygon:")) {
    return from_polyhedron(shapes::regular_polygon<double>(side_count(spec, std::string_view(spec).substr(8))), spec);
  }
  bad(spec, "not a built-in shape");
}

}  // namespace

ShapeData load_shape(const std::string& spec) {
  if (spec.empty()) throw InvalidInput(ErrorCode::Parse, "empty shape argument");
  if (is_builtin_shape(spec)) return builtin_shape(spec);
  const std::string ext = lower_extension(spec);
  if (ext == ".off") return read_off_file(spec);
  if (ext == ".obj") return read_obj_file(spec);
  if (ext == ".pts" || ext == ".xyz" || ext == ".txt") return read_points_file(spec);
  throw InvalidInput(ErrorCode::Parse,
                     "'" + spec + "' is neither a built-in shape (" +
                         "cube, box:HX,HY,HZ, tetra, prism:N, polygon:N, triangle) nor a file with a known " +
                         "extension (.off, .obj, or .pts/.xyz/.txt for a points file)");
}

const char* builtin_shapes_help() {
  return "  cube               the cube [-1,1]^3\n"
         "  box:HX,HY,HZ       axis-aligned box with half extents HX, HY, HZ\n"
         "  tetra              regular tetrahedron with vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1)\n"
         "  prism:N            regular N-gon prism around z, circumradius 1, z in [-1,1]\n"
         "  polygon:N          double-sided regular N-gon in the plane z = 0, circumradius 1\n"
         "  triangle           double-sided triangle (0,0,0), (1,0,0), (0,1,0)\n"
         "  FILE.off, FILE.obj face lists (one face: a double-sided polygon);\n"
         "                     FILE.pts, FILE.xyz, FILE.txt: points (hulled)\n";
}

}  // namespace sepax::cli::io
