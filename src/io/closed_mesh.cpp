// src/io/closed_mesh.cpp -- see closed_mesh.hpp.
#include "io/closed_mesh.hpp"

#include <array>
#include <map>
#include <string>
#include <utility>

#include <sepax/error.hpp>

namespace sepax::cli::io {

namespace {

[[noreturn]] void fail(ErrorCode code, const std::string& what) {
  throw InvalidInput(code, what + kHullHint);
}

}  // namespace

ClosedMesh closed_mesh(const ShapeData& s) {
  ClosedMesh m;
  // Weld: a file exported with texture seams repeats a position under
  // several indices; such copies are one vertex of the surface.
  std::map<std::array<double, 3>, int> id_of;
  // Only the vertices the faces use (the hull is taken over them).
  std::vector<char> used(s.vertices.size(), 0);
  for (const auto& f : s.faces) {
    for (const int v : f) used[static_cast<std::size_t>(v)] = 1;
  }
  std::vector<int> welded(s.vertices.size(), -1);
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    if (!used[v]) continue;
    const std::array<double, 3> key{s.vertices[v][0], s.vertices[v][1], s.vertices[v][2]};
    const auto [it, fresh] = id_of.try_emplace(key, static_cast<int>(m.vertex.size()));
    if (fresh) m.vertex.push_back(static_cast<int>(v));
    welded[v] = it->second;
  }
  // The first face using each directed edge (welded indices).
  std::map<std::pair<int, int>, int> face_of;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    std::vector<int> loop;
    for (const int v : s.faces[f]) loop.push_back(welded[static_cast<std::size_t>(v)]);
    const std::string fname = "face " + std::to_string(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      for (std::size_t j = i + 1; j < loop.size(); ++j) {
        if (loop[i] == loop[j]) {
          fail(ErrorCode::DegenerateFace, fname + " uses the point of vertex " +
                                              std::to_string(m.vertex[static_cast<std::size_t>(loop[i])]) +
                                              " twice");
        }
      }
    }
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::pair<int, int> e{loop[i], loop[(i + 1) % loop.size()]};
      const auto [it, fresh] = face_of.try_emplace(e, static_cast<int>(f));
      if (!fresh) {
        fail(ErrorCode::NotManifold,
             fname + ": its edge " + std::to_string(m.vertex[static_cast<std::size_t>(e.first)]) + "-" +
                 std::to_string(m.vertex[static_cast<std::size_t>(e.second)]) + " is also an edge of face " +
                 std::to_string(it->second) +
                 " in the same direction: the faces are inconsistently oriented, or more than two faces meet "
                 "at the edge (not a 2-manifold)");
      }
    }
    m.faces.push_back(std::move(loop));
  }
  for (const auto& [e, f] : face_of) {
    if (!face_of.count({e.second, e.first})) {
      fail(ErrorCode::NotManifold, "face " + std::to_string(f) + ": its edge " +
                                       std::to_string(m.vertex[static_cast<std::size_t>(e.first)]) + "-" +
                                       std::to_string(m.vertex[static_cast<std::size_t>(e.second)]) +
                                       " is on no other face: the mesh is open (it has a hole or a border)");
    }
  }
  return m;
}

}  // namespace sepax::cli::io
