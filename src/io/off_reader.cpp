// src/io/off_reader.cpp -- see off_reader.hpp.
#include "io/off_reader.hpp"

#include "io/open_file.hpp"
#include "io/text_input.hpp"

namespace sepax::cli::io {

namespace {

constexpr long long kMaxCount = 50'000'000;  // far beyond any convex polyhedron sepax can use

// "OFF" with optional prefixes ST, C, N, 4, n (in that order).  Returns false
// if token is not an OFF keyword; sets extra_values when the variant carries
// more than x y z per vertex.
bool off_keyword(const LineReader& r, std::string_view tok, bool& extra_values) {
  if (tok.size() < 3 || tok.substr(tok.size() - 3) != "OFF") return false;
  std::string_view pre = tok.substr(0, tok.size() - 3);
  if (pre.starts_with("ST")) pre.remove_prefix(2);
  if (pre.starts_with("C")) pre.remove_prefix(1);
  if (pre.starts_with("N")) pre.remove_prefix(1);
  if (pre.starts_with("4") || pre.starts_with("n")) {
    r.fail("unsupported header " + shown(tok) + ": only 3-dimensional OFF is supported");
  }
  if (!pre.empty()) return false;
  extra_values = tok != "OFF";
  return true;
}

}  // namespace

ShapeData read_off(std::istream& in, const std::string& name) {
  LineReader r(in, name);
  ShapeData out;
  out.kind = ShapeData::Kind::Faces;
  out.name = name;
  out.from_file = true;
  std::string line;
  std::vector<std::string_view> tok;

  // Next line with at least one token; false at end of file.
  const auto next_tokens = [&]() {
    while (r.next(line)) {
      tok = tokens(line);
      if (!tok.empty()) return true;
    }
    return false;
  };

  // Header (optional) and counts.
  if (!next_tokens()) r.fail("empty file: expected the OFF header");
  bool extra_values = false;
  std::vector<std::string_view> counts;
  if (off_keyword(r, tok[0], extra_values)) {
    if (tok.size() > 1 && tok[1] == "BINARY") r.fail("binary OFF is not supported");
    counts.assign(tok.begin() + 1, tok.end());
    if (counts.empty()) {
      if (!next_tokens()) r.fail("unexpected end of file: missing the counts line 'V F E'");
      counts = tok;
    }
  } else if (!tok[0].empty() && (tok[0][0] >= '0' && tok[0][0] <= '9')) {
    counts = tok;  // no header: the file starts with the counts
  } else {
    r.fail("expected the OFF header, found " + shown(tok[0]));
  }
  if (counts.size() < 2) r.fail("missing counts: expected 'V F E' (vertex, face and edge counts)");
  if (counts.size() > 3) r.fail("too many values on the counts line: expected 'V F E'");
  const long long nv = parse_count(r, counts[0], "the vertex count", kMaxCount);
  const long long nf = parse_count(r, counts[1], "the face count", kMaxCount);
  if (counts.size() == 3) (void)parse_count(r, counts[2], "the edge count", 3 * kMaxCount);
  if (nv < 3) r.fail("the file declares " + std::to_string(nv) + " vertices; a polyhedron needs at least 3");
  // 0 faces: the vertices are a point set (an OFF point cloud), to be hulled.
  if (nf == 0) out.kind = ShapeData::Kind::Points;

  for (long long i = 0; i < nv; ++i) {
    if (!next_tokens()) {
      r.fail("unexpected end of file: expected " + std::to_string(nv) + " vertices, found " +
             std::to_string(i));
    }
    const std::string what = "vertex " + std::to_string(i);
    if (tok.size() < 3) {
      r.fail(what + " has " + std::to_string(tok.size()) + " value" + (tok.size() == 1 ? "" : "s") +
             "; expected 3 (x y z)");
    }
    if (tok.size() > 3 && !extra_values) {
      r.fail(what + " has " + std::to_string(tok.size()) + " values; expected 3 (x y z)");
    }
    Vec3<double> p;
    for (int c = 0; c < 3; ++c) {
      p[c] = parse_double(r, tok[static_cast<std::size_t>(c)],
                          [&] { return "coordinate " + std::string(1, "xyz"[c]) + " of " + what; });
    }
    out.vertices.push_back(p);
    out.vertex_lines.push_back(r.line_number());
  }

  for (long long f = 0; f < nf; ++f) {
    if (!next_tokens()) {
      r.fail("unexpected end of file: expected " + std::to_string(nf) + " faces, found " + std::to_string(f));
    }
    const std::string what = "face " + std::to_string(f);
    const long long n = parse_count(r, tok[0], "the vertex count of " + what, kMaxCount);
    if (n < 3) r.fail(what + " has " + std::to_string(n) + " vertices; a face needs at least 3");
    if (static_cast<long long>(tok.size()) - 1 < n) {
      r.fail(what + " declares " + std::to_string(n) + " vertices but lists " +
             std::to_string(tok.size() - 1));
    }
    std::vector<int> face;
    for (long long k = 1; k <= n; ++k) {
      const long long idx =
          parse_integer(r, tok[static_cast<std::size_t>(k)], [&] { return "a vertex index of " + what; });
      if (idx < 0 || idx >= nv) {
        r.fail(what + ": vertex index " + std::to_string(idx) + " is out of range (the file has " +
               std::to_string(nv) + " vertices, indices 0.." + std::to_string(nv - 1) + ")");
      }
      face.push_back(static_cast<int>(idx));
    }
    out.faces.push_back(std::move(face));
    out.face_lines.push_back(r.line_number());
  }

  if (next_tokens()) {
    r.fail("unexpected content after the last face (the counts line declares " + std::to_string(nf) +
           " faces)");
  }
  return out;
}

ShapeData read_off_file(const std::string& path) {
  auto in = open_input(path);
  return read_off(in, path);
}

}  // namespace sepax::cli::io
