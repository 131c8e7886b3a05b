// sepax/convex_polyhedron_topology.hpp
//
// ConvexPolyhedron<T>'s topology (convex_polyhedron.hpp declares the class):
//   * build_topology(): the face loops to half-edges stored in twin pairs
//     (edge k = half-edges 2k, 2k+1), each vertex's fan of outgoing
//     half-edges, and the checks that the faces form a closed, consistently
//     oriented 2-manifold of genus 0 (NotManifold otherwise);
//   * choose_plane_triples(): for each face the three vertices that define
//     its plane, the best-conditioned triangle of its loop (triangle_area2()),
//     chosen the same way with and without FMA contraction.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "convex_polyhedron.hpp"

namespace sepax {

template <Number T>
inline void ConvexPolyhedron<T>::build_topology(const std::vector<std::vector<int>>& faces) {
  const int nv = vertex_count();
  detail::PolyhedronTopology& topo = topology_.edit();
  if (faces.size() < 2) fail(ErrorCode::NotManifold, "a closed polyhedron needs at least 2 faces");
  // The directed edges leaving each vertex, in the order the loops list
  // them (out_[out_start[u] ..]), each with its half-edge once assigned:
  // (u, v) was seen before iff one of u's assigned slots heads to v.
  struct OutEdge {
    int head, half_edge;
  };
  std::vector<int> out_start(static_cast<std::size_t>(nv) + 1, 0);
  for (const auto& loop : faces)
    for (int u : loop)
      if (u >= 0 && u < nv) ++out_start[static_cast<std::size_t>(u) + 1];
  for (int v = 0; v < nv; ++v)
    out_start[static_cast<std::size_t>(v) + 1] += out_start[static_cast<std::size_t>(v)];
  std::vector<OutEdge> out(static_cast<std::size_t>(out_start.back()));
  std::vector<int> out_next(out_start.begin(), out_start.end() - 1);  // u's first unassigned slot
  auto seen = [&](int u, int v) {  // the half-edge of an earlier u -> v, or -1
    for (int k = out_start[static_cast<std::size_t>(u)]; k < out_next[static_cast<std::size_t>(u)]; ++k)
      if (out[static_cast<std::size_t>(k)].head == v) return out[static_cast<std::size_t>(k)].half_edge;
    return -1;
  };
  topo.half_edges.clear();
  topo.faces.clear();
  topo.half_edges.reserve(out.size() + 1);  // (a valid surface has exactly out.size())
  topo.faces.reserve(faces.size());
  std::vector<int> loop_edges;  // (face f's half-edges; one buffer for every face)
  std::vector<int> face_mark(static_cast<std::size_t>(nv), 0);  // (a repeated vertex in one loop)
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& loop = faces[f];
    auto fname = [f] { return "face " + std::to_string(f); };  // (for messages)
    if (loop.size() < 3) fail(ErrorCode::DegenerateFace, fname() + " has fewer than 3 vertices");
    for (std::size_t i = 0; i < loop.size(); ++i) {
      if (loop[i] < 0 || loop[i] >= nv) {
        fail(ErrorCode::BadIndex, fname() + " refers to vertex " + std::to_string(loop[i]) +
                                      ", but there are only " + std::to_string(nv) + " vertices");
      }
      // (linear in the loop: a vertex's mark is the last face that used it, plus one)
      int& mark = face_mark[static_cast<std::size_t>(loop[i])];
      if (mark == static_cast<int>(f) + 1)
        fail(ErrorCode::DegenerateFace, fname() + " uses vertex " + std::to_string(loop[i]) + " twice");
      mark = static_cast<int>(f) + 1;
    }
    FaceLoop fl;
    fl.count = static_cast<int>(loop.size());
    loop_edges.clear();
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int u = loop[i];
      const int v = loop[(i + 1) % loop.size()];
      if (seen(u, v) >= 0) {
        fail(ErrorCode::NotManifold,
             "edge " + std::to_string(u) + "->" + std::to_string(v) +
                 " is used twice in the same direction (second time in " + fname() +
                 "): faces are inconsistently oriented or the surface is not a 2-manifold");
      }
      const auto key = std::minmax(u, v);
      int h;
      const int twin = seen(v, u);
      if (twin < 0) {
        const int e = static_cast<int>(topo.half_edges.size() / 2);
        topo.half_edges.push_back(HalfEdge{});
        topo.half_edges.push_back(HalfEdge{});
        h = 2 * e;
      } else {
        h = 2 * (twin / 2) + 1;
        if (topo.half_edges[static_cast<std::size_t>(h)].face != -1) {
          fail(ErrorCode::NotManifold, "edge " + std::to_string(key.first) + "-" +
                                           std::to_string(key.second) + " is shared by more than two faces");
        }
      }
      out[static_cast<std::size_t>(out_next[static_cast<std::size_t>(u)]++)] = OutEdge{v, h};
      topo.half_edges[static_cast<std::size_t>(h)].origin = u;
      topo.half_edges[static_cast<std::size_t>(h)].face = static_cast<int>(f);
      loop_edges.push_back(h);
    }
    for (std::size_t i = 0; i < loop_edges.size(); ++i) {
      auto& he = topo.half_edges[static_cast<std::size_t>(loop_edges[i])];
      he.next = loop_edges[(i + 1) % loop_edges.size()];
      he.prev = loop_edges[(i + loop_edges.size() - 1) % loop_edges.size()];
    }
    fl.edge = loop_edges[0];
    topo.faces.push_back(fl);
  }
  for (std::size_t h = 0; h < topo.half_edges.size(); ++h) {
    if (topo.half_edges[h].face == -1) {
      const auto& o = topo.half_edges[h ^ 1];
      const int u = o.origin;
      const int v = topo.half_edges[static_cast<std::size_t>(o.next)].origin;
      fail(ErrorCode::NotManifold, "edge " + std::to_string(u) + "-" + std::to_string(v) +
                                       " has only one face: the surface is not closed");
    }
  }
  // vertex fans
  std::vector<int> degree(static_cast<std::size_t>(nv), 0);
  for (const auto& he : topo.half_edges) ++degree[static_cast<std::size_t>(he.origin)];
  for (int v = 0; v < nv; ++v) {
    if (degree[static_cast<std::size_t>(v)] == 0) {
      fail(ErrorCode::UnusedVertex, "vertex " + std::to_string(v) + " is on no face");
    }
  }
  topo.fan_start.assign(static_cast<std::size_t>(nv) + 1, 0);
  for (int v = 0; v < nv; ++v)
    topo.fan_start[static_cast<std::size_t>(v) + 1] =
        topo.fan_start[static_cast<std::size_t>(v)] + degree[static_cast<std::size_t>(v)];
  topo.fan.assign(topo.half_edges.size(), -1);
  std::vector<int> fill(topo.fan_start.begin(), topo.fan_start.end() - 1);
  for (std::size_t h = 0; h < topo.half_edges.size(); ++h) {
    const auto o = static_cast<std::size_t>(topo.half_edges[h].origin);
    topo.fan[static_cast<std::size_t>(fill[o]++)] = static_cast<int>(h);
  }
  topology_.refresh();  // the arrays are complete: the accessors read them from here on
  const long euler =
      static_cast<long>(nv) - static_cast<long>(edge_count()) + static_cast<long>(face_count());
  if (euler != 2) {
    fail(ErrorCode::BadEuler, "V - E + F = " + std::to_string(nv) + " - " + std::to_string(edge_count()) +
                                  " + " + std::to_string(face_count()) + " = " + std::to_string(euler) +
                                  ", not 2: the surface is not a topological sphere");
  }
}

