// src/commands/audit_command.cpp -- see audit_command.hpp.
#include "commands/audit_command.hpp"

#include <cmath>
#include <cstddef>
#include <iostream>
#include <vector>

#include <sepax/error.hpp>
#include <sepax/fuzz/cli.hpp>
#include <sepax/fuzz/generators.hpp>

#include "io/shape_source.hpp"

namespace sepax::cli {

fuzz::ShapeSpec audit_shape(const std::string& spec, std::ostream& note) {
  const io::ShapeData d = io::load_shape(spec);
  fuzz::ShapeSpec tmp{d.vertices, {}};
  fuzz::round_to_float(tmp);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < d.vertices.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(tmp.vertices[i][c])) {
        throw InvalidInput(ErrorCode::BadScale, d.name + ": coordinate " + "xyz"[c] + " of " +
                                                    (d.kind == io::ShapeData::Kind::Points ? "point " : "vertex ") +
                                                    std::to_string(i) + " (" + format_number(d.vertices[i][c]) +
                                                    ") overflows float, which the audit's input must be");
      }
      if (tmp.vertices[i][c] != d.vertices[i][c]) ++changed;
    }
  }
  if (changed != 0) {
    note << "sepax audit: note: " << d.name << ": " << changed
         << " coordinate(s) rounded to float (float, double and exact runs see the same float-valued input)\n";
  }
  if (d.kind == io::ShapeData::Kind::Points) {
    try {
      return fuzz::hull_of(tmp.vertices);
    } catch (const InvalidInput& e) {
      throw InvalidInput(e.code(), d.name + ": " + e.what());
    }
  }
  tmp.faces = d.closed_faces();
  return tmp;
}

int audit_main(int argc, char** argv) {
  return fuzz::audit_main(
      argc, argv, [](const std::string& s) { return audit_shape(s, std::cerr); },
      "a built-in shape (cube, box:HX,HY,HZ, tetra, prism:N, polygon:N, triangle), an OFF or OBJ face list, or a "
      "points file (.pts, .xyz, .txt: hulled in float); coordinates are rounded to float");
}

}  // namespace sepax::cli
