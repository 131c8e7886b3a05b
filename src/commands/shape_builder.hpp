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
// InvalidInput messages are prefixed with the shape's name, and with
// "FILE:LINE" of the face they name when the face came from a file.
#pragma once

#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/error.hpp>

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

/// The coordinates in T.  A finite double that T cannot hold (1e300 in
/// float) is an error naming the point, not an infinity for the validation
/// to call non-finite.
template <Number T>
std::vector<Vec3<T>> converted(const io::ShapeData& s, const std::vector<Vec3<double>>& v) {
  std::vector<Vec3<T>> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    out.push_back(vec_from_double<T>(v[i]));
    for (int c = 0; c < 3; ++c) {
      if (!number_traits<T>::is_finite(out.back()[c])) {
        throw coordinate_beyond_range(c, s.kind == io::ShapeData::Kind::Points ? "point" : "vertex", i, v[i][c],
                                      number_traits<T>::name);
      }
    }
  }
  return out;
}

template <Number T>
ConvexPolyhedron<T> build_unnamed(const io::ShapeData& s, const Pose* pose) {
  if (s.kind == io::ShapeData::Kind::Points) {
#if SEPAX_CLI_HAVE_HULL
    std::vector<Vec3<double>> pts = s.vertices;
    if (pose) {
      for (auto& p : pts) p = pose->apply(p);
    }
    return convex_hull<T>(converted<T>(s, pts));
#else
    (void)pose;
    throw InvalidInput(ErrorCode::Parse, "this build of sepax has no hull builder (sepax/convex_hull.hpp)");
#endif
  }
  if (!pose) return ConvexPolyhedron<T>::from_faces(converted<T>(s, s.vertices), s.closed_faces());
  const auto base = ConvexPolyhedron<double>::from_faces(s.vertices, s.closed_faces());
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
