// src/io/closed_mesh.cpp -- see closed_mesh.hpp.
//
// Sorting, not maps: a scanned mesh has millions of faces, and a sorted
// vector of directed edges is a fraction of a map's time and memory.  The
// errors are the ones a walk over the faces in file order meets first.
#include "io/closed_mesh.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <tuple>
#include <utility>

#include <sepax/error.hpp>

namespace sepax::cli::io {

namespace {

[[noreturn]] void fail(ErrorCode code, const std::string& what) {
  throw InvalidInput(code, what + kHullHint);
}

struct DirectedEdge {
  int from, to;
  int face, position;  // the face using it, and where in its loop
  auto key() const { return std::tie(from, to, face, position); }
};

}  // namespace

ClosedMesh closed_mesh(const ShapeData& s) {
  ClosedMesh m;
  // Weld: a file exported with texture seams repeats a position under
  // several indices; such copies are one vertex of the surface, numbered in
  // the order of their first index.  Only the vertices the faces use count
  // (the hull is taken over them).
  const std::size_t n = s.vertices.size();
  std::vector<char> used(n, 0);
  for (const auto& f : s.faces) {
    for (const int v : f) used[static_cast<std::size_t>(v)] = 1;
  }
  const auto point = [&](std::size_t v) {
    return std::array<double, 3>{s.vertices[v][0], s.vertices[v][1], s.vertices[v][2]};
  };
  std::vector<int> order;
  for (std::size_t v = 0; v < n; ++v) {
    if (used[v]) order.push_back(static_cast<int>(v));
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const auto pa = point(static_cast<std::size_t>(a)), pb = point(static_cast<std::size_t>(b));
    return pa < pb || (!(pb < pa) && a < b);
  });
  std::vector<int> first(n, -1);  // used vertex -> the first index of its position
  for (std::size_t i = 0; i < order.size(); ++i) {
    const auto v = static_cast<std::size_t>(order[i]);
    const bool same = i > 0 && !(point(static_cast<std::size_t>(order[i - 1])) < point(v));
    first[v] = same ? first[static_cast<std::size_t>(order[i - 1])] : order[i];
  }
  std::vector<int> welded(n, -1);
  for (std::size_t v = 0; v < n; ++v) {
    if (!used[v]) continue;
    if (first[v] == static_cast<int>(v)) {
      welded[v] = static_cast<int>(m.vertex.size());
      m.vertex.push_back(static_cast<int>(v));
    } else {
      welded[v] = welded[static_cast<std::size_t>(first[v])];
    }
  }
  // The welded loops; the first face (in file order) repeating a point.
  std::size_t edge_count = 0;
  m.faces.reserve(s.faces.size());
  for (const auto& f : s.faces) {
    std::vector<int> loop;
    loop.reserve(f.size());
    for (const int v : f) loop.push_back(welded[static_cast<std::size_t>(v)]);
    edge_count += loop.size();
    m.faces.push_back(std::move(loop));
  }
  std::size_t degenerate = m.faces.size();
  int repeated = -1;
  for (std::size_t f = 0; f < m.faces.size() && degenerate == m.faces.size(); ++f) {
    const auto& loop = m.faces[f];
    for (std::size_t i = 0; i < loop.size() && repeated < 0; ++i) {
      for (std::size_t j = i + 1; j < loop.size(); ++j) {
        if (loop[i] == loop[j]) {
          degenerate = f;
          repeated = loop[i];
          break;
        }
      }
    }
  }
  // Every directed edge, sorted: a repeated one is a second use of an edge
  // in the same direction.
  std::vector<DirectedEdge> edges;
  edges.reserve(edge_count);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const auto& loop = m.faces[f];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      edges.push_back({loop[i], loop[(i + 1) % loop.size()], static_cast<int>(f), static_cast<int>(i)});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const DirectedEdge& a, const DirectedEdge& b) { return a.key() < b.key(); });
  const DirectedEdge* again = nullptr;  // the repeated use met first in file order
  const DirectedEdge* again_first = nullptr;
  for (std::size_t i = 1; i < edges.size(); ++i) {
    if (edges[i].from != edges[i - 1].from || edges[i].to != edges[i - 1].to) continue;
    if (!again || std::tie(edges[i].face, edges[i].position) < std::tie(again->face, again->position)) {
      again = &edges[i];
      std::size_t k = i;
      while (k > 0 && edges[k - 1].from == edges[i].from && edges[k - 1].to == edges[i].to) --k;
      again_first = &edges[k];
    }
  }
  const auto name = [&](int welded_vertex) {
    return std::to_string(m.vertex[static_cast<std::size_t>(welded_vertex)]);
  };
  if (degenerate < m.faces.size() && (!again || static_cast<int>(degenerate) <= again->face)) {
    fail(ErrorCode::DegenerateFace,
         "face " + std::to_string(degenerate) + " uses the point of vertex " + name(repeated) + " twice");
  }
  if (again) {
    fail(ErrorCode::NotManifold,
         "face " + std::to_string(again->face) + ": its edge " + name(again->from) + "-" + name(again->to) +
             " is also an edge of face " + std::to_string(again_first->face) +
             " in the same direction: the faces are inconsistently oriented, or more than two faces meet "
             "at the edge (not a 2-manifold)");
  }
  // Each directed edge's reverse must be there too.
  for (const DirectedEdge& e : edges) {
    const DirectedEdge reverse{e.to, e.from, -1, -1};
    const auto it =
        std::lower_bound(edges.begin(), edges.end(), reverse,
                         [](const DirectedEdge& a, const DirectedEdge& b) { return a.key() < b.key(); });
    if (it == edges.end() || it->from != e.to || it->to != e.from) {
      fail(ErrorCode::NotManifold, "face " + std::to_string(e.face) + ": its edge " + name(e.from) + "-" +
                                       name(e.to) +
                                       " is on no other face: the mesh is open (it has a hole or a border)");
    }
  }
  return m;
}

}  // namespace sepax::cli::io
