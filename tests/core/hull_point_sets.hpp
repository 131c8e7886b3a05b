// The hull tests' point-set generators and measures, shared by
// tests/core/convex_hull_test.cpp and the stress run tools/hull_stress.cpp (so
// the stress run measures exactly the sets the unit test holds to the bound).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/tolerances.hpp>

namespace sepax::hull_sets {

template <class T>
std::vector<Vec3<T>> to_t(const std::vector<Vec3<double>>& pts) {
  std::vector<Vec3<T>> out;
  for (const auto& p : pts) out.push_back(vec_cast<T>(p));
  return out;
}

// Largest height of any input point above any face plane, in units of
// coplanar * extent of the hull.
template <class T>
inline double max_outside(const ConvexPolyhedron<T>& h, const std::vector<Vec3<T>>& pts) {
  double worst = -1e300;
  for (int f = 0; f < h.face_count(); ++f) {
    for (const auto& p : pts) {
      const double d = to_double(T(dot(h.plane(f).normal, p) - h.plane(f).offset));
      worst = std::max(worst, d);
    }
  }
  return worst / (Tolerances<T>::kCoplanar * h.extent());
}

// Largest Euclidean distance of any input point from the hull (the solid, or
// the flat polygon), in units of coplanar * extent of the hull.  Computed in
// double on coordinates relative to the first vertex (an offset from the
// origin costs no precision): a point's distance is its distance to the
// nearest face polygon (its height over the face if it projects inside the
// polygon, else the distance to the nearest edge segment), or 0 if it is
// below that face (inside; not "below every face plane": the plane of a
// tiny face is poorly determined far from it).  Face normals are Newell
// normals of the loops in double (well conditioned for thin faces, unlike
// a vertex triple).
template <class T>
inline double max_distance(const ConvexPolyhedron<T>& h, const std::vector<Vec3<T>>& pts) {
  const Vec3<double> o = vec_to_double(h.vertex(0));
  auto rel = [&](const Vec3<T>& p) { return Vec3<double>(vec_to_double(p) - o); };
  struct Face {
    std::vector<Vec3<double>> v;
    Vec3<double> n;
    double off;
  };
  std::vector<Face> faces;
  for (int f = 0; f < h.face_count(); ++f) {
    Face fc;
    for (int v : h.face_vertices(f)) fc.v.push_back(rel(h.vertex(v)));
    Vec3<double> n(0, 0, 0), c(0, 0, 0);
    for (std::size_t i = 0; i < fc.v.size(); ++i) {
      const Vec3<double>& a = fc.v[i];
      const Vec3<double>& b = fc.v[(i + 1) % fc.v.size()];
      n += Vec3<double>((a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]),
                        (a[0] - b[0]) * (a[1] + b[1]));
      c += a;
    }
    fc.n = n / n.norm();
    fc.off = fc.n.dot(c / double(fc.v.size()));
    faces.push_back(std::move(fc));
  }
  double worst = 0;
  for (const auto& q : pts) {
    const Vec3<double> p = rel(q);
    double best = 1e300;
    bool above = false;
    for (const auto& fc : faces) {
      bool inside = true;
      double d = 1e300;
      for (std::size_t i = 0; i < fc.v.size(); ++i) {
        const Vec3<double>& a = fc.v[i];
        const Vec3<double>& b = fc.v[(i + 1) % fc.v.size()];
        const Vec3<double> e = b - a;
        if (dot(cross(e, fc.n), Vec3<double>(p - a)) > 0) inside = false;
        const double l2 = e.squaredNorm();
        const double t = l2 > 0 ? std::clamp((p - a).dot(e) / l2, 0.0, 1.0) : 0.0;
        d = std::min(d, (p - (a + t * e)).norm());
      }
      const double ht = fc.n.dot(p) - fc.off;
      if (inside) d = std::abs(ht);
      if (d < best * (1 - 1e-9)) {
        best = d;
        above = ht > 0;
      } else if (d <= best * (1 + 1e-9)) {
        best = std::min(best, d);
        above = above || ht > 0;
      }
    }
    if (h.is_flat() || above) worst = std::max(worst, best);
  }
  return worst / (Tolerances<T>::kCoplanar * h.extent());
}

