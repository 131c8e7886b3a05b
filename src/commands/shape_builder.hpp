// src/commands/shape_builder.hpp
//
// build_shape<T>: ShapeData (double coordinates) -> ConvexPolyhedron<T>.
//
//   face list, no pose   (one face: the double-sided polygon, closed_faces())
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
// InvalidInput messages are prefixed with the shape's name, and with
// "FILE:LINE" of the face they name when the face came from a file.
#pragma once

#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include <sepax/convex_polyhedron.hpp>

#include "commands/pose.hpp"
#include "io/shape_data.hpp"

#if __has_include(<sepax/convex_hull.hpp>)
#include <sepax/convex_hull.hpp>
#define SEPAX_CLI_HAVE_HULL 1
#else
#define SEPAX_CLI_HAVE_HULL 0
#endif

namespace sepax::cli {

inline constexpr bool hull_available = SEPAX_CLI_HAVE_HULL != 0;

namespace detail {

/// "name: message", or "name:LINE: message" when message starts by naming a
/// face ("face K ...") that was read from line LINE of a file.
inline std::string located_message(const io::ShapeData& s, const std::string& message) {
  std::size_t line = 0;
  if (message.starts_with("face ")) {
    std::size_t i = 5, k = 0;
    bool digits = false;
    while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i]))) {
      k = k * 10 + static_cast<std::size_t>(message[i] - '0');
      ++i;
      digits = true;
    }
    if (digits && k < s.face_lines.size()) line = s.face_lines[k];
  }
  return line ? s.name + ":" + std::to_string(line) + ": " + message : s.name + ": " + message;
}

template <Number T>
std::vector<Vec3<T>> converted(const std::vector<Vec3<double>>& v) {
  std::vector<Vec3<T>> out;
  out.reserve(v.size());
  for (const auto& p : v) out.push_back(vec_from_double<T>(p));
  return out;
}

/// The face list to build: a file with a single face is that face as a
/// double-sided polygon (sepax's flat shape: the loop and the same loop
/// reversed), so a file holding one triangle is the double-sided triangle.
inline std::vector<std::vector<int>> closed_faces(const io::ShapeData& s) {
  if (s.faces.size() != 1) return s.faces;
  return {s.faces[0], std::vector<int>(s.faces[0].rbegin(), s.faces[0].rend())};
}

template <Number T>
ConvexPolyhedron<T> build_unnamed(const io::ShapeData& s, const Pose* pose) {
  if (s.kind == io::ShapeData::Kind::Points) {
#if SEPAX_CLI_HAVE_HULL
    std::vector<Vec3<double>> pts = s.vertices;
    if (pose) {
      for (auto& p : pts) p = pose->apply(p);
    }
    return convex_hull<T>(converted<T>(pts));
#else
    (void)pose;
    throw InvalidInput(ErrorCode::Parse, "this build of sepax has no hull builder (sepax/convex_hull.hpp)");
#endif
  }
  if (!pose) return ConvexPolyhedron<T>::from_faces(converted<T>(s.vertices), closed_faces(s));
  const auto base = ConvexPolyhedron<double>::from_faces(s.vertices, closed_faces(s));
  std::vector<Vec3<double>> moved;
  moved.reserve(s.vertices.size());
  for (const auto& p : base.vertices()) moved.push_back(pose->apply(p));
  const auto posed = base.with_vertices(std::move(moved));
  if constexpr (std::is_same_v<T, double>) {
    return posed;
  } else {
    return ConvexPolyhedron<T>::convert_from(posed);
  }
}

}  // namespace detail

template <Number T>
ConvexPolyhedron<T> build_shape(const io::ShapeData& s, const Pose* pose = nullptr) {
  try {
    return detail::build_unnamed<T>(s, pose);
  } catch (const InvalidInput& e) {
    throw InvalidInput(e.code(), detail::located_message(s, e.what()));
  }
}

}  // namespace sepax::cli
