// hull_compare_signature.hpp: a polytope as a string up to vertex numbering (tools/hull_compare and the
// exact hull tests compare hulls by it).
#pragma once

#include <sepax/convex_polyhedron.hpp>

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace sepax::hull_compare {

// A polytope up to numbering: its sorted vertices and its faces as loops of
// coordinates, each started at its smallest vertex, sorted.
template <class T>
inline std::string signature(const ConvexPolyhedron<T>& h) {
  using P = std::array<double, 3>;
  auto pt = [&](int v) {
    return P{to_double(h.vertex(v)[0]), to_double(h.vertex(v)[1]), to_double(h.vertex(v)[2])};
  };
  std::vector<P> vs;
  for (int v = 0; v < h.vertex_count(); ++v) vs.push_back(pt(v));
  std::sort(vs.begin(), vs.end());
  std::vector<std::vector<P>> fs;
  for (int f = 0; f < h.face_count(); ++f) {
    std::vector<P> loop;
    for (int v : h.face_vertices(f)) loop.push_back(pt(v));
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    fs.push_back(loop);
  }
  std::sort(fs.begin(), fs.end());
  std::ostringstream s;
  s.precision(17);
  for (const auto& p : vs) s << p[0] << ' ' << p[1] << ' ' << p[2] << ';';
  s << '|';
  for (const auto& l : fs) {
    for (const auto& p : l) s << p[0] << ' ' << p[1] << ' ' << p[2] << ',';
    s << ';';
  }
  return s.str();
}

}  // namespace sepax::hull_compare
