// sepax/hull/hull_distance.hpp
//
// How far points are from a built hull, in double on the builder's local coordinates (float T):
//   1. polygon_faces: the hull's faces as polygons with Newell normals (well conditioned for thin faces).
//   2. plane_heights: a point's height over every face plane, in SIMD lanes.
//   3. polygon_distance: a point's Euclidean distance from the hull, through its nearest face polygon.
//   4. DeepInside: on a large solid, whether a point is certainly below every face plane, by a climb over
//      adjacent faces instead of a pass over every face.
//   5. face_distance: a point's distance from one face polygon (a large face: fan_edge, a bisection).
//   6. distance_to_segment, distance_to_triangle: a point's distance from a segment, from a triangle.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "../convex_polyhedron.hpp"
#include "../simd_ops.hpp"
#include "../tolerances.hpp"
#include "../vec3.hpp"
#include "index.hpp"

namespace sepax::hull::detail {

// Float T: the faces of an output polyhedron as polygons in double, on the
// local coordinates, with Newell normals (well conditioned for thin faces).
struct PolygonFace {
  std::span<const Vec3<double>> v;  // (into PolygonFaces::points)
  Vec3<double> n;
  double off = 0;
  double area = 0;
};

// Every face of one polyhedron, their corners in one buffer (moved, never
// copied: the faces point into it).
struct PolygonFaces {
  std::vector<Vec3<double>> points;
  std::vector<PolygonFace> faces;
  /// The faces' planes again by coordinate, faces[k].n and faces[k].off at k, once fill_lanes() ran: what
  /// plane_heights reads in lanes.
  std::vector<double> nx, ny, nz, off;
  PolygonFaces() = default;
  PolygonFaces(const PolygonFaces&) = delete;
  PolygonFaces(PolygonFaces&&) = default;
  /// Fills nx, ny, nz and off from faces (before measuring points against every face).
  void fill_lanes() {
    for (auto* a : {&nx, &ny, &nz, &off}) a->clear(), a->reserve(faces.size());
    for (const PolygonFace& fc : faces) {
      nx.push_back(fc.n[0]);
      ny.push_back(fc.n[1]);
      nz.push_back(fc.n[2]);
      off.push_back(fc.off);
    }
  }
};

// The faces of h as polygons on coordinates relative to centre, with Newell normals.
template <Number T>
inline PolygonFaces polygon_faces(const ConvexPolyhedron<T>& h, const Vec3<T>& centre) {
  const Vec3<double> c = vec_to_double(centre);
  PolygonFaces out;
  out.points.reserve(h.half_edges().size());
  std::vector<std::size_t> start;
  start.reserve(as_index(h.face_count()) + 1);
  for (int f = 0; f < h.face_count(); ++f) {
    start.push_back(out.points.size());
    int e = h.face(f).edge;
    for (int k = 0; k < h.face(f).count; ++k, e = h.half_edge(e).next)
      out.points.push_back(Vec3<double>(vec_to_double(h.vertex(h.half_edge(e).origin)) - c));
  }
  start.push_back(out.points.size());
  out.faces.reserve(as_index(h.face_count()));
  for (int f = 0; f < h.face_count(); ++f) {
    PolygonFace fc;
    fc.v = std::span<const Vec3<double>>(out.points.data() + start[as_index(f)],
                                         start[as_index(f) + 1] - start[as_index(f)]);
    Vec3<double> n(0, 0, 0), m(0, 0, 0);
    for (std::size_t i = 0; i < fc.v.size(); ++i) {
      const Vec3<double>& a = fc.v[i];
      const Vec3<double>& b = fc.v[(i + 1) % fc.v.size()];
      n += Vec3<double>((a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]),
                        (a[0] - b[0]) * (a[1] + b[1]));
      m += a;
    }
    const double len = std::sqrt(squared_norm(n));
    if (len > 0) n = n / len;
    fc.n = n;
    fc.area = len / 2;
    fc.off = dot(n, Vec3<double>(m / static_cast<double>(fc.v.size())));
    out.faces.push_back(fc);
  }
  return out;
}

