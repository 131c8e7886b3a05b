// src/io/shape_source.cpp -- see shape_source.hpp.
#include "io/shape_source.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include <sepax/shapes.hpp>

#include "io/obj_reader.hpp"
#include "io/off_reader.hpp"
#include "io/open_file.hpp"
#include "io/ply_reader.hpp"
#include "io/points_reader.hpp"
#include "io/soup_reader.hpp"
#include "io/text_input.hpp"

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
  return lower_ascii(std::filesystem::path(path).extension().string());
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
    return from_polyhedron(
        shapes::triangle<double>(Vec3<double>(0, 0, 0), Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0)), spec);
  }
  if (spec.starts_with("box:")) {
    const std::string_view args = std::string_view(spec).substr(4);
    double h[3];
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
      const std::size_t comma = args.find(',', start);
      if ((i < 2) != (comma != std::string_view::npos))
        bad(spec, "expected box:HX,HY,HZ (three half extents)");
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
    return from_polyhedron(
        shapes::regular_polygon<double>(side_count(spec, std::string_view(spec).substr(8))), spec);
  }
  bad(spec, "not a built-in shape");
}

}  // namespace

namespace {

/// "FILE.obj#SEL" -> ("FILE.obj", "SEL"); anything else -> (spec, none).
std::pair<std::string, std::optional<std::string>> split_selector(const std::string& spec) {
  const std::size_t hash = spec.rfind('#');
  if (hash == std::string::npos) return {spec, std::nullopt};
  const std::string file = spec.substr(0, hash);
  if (lower_extension(file) != ".obj" && file != "-" && file != "-:obj") return {spec, std::nullopt};
  return {file, spec.substr(hash + 1)};
}

/// The format of a mesh on standard input, from its first statement:
/// "OFF" (and COFF, NOFF, ...), "ply", "solid" (ASCII STL), an OBJ keyword
/// (v, vt, vn, f, o, g, ...), or a line of three numbers (a points file).
std::string sniffed_format(const std::string& text) {
  std::istringstream in{std::string(without_bom(text))};
  std::string line;
  while (std::getline(in, line)) {
    const auto tok = tokens(line, /*commas_separate=*/true);
    if (tok.empty()) continue;
    const std::string_view t = tok[0];
    if (t.ends_with("OFF")) return "off";
    if (t == "ply") return "ply";
    if (lower_ascii(std::string(t)) == "solid") return "stl";  // (any case, as read_stl takes it)
    static constexpr std::string_view obj_words[] = {"v", "vt", "vn", "vp", "f",      "o",
                                                     "g", "s",  "l",  "p",  "usemtl", "mtllib"};
    for (const auto w : obj_words) {
      if (t == w) return "obj";
    }
    if (tok.size() == 3 && std::isdigit(static_cast<unsigned char>(t.back()))) return "pts";
    break;
  }
  throw InvalidInput(ErrorCode::Parse,
                     "standard input: cannot tell the format from the content; name it: -:off, -:obj, -:ply, "
                     "-:stl or -:pts");
}

ShapeData read_stdin(const std::string& spec, const std::optional<std::string>& selector, std::istream& in) {
  std::string format = lower_ascii(spec == "-" ? "" : spec.substr(2));
  if (!in.good() || in.peek() == std::char_traits<char>::eof()) {
    throw InvalidInput(ErrorCode::Parse,
                       "standard input: nothing to read (empty, or already read by another '-')");
  }
  std::ostringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  if (format.empty()) format = sniffed_format(text);
  std::istringstream s(text);
  const std::string name = "standard input";
  if (format == "off") return read_off(s, name);
  if (format == "obj") return select_object(read_obj_objects(s, name), name, selector);
  if (format == "pts" || format == "xyz" || format == "txt") return read_points(s, name);
  if (format == "ply") return read_ply(s, name);
  if (format == "stl") return read_stl(s, name);
  throw InvalidInput(ErrorCode::Parse,
                     "'" + spec + "': unknown format '" + format + "' (off, obj, ply, stl or pts)");
}

/// A face list's vertices as a point set (to be hulled).
ShapeData as_points(ShapeData d, const std::string& spec) {
  d.kind = ShapeData::Kind::Points;
  d.name = spec;
  d.faces.clear();
  d.face_lines.clear();
  d.vertex_lines.clear();
  return d;
}

}  // namespace

