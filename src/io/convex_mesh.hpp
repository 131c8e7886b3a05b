// src/io/convex_mesh.hpp
//
// convex_mesh<T>: a face list that is a closed convex mesh, triangulated or
// with any number of coplanar faces per side, as the convex polyhedron it
// bounds -- the hull of its vertices (sepax::convex_hull<T>, which merges
// coplanar faces: within Tolerances<T>::kCoplanar * extent for float and
// double, exactly for exact types).
//
// The mesh is accepted only when it is its own hull:
//   1. closed_mesh(): the faces form a closed, consistently oriented
//      2-manifold (vertices of identical coordinates welded);
//   2. every face lies in the plane of a hull face -- each of its vertices
//      within Tolerances<T>::kPlanarity * extent of it (exactly on it for
//      exact T) -- and turns the same way (its Newell normal has a positive
//      dot product with the hull face's outward normal);
//   3. the faces' total area is less than 1.5 times the hull's surface area.
// Why that is equivalent to "the mesh bounds a convex polyhedron": 2 puts
// every face inside a hull face (its vertices are points of the set, so in
// the hull, and on that face's plane), so the closed surface of 1 lies on
// the hull's boundary, each face covering its part of it the right way
// round.  A closed oriented surface laid on a sphere like that covers it a
// whole number d >= 1 of times, with d times its area; 3 leaves d = 1: the
// faces tile the hull's boundary exactly once, so the mesh is the hull.
// Conversely the faces of a convex mesh lie in its supporting planes, which
// are its hull's face planes, with the outward orientation, and tile the
// boundary once.  A vertex inside the hull (a dent), a face across the
// inside or a face turned inwards fails 2.
//
// Errors: InvalidInput naming the face ("face K ...") or edge, ending with
// kHullHint.
#pragma once

#include <cmath>
#include <type_traits>
#include <string>
#include <vector>

#include <sepax/convex_hull.hpp>
#include <sepax/convex_polyhedron.hpp>
#include <sepax/error.hpp>
#include <sepax/tolerances.hpp>

#include "io/closed_mesh.hpp"
#include "io/shape_data.hpp"

namespace sepax::cli::io {

namespace detail {

/// Twice the vector area of a loop (Newell), in T (exact for exact T) or,
/// for float, in double from the float coordinates.
template <Number T>
auto newell(const std::vector<Vec3<T>>& p, const std::vector<int>& loop) {
  using W = std::conditional_t<number_traits<T>::is_exact, T, double>;
  Vec3<W> n(W(0), W(0), W(0));
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto& a = p[static_cast<std::size_t>(loop[i])];
    const auto& b = p[static_cast<std::size_t>(loop[(i + 1) % loop.size()])];
    if constexpr (number_traits<T>::is_exact) {
      n = n + cross(a, b);
    } else {
      n = n + cross(vec_to_double(a), vec_to_double(b));
    }
  }
  return n;
}

/// Height of x above plane pl (in T for exact T, else in double).
template <Number T>
auto height(const Plane<T>& pl, const Vec3<T>& x) {
  if constexpr (number_traits<T>::is_exact) {
    return T(dot(pl.normal, x) - pl.offset);
  } else {
    return dot(vec_to_double(pl.normal), vec_to_double(x)) - number_traits<T>::to_double(pl.offset);
  }
}

}  // namespace detail

/// The polyhedron bounded by the closed convex mesh s, whose vertices in T
/// (any frame) are v.  Throws InvalidInput when s is not one (see above).
template <Number T>
ConvexPolyhedron<T> convex_mesh(const ShapeData& s, const std::vector<Vec3<T>>& v) {
  const ClosedMesh m = closed_mesh(s);
  std::vector<Vec3<T>> pts;
  pts.reserve(m.vertex.size());
  for (const int i : m.vertex) pts.push_back(v[static_cast<std::size_t>(i)]);
  ConvexPolyhedron<T> hull = convex_hull<T>(pts);
  if (hull.is_flat()) {
    throw InvalidInput(ErrorCode::NotConvex,
                       std::string("the faces enclose no volume: every vertex is on one plane") + kHullHint);
  }
  // float/double: relative to the extent; the plane's normal is unit length.
  const double tol = Tolerances<T>::kPlanarity * hull.extent();
  const auto on_plane = [&](const Plane<T>& pl, const Vec3<T>& x) {
    if constexpr (number_traits<T>::is_exact) {
      return detail::height(pl, x) == T(0);
    } else {
      return std::abs(detail::height(pl, x)) <= tol;
    }
  };
  double mesh_area = 0, hull_area = 0;
  for (int h = 0; h < hull.face_count(); ++h) {
    std::vector<int> loop = hull.face_vertices(h);
    hull_area += std::sqrt(squared_norm(vec_to_double(detail::newell(hull.vertices(), loop)))) / 2;
  }
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const auto& loop = m.faces[f];
    const auto n = detail::newell(pts, loop);
    mesh_area += std::sqrt(squared_norm(vec_to_double(n))) / 2;
    bool found = false;
    for (int h = 0; h < hull.face_count() && !found; ++h) {
      const Plane<T>& pl = hull.plane(h);
      bool in = true;
      for (const int i : loop) in = in && on_plane(pl, pts[static_cast<std::size_t>(i)]);
      if (!in) continue;
      if constexpr (number_traits<T>::is_exact) {
        found = dot(n, pl.normal) > T(0);
      } else {
        found = dot(n, vec_to_double(pl.normal)) > 0;
      }
    }
    if (found) continue;
    // Why not: a vertex strictly inside the hull (a dent), else the face
    // crosses the inside or faces inwards.
    for (const int i : loop) {
      bool inside = true;
      for (int h = 0; h < hull.face_count() && inside; ++h) {
        const auto d = detail::height(hull.plane(h), pts[static_cast<std::size_t>(i)]);
        if constexpr (number_traits<T>::is_exact) {
          inside = d < T(0);
        } else {
          inside = d < -tol;
        }
      }
      if (inside) {
        throw InvalidInput(ErrorCode::NotConvex,
                           "face " + std::to_string(f) + ": its vertex " +
                               std::to_string(m.vertex[static_cast<std::size_t>(i)]) +
                               " is inside the convex hull of the vertices: the mesh is not convex" +
                               kHullHint);
      }
    }
    throw InvalidInput(
        ErrorCode::NotConvex,
        "face " + std::to_string(f) +
            " is not on the boundary of the convex hull of the vertices, facing out: the mesh is "
            "not convex, or the face is turned inwards" +
            kHullHint);
  }
  if (!(mesh_area < 1.5 * hull_area)) {
    throw InvalidInput(ErrorCode::NotManifold,
                       "the faces cover the surface of their convex hull more than once (area " +
                           format_number(mesh_area) + " against " + format_number(hull_area) + ")" +
                           kHullHint);
  }
  return hull;
}

}  // namespace sepax::cli::io