// heights[k] = dot(faces[k].n, x) - faces[k].off for every face k, Lanes<double>::width faces at a time
// once pf.fill_lanes() ran (each lane computes dot()'s products and sums in its order, so the values are the
// scalar expression's bit for bit; under FMA contraction the caveat of simd_ops.hpp); returns whether any
// height is above 0.
inline bool plane_heights(const PolygonFaces& pf, const Vec3<double>& x, std::vector<double>& heights) {
  using L = simd::Lanes<double>;
  constexpr std::size_t W = L::width;
  const std::size_t count = pf.faces.size();
  const std::size_t in_lanes = std::min(pf.nx.size(), count);  // (0 before fill_lanes(): face by face)
  heights.resize(count);
  const typename L::V x0 = L::set1(x[0]), x1 = L::set1(x[1]), x2 = L::set1(x[2]), zero = L::set1(0.0);
  typename L::M above = L::lt(zero, zero);  // (false in every lane)
  std::size_t k = 0;
  for (; k + W <= in_lanes; k += W) {
    const typename L::V h = L::sub(simd::dot3<L>(L::load(pf.nx.data() + k), L::load(pf.ny.data() + k),
                                                 L::load(pf.nz.data() + k), x0, x1, x2),
                                   L::load(pf.off.data() + k));
    L::store(heights.data() + k, h);
    above = L::mor(above, L::gt(h, zero));
  }
  bool any_above = L::bits(above) != 0;
  for (; k < count; ++k) {
    heights[k] = dot(pf.faces[k].n, x) - pf.faces[k].off;
    any_above |= heights[k] > 0;
  }
  return any_above;
}

// Float T, a large solid: whether a point is certainly below every face
// plane of the output, found without a pass over every face.  Seen from an
// interior point c, face f's plane is the dual point n_f / D_f (D_f =
// off_f - n_f.c, the distance of c below the plane); x is below every plane iff
// s_f(x) = n_f.(x - c) / D_f < 1 for every f, and s is a linear function of
// the dual points, whose maximum a climb over adjacent faces finds (the
// duals of a convex polyhedron's faces are the vertices of a convex one,
// adjacent faces its edges).  A point is deep when (1 - max s) * min D
// exceeds margin (the rounding of the heights outside_points computes, and
// how far the validated plane of a face may be from its Newell plane): it is
// below every face plane by more than the measure's slack, so measuring it
// could change nothing, and it is skipped at every size.  Every other point is
// measured against every face, or on a large solid (local()) against the
// faces near the climb's face.  Climbs
// start where the last one ended (the points come in Builder::measure_order,
// near ones after each other).
template <Number T>
struct DeepInside {
  DeepInside(const ConvexPolyhedron<T>& h, const std::vector<PolygonFace>& faces, double margin,
             std::size_t points)
      : faces_(faces) {
    local_ = static_cast<double>(points) * static_cast<double>(faces.size()) > kHullPointScanPairs;
    if (h.is_flat()) return;
    Vec3<double> c(0, 0, 0);
    std::size_t count = 0;
    for (const auto& fc : faces)
      for (const auto& v : fc.v) {
        c += v;
        ++count;
      }
    c_ = Vec3<double>(c / static_cast<double>(count));
    dist_.resize(faces.size());
    double d_min = 1e300;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (squared_norm(faces[f].n) == 0) return;
      dist_[f] = faces[f].off - dot(faces[f].n, c_);
      d_min = std::min(d_min, dist_[f]);
    }
    if (!(d_min > 0)) return;
    need_ = margin / d_min;
    start_.assign(faces.size() + 1, 0);
    for (int f = 0; f < h.face_count(); ++f) start_[as_index(f) + 1] = start_[as_index(f)] + h.face(f).count;
    adj_.resize(as_index(start_.back()));
    for (int f = 0; f < h.face_count(); ++f) {
      int e = h.face(f).edge;
      for (int k = 0; k < h.face(f).count; ++k, e = h.half_edge(e).next)
        adj_[as_index(start_[as_index(f)] + k)] = h.half_edge(ConvexPolyhedron<T>::twin(e)).face;
    }
    on_ = true;
  }
  bool enabled() const { return on_; }
  /// Points x faces above kHullPointScanPairs: a point that is not deep is measured against the faces near
  /// the climb's face (neighbours), not every face.
  bool local() const { return local_; }
  int face() const { return at_; }  // where the last climb ended
  std::span<const int> neighbours(int f) const {
    return std::span<const int>(adj_.data() + start_[as_index(f)],
                                as_index(start_[as_index(f) + 1] - start_[as_index(f)]));
  }
  bool operator()(const Vec3<double>& x) {
    const Vec3<double> d(x - c_);
    auto score = [&](int f) { return dot(faces_[as_index(f)].n, d) / dist_[as_index(f)]; };
    double s = score(at_);
    for (int from = -1; from != at_;) {
      from = at_;
      for (int k = start_[as_index(from)]; k < start_[as_index(from) + 1]; ++k) {
        const double t = score(adj_[as_index(k)]);
        if (t > s) {
          s = t;
          at_ = adj_[as_index(k)];
        }
      }
    }
    return 1 - s > need_;
  }

 private:
  const std::vector<PolygonFace>& faces_;
  Vec3<double> c_{0, 0, 0};
  std::vector<double> dist_;
  std::vector<int> start_, adj_;
  double need_ = 0;
  int at_ = 0;
  bool on_ = false, local_ = false;
};