// Thickness of the point set across the thinnest of the hull's face planes:
// the smallest, over the faces of h, of the spread of the points' heights
// along the face's Newell normal (double, relative to the first vertex), in
// units of coplanar * extent of the hull.  At least the set's true
// thickness; a slab's thickness when h has a face parallel to it (its flat
// polygon, or its top or bottom).
template <class T>
inline double min_face_width(const ConvexPolyhedron<T>& h, const std::vector<Vec3<T>>& pts) {
  const Vec3<double> o = vec_to_double(h.vertex(0));
  double best = 1e300;
  for (int f = 0; f < h.face_count(); ++f) {
    const auto& fv = h.face_vertices(f);
    Vec3<double> n(0, 0, 0);
    for (std::size_t i = 0; i < fv.size(); ++i) {
      const Vec3<double> a = vec_to_double(h.vertex(fv[i])) - o;
      const Vec3<double> b = vec_to_double(h.vertex(fv[(i + 1) % fv.size()])) - o;
      n += Vec3<double>((a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]),
                        (a[0] - b[0]) * (a[1] + b[1]));
    }
    if (n.norm() == 0) continue;
    n /= n.norm();
    double lo = 1e300, hi = -1e300;
    for (const auto& p : pts) {
      const double t = n.dot(vec_to_double(p) - o);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    best = std::min(best, hi - lo);
  }
  return best / (Tolerances<T>::kCoplanar * h.extent());
}

// Three draws of draw() as (x, y, z), z drawn first, then y, then x: a fixed
// order, so that every compiler makes the same sets (the order of a call's
// arguments is unspecified: gcc evaluates the last first, clang the first;
// the sets the tests cite by seed and iteration are gcc's).
template <class Draw>
inline Vec3<double> draw_zyx(Draw draw) {
  const double z = draw();
  const double y = draw();
  const double x = draw();
  return Vec3<double>(x, y, z);
}

inline std::vector<Vec3<double>> sphere_points(int n, std::mt19937& rng) {
  std::normal_distribution<double> nd;
  std::vector<Vec3<double>> v;
  for (int i = 0; i < n; ++i) {
    const Vec3<double> p = draw_zyx([&] { return nd(rng); });
    v.push_back(p / p.norm());
  }
  return v;
}

// Point sets of many kinds, at many scales and offsets.
inline std::vector<Vec3<double>> random_point_set(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> count(4, 80);
  auto uniform = [&] { return u(rng); };
  std::vector<Vec3<double>> p;
  const int n = count(rng);
  switch (kind) {
    case 0:  // uniform in a box
      for (int i = 0; i < n; ++i) p.push_back(draw_zyx(uniform));
      break;
    case 1:  // on a sphere
      p = sphere_points(n, rng);
      break;
    case 2: {  // near-coplanar cluster: thickness around the tolerances
      const double t = std::pow(10.0, -4.0 - 8.0 * std::abs(u(rng)));
      for (int i = 0; i < n; ++i) p.push_back(draw_zyx(uniform).cwiseProduct(Vec3<double>(1, 1, t)));
      break;
    }
    case 3: {  // sliver: a thin slab with a few points off it
      const double t = std::pow(10.0, -1.0 - 8.0 * std::abs(u(rng)));
      for (int i = 0; i < n; ++i) {
        const double y = u(rng);
        p.emplace_back(u(rng), y, i % 7 == 0 ? t : 0.0);
      }
      break;
    }
    case 4: {  // needle
      const double r = std::pow(10.0, -2.0 - 8.0 * std::abs(u(rng)));
      for (int i = 0; i < n; ++i) p.push_back(draw_zyx(uniform).cwiseProduct(Vec3<double>(1, r, r)));
      break;
    }
    case 5: {  // near-duplicates around a few centres
      std::vector<Vec3<double>> centres;
      for (int i = 0; i < 6; ++i) centres.push_back(draw_zyx(uniform));
      const double j = std::pow(10.0, -6.0 - 8.0 * std::abs(u(rng)));
      for (int i = 0; i < n; ++i)
        p.push_back(centres[static_cast<std::size_t>(i) % centres.size()] + j * draw_zyx(uniform));
      break;
    }
    case 6: {  // integer grid points (exact coplanarity everywhere)
      std::uniform_int_distribution<int> g(-3, 3);
      for (int i = 0; i < n; ++i) p.push_back(draw_zyx([&] { return double(g(rng)); }));
      break;
    }
    case 7: {  // sphere with clusters of near-coplanar points on its faces
      p = sphere_points(12, rng);
      for (int i = 0; i < n; ++i) {
        const auto& c = p[static_cast<std::size_t>(i) % 12];
        p.push_back(c + 1e-9 * draw_zyx(uniform));
      }
      break;
    }
    default: {  // points on two nearly parallel planes
      const double t = std::pow(10.0, -1.0 - 10.0 * std::abs(u(rng)));
      for (int i = 0; i < n; ++i) {
        const double z = (i % 2) * (1.0 + t * u(rng));
        const double y = u(rng);
        p.emplace_back(u(rng), y, z);
      }
      break;
    }
  }
  // random scale 1e-6..1e6 and sometimes an offset of 1e4 * scale
  const double scale = std::pow(10.0, 6.0 * u(rng));
  const Vec3<double> off = (u(rng) > 0 ? 1e4 : 0.0) * scale * Vec3<double>(1, -0.5, 0.25);
  for (auto& q : p) q = q * scale + off;
  return p;
}

