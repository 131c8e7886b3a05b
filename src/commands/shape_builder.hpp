// src/commands/shape_builder.hpp
//
// build_shape<T>: ShapeData (double coordinates) -> ConvexPolyhedron<T>.
//
//   face list, no pose   (one face: the double-sided polygon, ShapeData::closed_faces)
//                        ConvexPolyhedron<T>::from_faces on the coordinates
//                        converted to T (exactly for exact T), validated in T
//                        (exact checks for exact T)
//   face list, posed     validated in double, the pose applied to the double
//                        vertices, then ConvexPolyhedron<T>::convert_from
//                        (same topology and plane triples; the posed double
//                        coordinates are converted exactly for exact T, and
//                        not re-validated: a rotated face is planar only up
//                        to the rounding of the rotation)
//   points               the pose (if any) applied in double, then
//                        sepax::convex_hull<T> on the points converted to T
//
// A face list that validation refuses but is read from a file is accepted
// when it is a closed convex mesh (io/convex_mesh.hpp: a triangulated cube
// is the cube); otherwise the error suggests hull:FILE.
//
// With a centre c (io/exact_centre.hpp), the shape is built at its
// coordinates in T minus c, each subtraction exact: the caller adds c back
// to the positions it reports.  build_pair chooses the frame of a query.
//
// InvalidInput messages are prefixed with the shape's name, and with
// "FILE:LINE" of the face they name when the face came from a file.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/error.hpp>
#include <sepax/shapes.hpp>

#include "commands/pose.hpp"
#include "io/closed_mesh.hpp"
#include "io/exact_centre.hpp"
#include "io/shape_data.hpp"

#if __has_include(<sepax/convex_hull.hpp>)
#include <sepax/convex_hull.hpp>

#include "io/convex_mesh.hpp"
#define SEPAX_CLI_HAVE_HULL 1
#else
#define SEPAX_CLI_HAVE_HULL 0
#endif

namespace sepax::cli {

inline constexpr bool kHullAvailable = SEPAX_CLI_HAVE_HULL != 0;

namespace detail {

/// "name: message", or "name:LINE: message" when message starts by naming a
/// face ("face K ...") that was read from line LINE of a file, or (an unused
/// vertex: validation numbers the file's vertices as given) a vertex
/// ("vertex K ...").
inline std::string located_message(const io::ShapeData& s, const InvalidInput& e) {
  const std::string message = e.what();
  // the K of a message starting with prefix K, as an index into lines; 0 if none
  auto line_of = [&](std::string_view prefix, const std::vector<std::size_t>& lines) -> std::size_t {
    if (!message.starts_with(prefix)) return 0;
    std::size_t i = prefix.size(), k = 0;
    bool digits = false;
    while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i]))) {
      k = k * 10 + static_cast<std::size_t>(message[i] - '0');
      ++i;
      digits = true;
    }
    return digits && k < lines.size() ? lines[k] : 0;
  };
  std::size_t line = line_of("face ", s.face_lines);
  if (line == 0 && e.code() == ErrorCode::UnusedVertex) line = line_of("vertex ", s.vertex_lines);
  return line ? s.name + ":" + std::to_string(line) + ": " + message : s.name + ": " + message;
}

/// The coordinates in T.  A finite double that T cannot hold (1e300 in
/// float) is an error naming the point, not an infinity for the validation
/// to call non-finite.
template <Number T>
std::vector<Vec3<T>> converted(const io::ShapeData& s, const std::vector<Vec3<double>>& v) {
  std::vector<Vec3<T>> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    out.push_back(
        shapes::point_from_double<T>(v[i], i, s.kind == io::ShapeData::Kind::Points ? "point" : "vertex"));
  return out;
}

/// The face list of s on the vertices v (s's, in T): validated as it is, or,
/// for a file's face list that validation refuses, as a closed convex mesh.
template <Number T>
ConvexPolyhedron<T> face_polyhedron(const io::ShapeData& s, std::vector<Vec3<T>> v) {
  // A file's face list that is open or not a 2-manifold is no polyhedron of
  // either kind: said at once, before validation walks the millions of faces
  // of a scanned mesh.  (A face repeating a point is left to validation,
  // whose message names the vertex as the file numbers it.)
  if (s.from_file && s.faces.size() >= 2) {
    try {
      (void)io::closed_mesh(s);
    } catch (const InvalidInput& e) {
      if (e.code() == ErrorCode::NotManifold) throw;
    }
  }
  try {
    return ConvexPolyhedron<T>::from_faces(v, s.closed_faces());
  } catch (const InvalidInput& e) {
    if (!s.from_file || s.faces.size() < 2) throw;
#if SEPAX_CLI_HAVE_HULL
    if (io::may_be_convex_mesh(e.code())) return io::convex_mesh<T>(s, v);
#endif
    if (io::may_be_convex_mesh(e.code()) || e.code() == ErrorCode::DegenerateFace ||
        e.code() == ErrorCode::UnusedVertex)
      throw InvalidInput(e.code(), e.what() + std::string(io::kHullHint));
    throw;
  }
}

/// The points v of s moved by pose, in double.  A point the pose moves beyond
/// double's range is BadScale naming it (the file's coordinates are finite: an
/// infinity here is the pose's, not the input's).
inline std::vector<Vec3<double>> posed(const io::ShapeData& s, const std::vector<Vec3<double>>& v,
                                       const Pose& pose) {
  std::vector<Vec3<double>> moved;
  moved.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    moved.push_back(pose.apply(v[i]));
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(moved.back()[c])) {
        std::string m = "the pose moves coordinate ";
        m += "xyz"[c];
        m += s.kind == io::ShapeData::Kind::Points ? " of point " : " of vertex ";
        m += std::to_string(i) + " beyond the range of double";
        throw InvalidInput(ErrorCode::BadScale, std::move(m));
      }
    }
  }
  return moved;
}