// The first k >= from with |heights[k]| not above reach (NaN included), Lanes<double>::width heights at a
// time; heights.size() if none.
inline std::size_t next_within(const std::vector<double>& heights, std::size_t from, double reach) {
  using L = simd::Lanes<double>;
  constexpr std::size_t W = L::width;
  const std::size_t count = heights.size();
  const typename L::V r = L::set1(reach);
  std::size_t k = from;
  for (; k + W <= count; k += W) {
    const unsigned beyond = L::bits(L::gt(L::abs(L::load(heights.data() + k)), r));
    if (beyond != (1u << W) - 1) return k + static_cast<std::size_t>(std::countr_one(beyond));
  }
  for (; k < count; ++k)
    if (!(std::abs(heights[k]) > reach)) return k;
  return count;
}

// A face with at least this many corners is measured by fan_distance2 (O(log n) plus a short walk) rather
// than by a pass over its edges (a cylinder's cap, a flat polygon of 10^5 corners).
inline constexpr std::size_t kFanSearchCorners = 32;

// The squared distance of x from the segment pa pb.
inline double segment_distance2(const Vec3<double>& x, const Vec3<double>& pa, const Vec3<double>& pb) {
  const Vec3<double> e(pb - pa), ax(x - pa);
  const double l2 = squared_norm(e);
  const double t = l2 > 0 ? std::clamp(dot(ax, e) / l2, 0.0, 1.0) : 0.0;
  return squared_norm(Vec3<double>(ax - t * e));
}

// The squared distance of x from edge i (corner i to i + 1) of the face.
inline double edge_distance2(const PolygonFace& fc, std::size_t i, const Vec3<double>& x) {
  return segment_distance2(x, fc.v[i], fc.v[(i + 1) % fc.v.size()]);
}

// Whether x is beyond the line of edge i (outside its side of the face).
inline bool beyond_edge(const PolygonFace& fc, std::size_t i, const Vec3<double>& x) {
  const std::size_t n = fc.v.size();
  return dot(cross(Vec3<double>(fc.v[(i + 1) % n] - fc.v[i]), fc.n), Vec3<double>(x - fc.v[i])) > 0;
}

// A large face: the edge of the polygon nearest x (by a walk to it that ends where the distance stops
// falling), its squared distance in d2, and in inside whether x projects inside the polygon.  The corners
// seen from corner 0 turn counter-clockwise by less than a half turn, so the side of x of the ray from
// corner 0 through corner i changes once along the loop: a bisection finds the fan triangle (0, i, i + 1)
// whose wedge holds x.  x is inside iff it is not beyond edge i (nor, for a wedge chosen by rounding, its
// neighbours).  Outside, edge i is on the chain of edges x is beyond, along which the distance falls to its
// minimum and rises again; inside near the boundary, edge i is next to the nearest edge (a point near edge
// j lies in fan triangle j, one near a corner in a triangle of that corner): either way the walk from it
// ends at the nearest edge.
inline std::size_t fan_edge(const PolygonFace& fc, const Vec3<double>& x, double& d2, bool& inside) {
  const std::size_t n = fc.v.size();
  const Vec3<double> x0(x - fc.v[0]);
  auto left_of_ray = [&](std::size_t i) {
    return dot(fc.n, cross(Vec3<double>(fc.v[i] - fc.v[0]), x0)) >= 0;
  };
  std::size_t at;  // an edge x is beyond, or the wedge's edge
  inside = false;
  if (!left_of_ray(1)) {
    at = 0;
  } else if (left_of_ray(n - 1)) {
    at = n - 1;
  } else {
    std::size_t lo = 1, hi = n - 1;  // left_of_ray(lo), !left_of_ray(hi)
    while (hi - lo > 1) {
      const std::size_t mid = lo + (hi - lo) / 2;
      (left_of_ray(mid) ? lo : hi) = mid;
    }
    at = lo;
    inside = !beyond_edge(fc, lo, x) && !beyond_edge(fc, lo - 1, x) && !beyond_edge(fc, (lo + 1) % n, x);
  }
  d2 = edge_distance2(fc, at, x);
  for (const std::size_t step : {std::size_t{1}, n - 1}) {  // forwards, then backwards
    for (std::size_t walked = 0; walked + 1 < n; ++walked) {
      const std::size_t next = (at + step) % n;
      const double nd2 = edge_distance2(fc, next, x);
      if (!(nd2 < d2)) break;
      at = next;
      d2 = nd2;
    }
  }
  return at;
}

