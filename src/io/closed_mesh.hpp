// src/io/closed_mesh.hpp
//
// The topological half of accepting a face list as a convex polyhedron when
// it is not already one face per plane (a triangulated convex mesh, as most
// files hold): the faces, with vertices of identical coordinates welded,
// must form a closed, consistently oriented 2-manifold -- every directed
// edge used by exactly one face, and its reverse by exactly one other.  The
// geometric half is convex_mesh.hpp.
//
// Errors: InvalidInput(NotManifold or DegenerateFace) whose message starts
// "face K" (K 0-based, as in validation messages, so the program adds the
// file's line) and ends with kHullHint.
#pragma once

#include <vector>

#include <sepax/error.hpp>

#include "io/shape_data.hpp"

namespace sepax::cli::io {

/// Appended to the errors of face lists that are not convex polyhedra.
inline constexpr const char* kHullHint =
    "; to use the convex hull of the vertices, write hull:FILE (or pass --hull)";

/// Whether validation's refusal of a face list with this code may be a closed convex mesh's (coplanar
/// neighbouring faces, a face split into several: a triangulated cube), which convex_mesh.hpp then reads
/// as the polyhedron it bounds.
inline bool may_be_convex_mesh(ErrorCode code) {
  switch (code) {
    case ErrorCode::NotConvex:
    case ErrorCode::NotManifold:
    case ErrorCode::BadEuler:
    case ErrorCode::NonPlanarFace:
    case ErrorCode::NonConvexFace:
    case ErrorCode::InwardFaces:
      return true;
    default:
      return false;
  }
}

struct ClosedMesh {
  std::vector<int> vertex;              // welded vertex -> its first index in ShapeData::vertices
                                        // (only vertices some face uses)
  std::vector<std::vector<int>> faces;  // per face of the input, the welded vertex loop
};

/// Welds identical vertices and checks the faces form a closed, consistently
/// oriented 2-manifold (throws otherwise).
ClosedMesh closed_mesh(const ShapeData& s);

}  // namespace sepax::cli::io