// Plane triple: the best-conditioned triangle (0, j, k) of the face loop
// (largest |cross| in T) for faces of up to 16 vertices; (0, n/3, 2n/3) for
// larger ones.  For the back face of a flat shape, the front face's triple
// reversed, so the two normals are exactly opposite.
// |(b-a) x (c-a)|^2, for choosing plane triples.  For float T every product
// is rounded on its own (volatile stores), so no a*b+c can be fused into an
// FMA: the choice -- which the exact images inherit through convert_from --
// is then the same with and without -march=native -ffp-contract=fast (ties
// between equally good triangles are common in symmetric faces).  Without
// contraction the values are exactly those of cross() and squared_norm().
template <Number T>
inline T ConvexPolyhedron<T>::triangle_area2(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  const Vec3<T> u(b - a), w(c - a);
  if constexpr (number_traits<T>::is_exact) {
    return squared_norm(cross(u, w));
  } else {
    const auto mul = [](T x, T y) {
      volatile T r = x * y;
      return static_cast<T>(r);
    };
    const T x = T(mul(u[1], w[2]) - mul(u[2], w[1]));
    const T y = T(mul(u[2], w[0]) - mul(u[0], w[2]));
    const T z = T(mul(u[0], w[1]) - mul(u[1], w[0]));
    T s = mul(x, x);
    s = s + mul(y, y);
    s = s + mul(z, z);
    return s;
  }
}

// For float T the areas are compared on the face's vertices relative to
// loop[0], scaled by one power of two per face (largest |component| in
// [1, 2)): the squared areas then neither overflow nor underflow at any
// scale, and since the scaling is exact and commutes with rounding, every
// comparison -- hence the chosen triple -- is the same as unscaled wherever
// the unscaled squares stayed in range.
template <Number T>
inline void ConvexPolyhedron<T>::choose_plane_triples() {
  detail::PolyhedronTopology& topo = topology_.edit();
  std::vector<int> loop;     // (face f's vertices; one buffer for every face)
  std::vector<Vec3<T>> rel;  // (loop vertices relative to loop[0], scaled for float)
  for (int f = 0; f < face_count(); ++f) {
    face_vertices(f, loop);
    const int n = static_cast<int>(loop.size());
    std::array<int, 3> best{loop[0], loop[1], loop[2]};
    if (n == 3) {
      // a triangle: its one triple
    } else if (n <= 16) {
      rel.clear();
      for (int i = 0; i < n; ++i) rel.push_back(Vec3<T>(vertex(loop[i]) - vertex(loop[0])));
      if constexpr (std::is_floating_point_v<T>) {
        T m(0);
        for (const auto& r : rel) m = std::max(m, detail::max_abs2(r, r));
        if (m > T(0) && m <= std::numeric_limits<T>::max()) {
          const int e = detail::pow2_exponent(m);
          for (auto& r : rel) r = detail::scale_pow2(r, e);
        }
      }
      const Vec3<T> origin(T(0), T(0), T(0));
      T best_area(-1);
      for (int j = 1; j + 1 < n; ++j) {
        for (int k = j + 1; k < n; ++k) {
          const T a =
              triangle_area2(origin, rel[static_cast<std::size_t>(j)], rel[static_cast<std::size_t>(k)]);
          if (a > best_area) {
            best_area = a;
            best = {loop[0], loop[j], loop[k]};
          }
        }
      }
    } else {
      best = {loop[0], loop[n / 3], loop[(2 * n) / 3]};
    }
    topo.faces[static_cast<std::size_t>(f)].plane_vertices = best;
  }
  if (face_count() == 2) {
    const auto& t = topo.faces[0].plane_vertices;
    topo.faces[1].plane_vertices = {t[0], t[2], t[1]};
  }
}

}  // namespace sepax
