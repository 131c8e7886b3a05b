// sepax/hull/to_polyhedron.hpp
//
// The hull's output as a validated ConvexPolyhedron<T>, with the decisions of ConvexPolyhedron::from_faces:
//   1. exact T, a solid: topology, plane triples and planes as from_faces builds them; when every vertex is
//      exactly a double, the filtered certificate (certify_exact: orientation predicates on the vertices,
//      decided by orientation_filter, in T only when it cannot), else, or when that certificate cannot
//      conclude, from_faces' own exact checks with the local certificate;
//   2. float T, a solid: topology, plane triples and derived data as from_faces builds them; validation
//      with the local convexity certificate (linear), then, on shapes small enough that from_faces scans
//      (faces x vertices <= kConvexityScanPairs), every vertex against every face plane through a
//      VertexTree, which skips only vertices it proves within the convexity tolerance, and skips the faces
//      whose planes the builder's pre-check scanned, bit for bit, with a margin for rounding.  The shape is
//      accepted exactly when from_faces accepts it: the scan rejects every vertex above a plane by more
//      than the tolerance, which is what the full scan, the certificate and the inward-faces test reject.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../error.hpp"
#include "../number_traits.hpp"
#include "../orientation_filter.hpp"
#include "../tolerances.hpp"
#include "../vec3.hpp"
#include "index.hpp"
#include "orientation_filter.hpp"
#include "vertex_tree.hpp"

namespace sepax::hull::detail {

/// Float T: planes the builder's pre-check scanned (precheck.hpp): every output vertex has a computed height
/// T(dot(n, x) - off) of at most below above each of them.
template <class T>
struct ScannedPlanes {
  std::vector<Plane<T>> planes;
  T below = T(0);
};

/// ConvexPolyhedron<T>::from_faces for the hull builder (a friend of ConvexPolyhedron).
template <class T>
struct HullPolyhedron {
  /// doubles (exact T): the vertices as doubles, each exactly equal to its vertex, or null.  scanned (float
  /// T): planes every vertex is known to be at most a height below, or null; a face whose plane is one of
  /// them bit for bit, with that height and the rounding of evaluating it again within the convexity
  /// tolerance (VertexTree::height_holds), needs no scan: the scan would compute heights within it.
  static ConvexPolyhedron<T> from_faces(std::vector<Vec3<T>> vertices,
                                        const std::vector<std::vector<int>>& faces,
                                        const std::vector<Vec3<double>>* doubles = nullptr,
                                        const ScannedPlanes<T>* scanned = nullptr) {
    if (faces.size() == 2) return ConvexPolyhedron<T>::from_faces(std::move(vertices), faces);  // flat
    // a solid: topology, plane triples and planes as from_faces builds them
    ConvexPolyhedron<T> p;
    p.vertices_ = std::move(vertices);
    p.check_coordinates();
    p.build_topology(faces);
    p.choose_plane_triples();
    p.compute_derived();
    if constexpr (!std::is_floating_point_v<T>) {
      // The filtered certificate; where it cannot conclude, from_faces' exact checks with the local
      // certificate (exact for exact T, so the same acceptance as from_faces' full scan).
      if (doubles == nullptr || !certify_exact(p, *doubles)) p.validate_geometry(0.0);
      return p;
    } else {
      p.validate_geometry(0.0);  // the certificate (or the full scan where a vertex is not wound once)
      if (static_cast<double>(p.face_count()) * static_cast<double>(p.vertex_count()) > kConvexityScanPairs)
        return p;  // (what from_faces checks on a large shape: the certificate alone)
      const T conv_tol = p.height_tolerance(Tolerances<T>::kConvexity);
      std::array<double, 3> mag{0, 0, 0};  // max |x_i| over the vertices
      for (int v = 0; v < p.vertex_count(); ++v)
        for (int c = 0; c < 3; ++c)
          mag[as_index(c)] = std::max(mag[as_index(c)], std::abs(static_cast<double>(p.vertex(v)[c])));
      auto known = [&](int f) {
        if (scanned == nullptr || as_index(f) >= scanned->planes.size()) return false;
        const Plane<T>& q = scanned->planes[as_index(f)];
        return q.normal == p.plane(f).normal && q.offset == p.plane(f).offset &&
               VertexTree<T>::height_holds(q, mag, scanned->below, conv_tol);
      };
      std::optional<VertexTree<T>> tree;  // (built when a face needs the scan)
      for (int f = 0; f < p.face_count(); ++f) {
        if (known(f)) continue;
        if (!tree) {
          std::vector<int> all(as_index(p.vertex_count()));
          for (int v = 0; v < p.vertex_count(); ++v) all[as_index(v)] = v;
          tree.emplace(all, [&](int v) { return p.vertex(v); });
        }
        tree->may_exceed(p.plane(f), conv_tol, [&](int v) {
          const T h = p.height(f, p.vertex(v));
          if (h > conv_tol) {
            ConvexPolyhedron<T>::fail(ErrorCode::NotConvex, "not convex: vertex " + std::to_string(v) +
                                                                " is " + std::to_string(to_double(h)) +
                                                                " above the plane of face " +
                                                                std::to_string(f));
          }
        });
      }
      return p;
    }
  }