/// The coordinates of s in T as it is placed (posed when pose is given): the
/// points exact_centre<T> is taken over.
template <Number T>
std::vector<Vec3<T>> world_points(const io::ShapeData& s, const Pose* pose) {
  if (!pose) return converted<T>(s, s.vertices);
  return converted<T>(s, posed(s, s.vertices, *pose));
}

template <Number T>
ConvexPolyhedron<T> build_unnamed(const io::ShapeData& s, const Pose* pose, const Vec3<T>& c) {
  if (s.kind == io::ShapeData::Kind::Points) {
#if SEPAX_CLI_HAVE_HULL
    return convex_hull<T>(io::minus(world_points<T>(s, pose), c));
#else
    (void)pose;
    throw InvalidInput(ErrorCode::Parse, "this build of sepax has no hull builder (sepax/convex_hull.hpp)");
#endif
  }
  if (!pose) return face_polyhedron<T>(s, io::minus(converted<T>(s, s.vertices), c));
  auto base = face_polyhedron<double>(s, s.vertices);
  const std::vector<Vec3<double>> moved = posed(s, base.vertices(), *pose);
  std::vector<Vec3<T>> local = io::minus(converted<T>(s, moved), c);
  ConvexPolyhedron<T> typed = [&] {
    if constexpr (std::is_same_v<T, double>) {
      return std::move(base);
    } else {
      return ConvexPolyhedron<T>::convert_from(base);
    }
  }();
  try {
    return typed.with_vertices(std::move(local));
  } catch (const InvalidInput& e) {
    // A pose far from the origin rounds the coordinates (posed in double,
    // then converted to T) to a coarse spacing, which can take a face's
    // plane triple together; the shape is built at those coordinates minus
    // the centre c, so the error's own coordinates are small: say how far
    // the pose placed it.
    if (e.code() != ErrorCode::BadScale) throw;
    double reach = 0;
    for (const Vec3<double>& p : moved)
      reach = std::max({reach, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    const std::string_view rounded = number_traits<T>::is_exact ? "double" : number_traits<T>::name;
    throw InvalidInput(ErrorCode::BadScale,
                       e.what() + std::string("; the pose placed the shape at coordinates up to ") +
                           format_number(reach) + ", rounded in " + std::string(rounded) + " there");
  }
}

}  // namespace detail

/// The coordinates of s in T as placed (posed by pose); errors named like
/// build_shape's.
template <Number T>
std::vector<Vec3<T>> shape_points(const io::ShapeData& s, const Pose* pose = nullptr) {
  try {
    return detail::world_points<T>(s, pose);
  } catch (const InvalidInput& e) {
    throw InvalidInput(e.code(), detail::located_message(s, e));
  }
}

/// s built in T (posed by pose), at its coordinates minus *centre when given.
template <Number T>
ConvexPolyhedron<T> build_shape(const io::ShapeData& s, const Pose* pose = nullptr,
                                const Vec3<T>* centre = nullptr) {
  try {
    return detail::build_unnamed<T>(s, pose, centre ? *centre : Vec3<T>(T(0), T(0), T(0)));
  } catch (const InvalidInput& e) {
    throw InvalidInput(e.code(), detail::located_message(s, e));
  }
}

/// A query's two shapes in one frame, and that frame's origin in world
/// coordinates (add it to positions to report them).
template <Number T>
struct BuiltPair {
  ConvexPolyhedron<T> a, b;
  Vec3<T> origin;
};

/// A and B (B posed by pose_b) built for one query.  Normally both at their
/// coordinates in T minus one exact centre (io/exact_centre.hpp): the shapes
/// read, only moved.  When that frame is too far from one of them for T
/// (two small shapes far apart from each other, in float), each is built and
/// validated around its own exact centre, and B is then expressed in A's
/// frame: its vertices' coordinates minus A's centre, rounded to T once, not
/// re-validated there (as a posed shape is).
template <Number T>
BuiltPair<T> build_pair(const io::ShapeData& sa, const io::ShapeData& sb, const Pose* pose_b) {
  const std::vector<Vec3<T>> world[] = {shape_points<T>(sa), shape_points<T>(sb, pose_b)};
  const Vec3<T> c = io::exact_centre<T>(world);
  if (io::resolvable_around(world[0], c) && io::resolvable_around(world[1], c)) {
    return BuiltPair<T>{build_shape<T>(sa, nullptr, &c), build_shape<T>(sb, pose_b, &c), c};
  }
  const Vec3<T> ca = io::exact_centre<T>(std::span(world, 1));
  const Vec3<T> cb = io::exact_centre<T>(std::span(world + 1, 1));
  ConvexPolyhedron<T> b = build_shape<T>(sb, pose_b, &cb);
  std::vector<Vec3<T>> moved;
  moved.reserve(b.vertices().size());
  for (const auto& v : b.vertices()) {
    // float: the sum of three floats in double (exact for coordinates within
    // 2^29 of each other's magnitude), rounded once; double: v + cb restores
    // the coordinate read (exact), minus ca rounded once.
    if constexpr (std::is_same_v<T, float>) {
      moved.push_back(
          vec_from_double<T>(Vec3<double>(vec_to_double(v) + vec_to_double(cb) - vec_to_double(ca))));
    } else {
      moved.push_back(Vec3<T>(Vec3<T>(v + cb) - ca));
    }
  }
  return BuiltPair<T>{build_shape<T>(sa, nullptr, &ca), b.with_vertices(std::move(moved)), ca};
}

}  // namespace sepax::cli
