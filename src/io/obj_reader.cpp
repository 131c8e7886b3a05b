// src/io/obj_reader.cpp -- see obj_reader.hpp.
#include "io/obj_reader.hpp"

#include <limits>

#include "io/open_file.hpp"
#include "io/text_input.hpp"

namespace sepax::cli::io {

ShapeData read_obj(std::istream& in, const std::string& name) {
  LineReader r(in, name);
  ShapeData out;
  out.kind = ShapeData::Kind::Faces;
  out.name = name;
  std::string line;
  bool any_content = false;
  while (r.next(line)) {
    const auto tok = tokens(line);
    if (tok.empty()) continue;
    any_content = true;
    if (tok[0] == "v") {
      const std::string what = "vertex " + std::to_string(out.vertices.size() + 1);
      const std::size_t n = tok.size() - 1;
      if (n < 3) r.fail(what + " has " + std::to_string(n) + " value" + (n == 1 ? "" : "s") + "; expected 'v x y z'");
      if (n == 5 || n > 7) r.fail(what + " has " + std::to_string(n) + " values; expected x y z [w] or x y z r g b");
      Vec3<double> p;
      for (int c = 0; c < 3; ++c) {
        p[c] = parse_double(r, tok[static_cast<std::size_t>(c) + 1], "coordinate " + std::string(1, "xyz"[c]) + " of " + what);
      }
      if (n == 4) {
        const double w = parse_double(r, tok[4], "w of " + what);
        if (w != 1.0) r.fail(what + " has w = " + std::string(tok[4]) + "; only w = 1 is supported");
      } else {
        for (std::size_t c = 4; c <= n; ++c) (void)parse_double(r, tok[c], "a colour value of " + what);
      }
      out.vertices.push_back(p);
    } else if (tok[0] == "f") {
      const std::string what = "face " + std::to_string(out.faces.size() + 1);
      if (tok.size() - 1 < 3) {
        r.fail(what + " has " + std::to_string(tok.size() - 1) + " vertices; a face needs at least 3");
      }
      std::vector<int> face;
      const auto nv = static_cast<long long>(out.vertices.size());
      for (std::size_t k = 1; k < tok.size(); ++k) {
        const std::string_view entry = tok[k];
        const std::string_view index = entry.substr(0, entry.find('/'));
        const long long i = parse_integer(r, index, "a vertex index of " + what);
        long long zero_based;
        if (i > 0) {
          zero_based = i - 1;
        } else if (i < 0) {
          zero_based = nv + i;  // -1 is the last vertex read so far
        } else {
          r.fail(what + ": vertex index 0 is invalid (OBJ indices start at 1)");
        }
        if (zero_based < 0 || zero_based >= nv) {
          r.fail(what + ": vertex index " + std::to_string(i) + " is out of range (" + std::to_string(nv) +
                 " vertices read so far)");
        }
        face.push_back(static_cast<int>(zero_based));
      }
      out.faces.push_back(std::move(face));
      out.face_lines.push_back(r.line_number());
    }
    // every other statement is ignored
  }
  if (!any_content) r.fail("empty file: no 'v' or 'f' statements");
  if (out.vertices.empty()) r.fail("no vertices ('v' lines) in the file");
  if (out.faces.empty()) r.fail("no faces ('f' lines) in the file (for a point set, use a points file)");
  return out;
}

ShapeData read_obj_file(const std::string& path) {
  auto in = open_input(path);
  return read_obj(in, path);
}

}  // namespace sepax::cli::io
