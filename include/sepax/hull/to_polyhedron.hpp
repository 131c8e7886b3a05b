// sepax/hull/to_polyhedron.hpp
//
// The hull's output as a validated ConvexPolyhedron<T>, with the decisions of ConvexPolyhedron::from_faces:
//   1. exact T: from_faces itself;
//   2. float T, a solid: topology, plane triples and derived data as from_faces builds them; validation
//      with the local convexity certificate (linear), then, on shapes small enough that from_faces scans
//      (faces x vertices <= kConvexityScanPairs), every vertex against every face plane through a
//      VertexTree, which skips only vertices it proves within the convexity tolerance.  The shape is
//      accepted exactly when from_faces accepts it: the scan rejects every vertex above a plane by more
//      than the tolerance, which is what the full scan, the certificate and the inward-faces test reject.
#pragma once

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../error.hpp"
#include "../tolerances.hpp"
#include "../vec3.hpp"
#include "vertex_tree.hpp"

namespace sepax::hull::detail {

/// ConvexPolyhedron<T>::from_faces for the hull builder (a friend of ConvexPolyhedron).
template <class T>
struct HullPolyhedron {
  static ConvexPolyhedron<T> from_faces(std::vector<Vec3<T>> vertices,
                                        const std::vector<std::vector<int>>& faces) {
    if constexpr (!std::is_floating_point_v<T>) {
      return ConvexPolyhedron<T>::from_faces(std::move(vertices), faces);
    } else {
      if (faces.size() == 2) return ConvexPolyhedron<T>::from_faces(std::move(vertices), faces);  // flat
      ConvexPolyhedron<T> p;
      p.vertices_ = std::move(vertices);
      p.check_coordinates();
      p.build_topology(faces);
      p.choose_plane_triples();
      p.compute_derived();
      p.validate_geometry(0.0);  // the certificate (or the full scan where a vertex is not wound once)
      if (static_cast<double>(p.face_count()) * static_cast<double>(p.vertex_count()) > kConvexityScanPairs)
        return p;  // (what from_faces checks on a large shape: the certificate alone)
      const T conv_tol = p.height_tolerance(Tolerances<T>::convexity);
      std::vector<int> all(as_index(p.vertex_count()));
      for (int v = 0; v < p.vertex_count(); ++v) all[as_index(v)] = v;
      const VertexTree<T> tree(all, [&](int v) { return p.vertex(v); });
      for (int f = 0; f < p.face_count(); ++f) {
        tree.may_exceed(p.plane(f), conv_tol, [&](int v) {
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
};

}  // namespace sepax::hull::detail