// The points of a text file, one "x y z" a line (decimal or hexadecimal floats, read exactly), lines
// starting with '#' skipped: the regression sets of tests/data.
inline std::vector<Vec3<double>> read_points(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<Vec3<double>> p;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string x, y, z;
    if (!(words >> x >> y >> z)) throw std::runtime_error("not three numbers: " + line);
    p.emplace_back(std::strtod(x.c_str(), nullptr), std::strtod(y.c_str(), nullptr),
                   std::strtod(z.c_str(), nullptr));
  }
  return p;
}

// The hull benchmark's point sets (bench/hull_bench.cpp, tools/hull_compare.cpp;
// seed 42): n points on the unit sphere, in the unit ball, in the thin slab
// [-1, 1]^2 x [-1e-3, 1e-3], at random angles on the two rims of a cylinder
// (radius 1, z = +-1: "rim") or on one circle ("circle"), or on a cylinder's
// lateral surface (radius 1, height 2; any other kind).
inline std::vector<Vec3<double>> bench_point_set(const std::string& kind, std::size_t n) {
  std::mt19937_64 rng(42);
  std::normal_distribution<double> nd;
  std::uniform_real_distribution<double> ud(-1.0, 1.0);
  std::vector<Vec3<double>> p;
  p.reserve(n);
  while (p.size() < n) {
    if (kind == "sphere") {
      const double x = nd(rng), y = nd(rng), z = nd(rng), l = std::sqrt(x * x + y * y + z * z);
      if (l > 0) p.emplace_back(x / l, y / l, z / l);
    } else if (kind == "ball") {
      const double x = ud(rng), y = ud(rng), z = ud(rng);
      if (x * x + y * y + z * z <= 1) p.emplace_back(x, y, z);
    } else if (kind == "slab") {
      p.push_back(draw_zyx([&] { return ud(rng); }).cwiseProduct(Vec3<double>(1, 1, 1e-3)));
    } else if (kind == "rim" || kind == "circle") {  // a cylinder's two rims; one circle
      const double a = 3.14159265358979323846 * ud(rng);
      p.emplace_back(std::cos(a), std::sin(a), kind == "circle" ? 0.0 : p.size() % 2 == 0 ? 1.0 : -1.0);
    } else {
      const double a = 3.14159265358979323846 * ud(rng);
      p.emplace_back(std::cos(a), std::sin(a), ud(rng));
    }
  }
  return p;
}

}  // namespace sepax::hull_sets