  /// Exact T, a solid whose vertices are exactly the doubles d: validation by orientation predicates on the
  /// vertices, each decided by orientation_filter (its bound derived in orientation_filter.hpp) or, when
  /// the filter cannot, exactly in T.  Fails (InvalidInput, as from_faces) on a zero-area, non-planar or
  /// non-convex face, a vertex on fewer than three edges, a reflex edge or adjacent coplanar faces.  Returns
  /// false when it cannot conclude (the caller then runs from_faces' checks); true when the shape is convex:
  ///   (a) an interior point c (the vertices' mean, rounded: a double) is strictly below every face plane;
  ///   (b) every vertex v is wound once around the axis c -> v: its neighbours u_0 .. u_k-1 (in order around
  ///       v) turn once around that axis.  By (a) and the faces' convexity every step u_i -> u_i+1 turns
  ///       positively (det[v - c, u_i - c, u_i+1 - c] = -det[u_i - v, u_i+1 - v, c - v] > 0, the face's
  ///       orientation seen from c), so the turns are counted by the upward crossings of the half-plane
  ///       (c, v, u_0): the sign of det[v - c, u_0 - c, u_i - c] going from <= 0 to > 0;
  ///   (c) every edge is convex (the witnesses of local_convexity_witnesses on or below the face plane) and
  ///       (d) adjacent faces are not coplanar.
  /// (a) and (b) make the radial projection from c a covering of the sphere, hence one-to-one: the surface
  /// is embedded and star-shaped around c, and every vertex's cone, wound once with positive turns and
  /// convex edges, is convex.  A closed surface locally convex at every edge and vertex bounds a convex body
  /// (docs/hull.md, "Validation").  Every decision is exact.
  static bool certify_exact(ConvexPolyhedron<T>& p, const std::vector<Vec3<double>>& d) {
    using P = ConvexPolyhedron<T>;
    // sign of det[b - a, c - a, x - a]: the filter, else exactly in T
    auto orient = [&](const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c,
                      const Vec3<double>& x) {
      const FilteredSign r = orientation_filter(a, b, c, x);
      if (r.certain) return r.det > 0 ? 1 : -1;
      const Vec3<T> ta = vec_from_double<T>(a);
      const Vec3<T> tb(vec_from_double<T>(b) - ta), tc(vec_from_double<T>(c) - ta),
          tx(vec_from_double<T>(x) - ta);
      return sign_of(T(dot(cross(tb, tc), tx)));
    };
    auto vd = [&](int v) -> const Vec3<double>& { return d[as_index(v)]; };
    const int nf = p.face_count();
    // faces: non-zero area, planar, strictly convex loops
    std::vector<int> loop;  // (face f's vertices; one buffer for every face)
    for (int f = 0; f < nf; ++f) {
      const auto& t = p.face(f).plane_vertices;
      if (!certainly_nonzero_cross(vd(t[0]), vd(t[1]), vd(t[2])) && is_zero(p.plane(f).normal)) {
        P::fail(ErrorCode::DegenerateFace,
                "face " + std::to_string(f) + " has zero area (its vertices are collinear)");
      }
      p.face_vertices(f, loop);
      const std::size_t n = loop.size();
      if (n == 3) continue;  // its own plane triple: planar, and convex with area
      for (int v : loop) {
        if (v == t[0] || v == t[1] || v == t[2]) continue;
        if (orient(vd(t[0]), vd(t[1]), vd(t[2]), vd(v)) != 0) {
          P::fail(ErrorCode::NonPlanarFace, "face " + std::to_string(f) + " is not planar: vertex " +
                                                std::to_string(v) + " is off the face's plane");
        }
      }
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3<T>& a = p.vertex(loop[(i + n - 1) % n]);
        const Vec3<T>& b = p.vertex(loop[i]);
        const Vec3<T>& c = p.vertex(loop[(i + 1) % n]);
        if (!(dot(p.plane(f).normal, cross(Vec3<T>(b - a), Vec3<T>(c - b))) > T(0))) {
          P::fail(ErrorCode::NonConvexFace, "face " + std::to_string(f) + " is not convex at vertex " +
                                                std::to_string(loop[i]) + " (reflex or collinear corner)");
        }
      }
    }
    for (int v = 0; v < p.vertex_count(); ++v) {
      if (p.vertex_half_edges(v).size() < 3) {
        P::fail(ErrorCode::NotConvex,
                "vertex " + std::to_string(v) + " has only two edges (it lies in the middle of an edge)");
      }
    }
    // (a) the interior point
    Vec3<double> c(0, 0, 0);
    for (const auto& x : d) c = Vec3<double>(c + x);
    c = Vec3<double>(c / static_cast<double>(d.size()));
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) return false;
    for (int f = 0; f < nf; ++f) {
      const auto& t = p.face(f).plane_vertices;
      if (orient(vd(t[0]), vd(t[1]), vd(t[2]), c) >= 0) return false;
    }
    // (b) every vertex wound once around c -> v
    for (int v = 0; v < p.vertex_count(); ++v) {
      const auto fan = p.vertex_half_edges(v);
      const int first = fan[0];
      const Vec3<double>& r = vd(p.half_edge(P::twin(first)).origin);
      int crossings = 0, prev_side = 0;  // u_0 is on the half-plane's plane
      int h = first;
      std::size_t steps = 0;
      do {
        h = P::twin(p.half_edge(h).prev);
        const int u = p.half_edge(P::twin(h)).origin;
        const int side = h == first ? 0 : orient(c, vd(v), r, vd(u));
        if (prev_side <= 0 && side > 0) ++crossings;
        prev_side = side;
      } while (h != first && ++steps <= fan.size());
      if (crossings != 1) return false;
    }
    // (c) convex edges, (d) no adjacent coplanar faces
    std::vector<int> witnesses;
    for (int f = 0; f < nf; ++f) {
      const auto& t = p.face(f).plane_vertices;
      p.local_convexity_witnesses(f, witnesses);
      for (int w : witnesses) {
        if (orient(vd(t[0]), vd(t[1]), vd(t[2]), vd(w)) > 0) {
          P::fail(ErrorCode::NotConvex, "not convex: vertex " + std::to_string(w) +
                                            " is above the plane of face " + std::to_string(f));
        }
      }
    }
    for (int e = 0; e < p.edge_count(); ++e) {
      const int f = p.edge_face(e, 0), g = p.edge_face(e, 1);
      const auto& t = p.face(f).plane_vertices;
      const int ea = p.half_edge(2 * e).origin, eb = p.half_edge(2 * e + 1).origin;
      bool apart = false;  // (the edge's ends are on f's plane: f is planar)
      for (int v : p.face(g).plane_vertices)
        apart = apart || (v != ea && v != eb && orient(vd(t[0]), vd(t[1]), vd(t[2]), vd(v)) != 0);
      if (!apart) {
        P::fail(ErrorCode::NotConvex, "faces " + std::to_string(f) + " and " + std::to_string(g) +
                                          " are adjacent and coplanar: merge them into one face");
      }
    }
    return true;
  }
};

}  // namespace sepax::hull::detail
