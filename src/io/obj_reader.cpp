// src/io/obj_reader.cpp -- see obj_reader.hpp.
#include "io/obj_reader.hpp"

#include <algorithm>
#include <charconv>
#include <map>

#include <sepax/error.hpp>

#include "io/open_file.hpp"
#include "io/text_input.hpp"

namespace sepax::cli::io {

namespace {

/// Whether a face entry is v, v/vt, v//vn or v/vt/vn (also v/, as some
/// exporters write it) with integer texture and normal indices: they are
/// read past, not used, but "1/1/1/1" or "1/x" is not OBJ.
bool face_entry_well_formed(std::string_view entry) {
  const auto slash = entry.find('/');
  if (slash == std::string_view::npos) return true;
  auto integer = [](std::string_view t) {
    if (t.starts_with('-')) t.remove_prefix(1);
    return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  const std::string_view rest = entry.substr(slash + 1);
  const auto second = rest.find('/');
  if (second == std::string_view::npos) return rest.empty() || integer(rest);  // v/ or v/vt
  const std::string_view vt = rest.substr(0, second), vn = rest.substr(second + 1);
  return (vt.empty() || integer(vt)) && integer(vn);  // v//vn or v/vt/vn (a third '/' is not an integer)
}

/// The name an 'o' or 'g' statement gives: the rest of the line, or "" (the
/// default group) when there is none.
std::string statement_name(const std::vector<std::string_view>& tok) {
  std::string n;
  for (std::size_t k = 1; k < tok.size(); ++k) {
    if (k > 1) n += ' ';
    n += tok[k];
  }
  return n;
}

/// One object: the faces whose 'o' (or, without any 'o', 'g') name is name,
/// with the vertices they use, renumbered in file order.
ShapeData object_shape(const ShapeData& all, const std::string& name, const std::vector<std::size_t>& faces) {
  ShapeData out;
  out.kind = ShapeData::Kind::Faces;
  out.name = name;
  out.from_file = true;
  std::vector<int> renumber(all.vertices.size(), -1);
  for (const std::size_t f : faces) {
    for (const int v : all.faces[f]) renumber[static_cast<std::size_t>(v)] = 0;
  }
  for (std::size_t v = 0; v < renumber.size(); ++v) {
    if (renumber[v] < 0) continue;
    renumber[v] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(all.vertices[v]);
    out.vertex_lines.push_back(all.vertex_lines[v]);
  }
  for (const std::size_t f : faces) {
    std::vector<int> loop;
    for (const int v : all.faces[f]) loop.push_back(renumber[static_cast<std::size_t>(v)]);
    out.faces.push_back(std::move(loop));
    out.face_lines.push_back(all.face_lines[f]);
  }
  return out;
}

}  // namespace

std::vector<ObjObject> read_obj_objects(std::istream& in, const std::string& name) {
  LineReader r(in, name);
  ShapeData out;
  out.kind = ShapeData::Kind::Faces;
  out.name = name;
  std::string line;
  bool any_content = false;
  // The current 'o' and 'g' names, and each face's.
  std::string o_name, g_name;
  bool any_o = false;
  std::vector<std::string> face_o, face_g;
  while (r.next(line)) {
    const auto tok = tokens(line);
    if (tok.empty()) continue;
    any_content = true;
    if (tok[0] == "v") {
      const std::string what = "vertex " + std::to_string(out.vertices.size() + 1);
      const std::size_t n = tok.size() - 1;
      if (n < 3)
        r.fail(what + " has " + std::to_string(n) + " value" + (n == 1 ? "" : "s") + "; expected 'v x y z'");
      if (n == 5 || n > 7)
        r.fail(what + " has " + std::to_string(n) + " values; expected x y z [w] or x y z r g b");
      Vec3<double> p;
      for (int c = 0; c < 3; ++c) {
        p[c] = parse_double(r, tok[static_cast<std::size_t>(c) + 1],
                            [&] { return "coordinate " + std::string(1, "xyz"[c]) + " of " + what; });
      }
      if (n == 4) {
        const double w = parse_double(r, tok[4], [&] { return "w of " + what; });
        if (w != 1.0) r.fail(what + " has w = " + std::string(tok[4]) + "; only w = 1 is supported");
      } else {
        for (std::size_t c = 4; c <= n; ++c)
          (void)parse_double(r, tok[c], [&] { return "a colour value of " + what; });
      }
      out.vertices.push_back(p);
      out.vertex_lines.push_back(r.line_number());
    } else if (tok[0] == "f") {
      const std::string what = "face " + std::to_string(out.faces.size() + 1);
      if (tok.size() - 1 < 3) {
        r.fail(what + " has " + std::to_string(tok.size() - 1) + " vertices; a face needs at least 3");
      }
      std::vector<int> face;
      const auto nv = static_cast<long long>(out.vertices.size());
      for (std::size_t k = 1; k < tok.size(); ++k) {
        const std::string_view entry = tok[k];
        if (!face_entry_well_formed(entry))
          r.fail(what + ": bad vertex entry " + shown(entry) + " (expected v, v/vt, v//vn or v/vt/vn)");
        const std::string_view index = entry.substr(0, entry.find('/'));
        const long long i = parse_integer(r, index, [&] { return "a vertex index of " + what; });
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
      face_o.push_back(o_name);
      face_g.push_back(g_name);
    } else if (tok[0] == "o") {
      o_name = statement_name(tok);
      any_o = true;
    } else if (tok[0] == "g") {
      g_name = statement_name(tok);
    }
    // every other statement is ignored
  }
  if (!any_content) r.fail("empty file: no 'v' or 'f' statements");
  if (out.vertices.empty()) r.fail("no vertices ('v' lines) in the file");
  if (out.faces.empty()) {
    // Only 'v' lines: a point cloud (a scan exported as OBJ), one point set to be hulled.
    out.kind = ShapeData::Kind::Points;
    return {ObjObject{"", std::move(out)}};
  }

  // Objects by 'o' name when the file has 'o' statements, else by 'g' name;
  // statements of the same name are one object, in order of first use.
  const std::vector<std::string>& key = any_o ? face_o : face_g;
  std::vector<std::string> names;
  std::map<std::string, std::vector<std::size_t>> faces_of;
  for (std::size_t f = 0; f < key.size(); ++f) {
    auto& list = faces_of[key[f]];
    if (list.empty()) names.push_back(key[f]);
    list.push_back(f);
  }
  std::vector<ObjObject> objects;
  if (names.size() == 1) {
    // One object: the file itself (vertices no face uses are dropped).
    objects.push_back(ObjObject{names[0], object_shape(out, name, faces_of[names[0]])});
    return objects;
  }
  for (std::size_t k = 0; k < names.size(); ++k) {
    objects.push_back(
        ObjObject{names[k], object_shape(out, name + "#" + (names[k].empty() ? std::to_string(k) : names[k]),
                                         faces_of[names[k]])});
  }
  return objects;
}

std::string object_list(const std::vector<ObjObject>& objects) {
  std::string s;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    s += (k ? ", " : "") + std::to_string(k) + " '" + objects[k].name + "'";
  }
  return s;
}

ShapeData select_object(const std::vector<ObjObject>& objects, const std::string& file,
                        const std::optional<std::string>& selector) {
  if (!selector) {
    if (objects.size() == 1) return objects[0].shape;
    throw InvalidInput(ErrorCode::Parse, file + ": the file holds " + std::to_string(objects.size()) +
                                             " objects (" + object_list(objects) + "); select one with " +
                                             file + "#NAME or " + file + "#K ('sepax info " + file +
                                             "' lists them)");
  }
  for (const auto& o : objects) {
    if (o.name == *selector) return o.shape;
  }
  std::size_t k = 0;
  const auto r = std::from_chars(selector->data(), selector->data() + selector->size(), k);
  if (!selector->empty() && r.ec == std::errc() && r.ptr == selector->data() + selector->size() &&
      k < objects.size()) {
    return objects[k].shape;
  }
  throw InvalidInput(ErrorCode::Parse, file + ": no object '" + *selector + "' (the file holds " +
                                           std::to_string(objects.size()) + ": " + object_list(objects) +
                                           ")");
}

ShapeData read_obj(std::istream& in, const std::string& name) {
  return select_object(read_obj_objects(in, name), name, std::nullopt);
}

ShapeData read_obj_file(const std::string& path) {
  auto in = open_input(path);
  return read_obj(in, path);
}

}  // namespace sepax::cli::io