ShapeData load_shape(const std::string& spec, std::istream& standard_input) {
  if (spec.empty()) throw InvalidInput(ErrorCode::Parse, "empty shape argument");
  if (spec.starts_with("hull:")) return as_points(load_shape(spec.substr(5), standard_input), spec);
  if (is_builtin_shape(spec)) return builtin_shape(spec);
  const auto [file, selector] = split_selector(spec);
  if (file == "-" || file.starts_with("-:")) return read_stdin(file, selector, standard_input);
  const std::string ext = lower_extension(file);
  if (ext == ".obj") {
    auto in = open_input(file);
    return select_object(read_obj_objects(in, file), file, selector);
  }
  if (ext == ".off") return read_off_file(spec);
  if (ext == ".pts" || ext == ".xyz" || ext == ".txt") return read_points_file(spec);
  if (ext == ".ply") return read_ply_file(spec);
  if (ext == ".stl") return read_stl_file(spec);
  throw InvalidInput(ErrorCode::Parse,
                     "'" + spec + "' is neither a built-in shape (" +
                         "cube, box:HX,HY,HZ, tetra, prism:N, polygon:N, triangle) nor a file with a known " +
                         "extension (.off, .obj, .ply, .stl, or .pts/.xyz/.txt for a points file), nor - " +
                         "(standard input)");
}

ShapeData load_shape(const std::string& spec) { return load_shape(spec, std::cin); }

std::optional<ObjectListing> object_listing(const std::string& spec, std::optional<ShapeData>* single) {
  if (lower_extension(spec) != ".obj" || spec.starts_with("hull:") || is_builtin_shape(spec))
    return std::nullopt;
  auto in = open_input(spec);
  auto objects = read_obj_objects(in, spec);
  if (objects.size() < 2) {
    if (single) *single = std::move(objects[0].shape);
    return std::nullopt;
  }
  ObjectListing listing{spec, {}};
  for (const auto& o : objects)
    listing.objects.push_back({o.name, o.shape.vertices.size(), o.shape.faces.size()});
  return listing;
}

std::string ObjectListing::text() const {
  std::string s = spec + ": " + std::to_string(objects.size()) + " objects (select one with " + spec +
                  "#NAME or " + spec + "#K)\n";
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const Entry& e = objects[k];
    s += "  " + std::to_string(k) + "  " + (e.name.empty() ? "(no name)" : e.name) + ": " +
         std::to_string(e.vertices) + " vertices, " + std::to_string(e.faces) + " faces in the file\n";
  }
  return s;
}

const char* builtin_shapes_help() {
  return "  cube               the cube [-1,1]^3\n"
         "  box:HX,HY,HZ       axis-aligned box with half extents HX, HY, HZ\n"
         "  tetra              regular tetrahedron with vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1)\n"
         "  prism:N            regular N-gon prism around z, circumradius 1, z in [-1,1]\n"
         "  polygon:N          double-sided regular N-gon in the plane z = 0, circumradius 1\n"
         "  triangle           double-sided triangle (0,0,0), (1,0,0), (0,1,0)\n"
         "  FILE.off|.obj|.ply|.stl   a face list (one face: a double-sided polygon; a closed\n"
         "                     convex mesh, e.g. triangulated, is the polyhedron it bounds)\n"
         "  FILE.obj#NAME|#K   one object ('o', else 'g') of an OBJ file (K counts from 0)\n"
         "  FILE.pts|.xyz|.txt points (hulled); so is a .ply/.obj/.off of vertices without faces\n"
         "  hull:SHAPE         the convex hull of SHAPE's vertices\n"
         "  -, -:FORMAT        standard input (FORMAT off, obj, ply, stl or pts; - alone guesses)\n";
}

}  // namespace sepax::cli::io
