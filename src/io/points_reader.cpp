// src/io/points_reader.cpp -- see points_reader.hpp.
#include "io/points_reader.hpp"

#include <algorithm>
#include <string_view>

#include "io/open_file.hpp"
#include "io/text_input.hpp"

namespace sepax::cli::io {

ShapeData read_points(std::istream& in, const std::string& name) {
  LineReader r(in, name);
  ShapeData out;
  out.kind = ShapeData::Kind::Points;
  out.name = name;
  std::string line;
  while (r.next(line)) {
    const auto tok = tokens(line, /*commas_separate=*/true);
    if (tok.empty()) continue;
    const std::string what = "point " + std::to_string(out.vertices.size());
    if (tok.size() != 3) {
      r.fail(what + " has " + std::to_string(tok.size()) + " value" + (tok.size() == 1 ? "" : "s") +
             "; expected 3 (x y z)");
    }
    // commas, when used, separate the three values: two of them, no empty value ("1,,2,3", "4,5,6,")
    const std::string_view data = std::string_view(line).substr(0, std::string_view(line).find('#'));
    if (const auto commas = std::count(data.begin(), data.end(), ','); commas != 0 && commas != 2)
      r.fail(what + " has " + std::to_string(commas) + (commas == 1 ? " comma" : " commas") +
             "; commas separate exactly 3 values (x,y,z)");
    Vec3<double> p;
    for (int c = 0; c < 3; ++c) {
      p[c] = parse_double(r, tok[static_cast<std::size_t>(c)],
                          [&] { return "coordinate " + std::string(1, "xyz"[c]) + " of " + what; });
    }
    out.vertices.push_back(p);
  }
  if (out.vertices.empty()) r.fail("empty file: no points");
  return out;
}

ShapeData read_points_file(const std::string& path) {
  auto in = open_input(path);
  return read_points(in, path);
}

}  // namespace sepax::cli::io