// A large face: the squared distance of x's projection from the polygon's boundary if it projects outside
// it, else -1 (fan_edge).
inline double fan_distance2(const PolygonFace& fc, const Vec3<double>& x) {
  double d2 = 0;
  bool inside = false;
  fan_edge(fc, x, d2, inside);
  return inside ? -1 : d2;
}

// The distance of x from the face polygon: |h| (its height over the face's plane) if it projects inside,
// else its distance from the nearest edge (squared distances compared first: sqrt is correctly rounded,
// hence monotone, so the root of the smallest is the smallest root).
inline double face_distance(const PolygonFace& fc, const Vec3<double>& x, double h) {
  const std::size_t n = fc.v.size();
  if (n >= kFanSearchCorners) {
    const double d2 = fan_distance2(fc, x);
    return d2 < 0 ? std::abs(h) : std::sqrt(d2);
  }
  bool inside = true;
  for (std::size_t i = 0; i < n && inside; ++i) inside = !beyond_edge(fc, i, x);
  if (inside) return std::abs(h);
  double d2 = 1e300;
  for (std::size_t i = 0; i < n; ++i) d2 = std::min(d2, edge_distance2(fc, i, x));
  return std::sqrt(d2);
}

// Euclidean distance of x from the polyhedron given by faces: the distance
// to the nearest face polygon (its height if it projects inside the
// polygon, else the distance to the nearest edge), or 0 if x is below that
// face (inside).  (Not "below every face plane": the plane of a tiny face
// is poorly determined far from it, and a point deep inside can be above
// it.)  A flat polygon is always measured to its polygon.
// (Only the faces listed in subset, if given.)  A solid's point below
// every plane is below its nearest face too: 0 without measuring polygons
// (heights holds the heights, computed once, so both passes see the same).
inline double polygon_distance(const PolygonFaces& polygons, bool flat, const Vec3<double>& x,
                               std::vector<double>& heights, const std::vector<int>* subset = nullptr) {
  const std::vector<PolygonFace>& faces = polygons.faces;
  double best = 1e300;
  bool above = false;  // above a face at the nearest distance (within rounding)
  const std::size_t count = subset != nullptr ? subset->size() : faces.size();
  bool any_above = false;
  if (subset != nullptr) {
    heights.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
      const auto& fc = faces[as_index((*subset)[k])];
      heights[k] = dot(fc.n, x) - fc.off;
      any_above |= heights[k] > 0;
    }
  } else {
    any_above = plane_heights(polygons, x, heights);
  }
  if (!flat && !any_above) return 0.0;
  double reach = best * (1 + kHullDistanceTie);  // (kept equal to it as best changes)
  // (a face whose |height| exceeds reach is skipped: the polygon is no nearer than its plane)
  for (std::size_t k = next_within(heights, 0, reach); k < count; k = next_within(heights, k + 1, reach)) {
    const double h = heights[k];
    const auto& fc = faces[subset != nullptr ? as_index((*subset)[k]) : k];
    const double d = face_distance(fc, x, h);
    if (d < best * (1 - kHullDistanceTie)) {
      best = d;
      above = h > 0;
    } else if (d <= best * (1 + kHullDistanceTie)) {
      best = std::min(best, d);
      above = above || h > 0;
    }
    reach = best * (1 + kHullDistanceTie);
  }
  return flat || above ? best : 0.0;
}

/// Euclidean distance of x from the segment between a and b.
inline double distance_to_segment(const Vec3<double>& x, const Vec3<double>& pa, const Vec3<double>& pb) {
  return std::sqrt(segment_distance2(x, pa, pb));
}

/// Euclidean distance of x from the triangle abc (its height over the plane if x projects inside, else the
/// distance from the nearest side; a degenerate triangle: from its sides).
inline double distance_to_triangle(const Vec3<double>& x, const Vec3<double>& a, const Vec3<double>& b,
                                   const Vec3<double>& c) {
  const Vec3<double> n = cross(Vec3<double>(b - a), Vec3<double>(c - a));
  const double n2 = squared_norm(n);
  if (n2 > 0) {
    auto inside_of = [&](const Vec3<double>& p, const Vec3<double>& q) {
      return dot(n, cross(Vec3<double>(q - p), Vec3<double>(x - p))) >= 0;
    };
    if (inside_of(a, b) && inside_of(b, c) && inside_of(c, a))
      return std::abs(dot(n, Vec3<double>(x - a))) / std::sqrt(n2);
  }
  return std::min({distance_to_segment(x, a, b), distance_to_segment(x, b, c), distance_to_segment(x, c, a)});
}

}  // namespace sepax::hull::detail
