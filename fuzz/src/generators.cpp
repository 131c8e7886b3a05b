// Case generators, the byte decoder and built-in shapes: see sepax/fuzz/generators.hpp.
#include <sepax/fuzz/generators.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <Eigen/Geometry>
#include <sepax/convex_hull.hpp>
#include <sepax/shapes.hpp>
#include <sepax/fuzz/random.hpp>

namespace sepax::fuzz {

namespace {

using V = Vec3<double>;

double uni(Rng& r, double a, double b) { return r.uniform(a, b); }
int irange(Rng& r, int a, int b) { return r.uniform_int(a, b); }
double log_uni(Rng& r, double a, double b) { return std::exp(uni(r, std::log(a), std::log(b))); }

// Several draws in one expression must be sequenced: the order in which a
// call's arguments are evaluated is unspecified (compilers differ), so every
// multi-draw value below is built from named draws in a fixed order.
V uni3(Rng& r, double a, double b) {
  const double x = uni(r, a, b), y = uni(r, a, b), z = uni(r, a, b);  // declarators are sequenced
  return V(x, y, z);
}
V int3(Rng& r, int a, int b) {
  const int x = irange(r, a, b), y = irange(r, a, b), z = irange(r, a, b);
  return V(x, y, z);
}

ShapeSpec spec_from(const ConvexPolyhedron<double>& p) {
  ShapeSpec s;
  s.vertices = p.vertices();
  for (int f = 0; f < p.face_count(); ++f) s.faces.push_back(p.face_vertices(f));
  return s;
}

V random_unit(Rng& r) {
  for (;;) {
    const V v = uni3(r, -1, 1);
    const double n = v.norm();
    if (n > 1e-3 && n <= 1) return v / n;
  }
}

// A uniformly distributed rotation: a point uniform in the unit 4-ball (by
// rejection) as a quaternion, normalised by quat_matrix.
std::array<double, 4> random_quat(Rng& r) {
  for (;;) {
    const std::array<double, 4> q{uni(r, -1, 1), uni(r, -1, 1), uni(r, -1, 1), uni(r, -1, 1)};
    const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    if (n2 > 1e-6 && n2 <= 1) return q;
  }
}

// The 24 rotations of the cube: signed permutation matrices with det +1.
Eigen::Matrix3d cube_rotation(int k) {
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int* p = perms[(k / 8) % 6];
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) m(i, p[i]) = ((k >> i) & 1) ? -1.0 : 1.0;
  if (m.determinant() < 0) m.row(0) *= -1.0;
  return m;
}

ShapeSpec transformed(const ShapeSpec& s, const Eigen::Matrix3d& R, const V& t, double scale = 1.0) {
  ShapeSpec o = s;
  for (auto& v : o.vertices) v = V(R * (v * scale) + t);
  round_to_float(o);
  return o;
}

Eigen::Matrix3d quat_matrix(const double q[4]) {
  Eigen::Quaterniond qq(q[0], q[1], q[2], q[3]);
  if (qq.norm() == 0) return Eigen::Matrix3d::Identity();
  return qq.normalized().toRotationMatrix();
}

Eigen::Matrix3d random_rotation(Rng& r) {
  const auto q = random_quat(r);
  return quat_matrix(q.data());
}

ShapeSpec tetra_of(std::array<V, 4> p) {
  ShapeSpec s;
  s.vertices.assign(p.begin(), p.end());
  round_to_float(s);
  const V& a = s.vertices[0];
  const double det = (s.vertices[1] - a).cross(s.vertices[2] - a).dot(s.vertices[3] - a);
  s.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  if (det > 0)
    for (auto& f : s.faces) std::reverse(f.begin(), f.end());
  return s;
}

ShapeSpec flat_of(std::vector<V> loop) {
  ShapeSpec s;
  s.vertices = std::move(loop);
  std::vector<int> front(s.vertices.size());
  for (std::size_t i = 0; i < front.size(); ++i) front[i] = static_cast<int>(i);
  s.faces = {front, std::vector<int>(front.rbegin(), front.rend())};
  round_to_float(s);
  return s;
}

double radius_of(const ShapeSpec& s) {
  V c = V::Zero();
  for (const auto& v : s.vertices) c += v;
  c /= static_cast<double>(s.vertices.size());
  double r = 0;
  for (const auto& v : s.vertices) r = std::max(r, (v - c).norm());
  return r;
}

// ---- local shapes (centred near the origin, size ~1) ----
ShapeSpec sphere_hull(Rng& r, int n) {
  for (int attempt = 0;; ++attempt) {
    std::vector<V> pts;
    for (int i = 0; i < n; ++i) pts.push_back(random_unit(r));
    try {
      return hull_of(pts);
    } catch (const InvalidInput&) {
      if (attempt > 10) throw;
    }
  }
}

ShapeSpec random_box(Rng& r) {
  const int kind = irange(r, 0, 2);
  double hx = uni(r, 0.2, 1.5), hy = uni(r, 0.2, 1.5), hz = uni(r, 0.2, 1.5);
  if (kind == 0) hx = hy = hz = 1.0;  // cube: all ties
  if (kind == 1) hx = irange(r, 1, 4) * 0.25, hy = irange(r, 1, 4) * 0.25, hz = irange(r, 1, 4) * 0.25;
  return spec_from(shapes::box<double>(hx, hy, hz));
}

ShapeSpec random_tetra(Rng& r) {
  std::array<V, 4> p;
  for (auto& x : p) x = uni3(r, -1, 1);
  if (irange(r, 0, 1)) {
    // sliver: the 4th point eps off the plane of the first three, inside their triangle
    const V n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    const double w0 = uni(r, 0.1, 0.8), w1 = uni(r, 0.1, 1 - w0 - 0.05);
    const double mag = log_uni(r, 1e-6, 1e-1);
    const double eps = irange(r, 0, 1) ? mag : -mag;
    p[3] = w0 * p[0] + w1 * p[1] + (1 - w0 - w1) * p[2] + eps * n;
  }
  return tetra_of(p);
}

ShapeSpec random_flat(Rng& r) {
  std::vector<V> loop;
  if (irange(r, 0, 1)) {
    for (int i = 0; i < 3; ++i) {
      const double x = uni(r, -1, 1), y = uni(r, -1, 1);
      loop.emplace_back(x, y, 0.0);
    }
    if ((loop[1] - loop[0]).cross(loop[2] - loop[0])[2] < 0) std::swap(loop[1], loop[2]);
  } else {
    const double a = uni(r, 0.2, 1.2), b = irange(r, 0, 1) ? a : uni(r, 0.2, 1.2);
    loop = {V(-a, -b, 0), V(a, -b, 0), V(a, b, 0), V(-a, b, 0)};
  }
  const Eigen::Matrix3d R = irange(r, 0, 1) ? cube_rotation(irange(r, 0, 23)) : random_rotation(r);
  for (auto& v : loop) v = R * v;
  return flat_of(loop);
}

// Two convex polygons exactly in one plane (float coordinates): vertices on
// circles in the plane z = 0 (angles sorted, so the loops are convex), B's
// centre at a random in-plane distance (gap, touching range or overlap), then
// a map that keeps them exactly coplanar in float: z = 2^j x (exact), axis
// permutations and sign flips (cube rotations).  Only the side axes separate
// such a pair when there is a gap (best_axis.hpp).
std::pair<ShapeSpec, ShapeSpec> coplanar_flat_pair(Rng& r) {
  auto loop_at = [&](double cx, double cy) {
    const int n = irange(r, 3, 8);
    const double rad = uni(r, 0.3, 1.0);
    std::vector<double> ang;
    for (int i = 0; i < n; ++i) ang.push_back(uni(r, 0, 6.283185307179586));
    std::sort(ang.begin(), ang.end());
    std::vector<V> loop;
    for (double a : ang) {
      const V p(static_cast<float>(cx + rad * std::cos(a)), static_cast<float>(cy + rad * std::sin(a)), 0.0);
      if (!loop.empty() && (p - loop.back()).norm() < 0.05 * rad) continue;
      loop.push_back(p);
    }
    while (loop.size() > 3 && (loop.front() - loop.back()).norm() < 0.05 * rad) loop.pop_back();
    return loop;
  };
  const double dist = uni(r, 0.0, 2.5), dir = uni(r, 0, 6.283185307179586);
  std::vector<V> la = loop_at(0, 0), lb = loop_at(dist * std::cos(dir), dist * std::sin(dir));
  const int tilt = irange(r, -2, 2);  // z = 2^tilt x, or no tilt
  const Eigen::Matrix3d R = cube_rotation(irange(r, 0, 23));
  for (auto* l : {&la, &lb})
    for (auto& v : *l) {
      if (tilt != 0) v[2] = std::ldexp(v[0], tilt);
      v = R * v;
    }
  return {flat_of(la), flat_of(lb)};
}

ShapeSpec random_prism(Rng& r) {
  const int n = irange(r, 3, 32);
  const double radius = uni(r, 0.3, 1.2), half_height = uni(r, 0.2, 1.2);
  return spec_from(shapes::prism<double>(n, radius, half_height));
}

ShapeSpec perturbed(Rng& r, ShapeSpec s) {
  const double ext = 2 * radius_of(s);
  const int v = irange(r, 0, static_cast<int>(s.vertices.size()) - 1);
  const V dir = random_unit(r);
  s.vertices[static_cast<std::size_t>(v)] += dir * ext * log_uni(r, 1e-8, 5e-6);
  round_to_float(s);
  return s;
}

ShapeSpec any_solid(Rng& r) {
  switch (irange(r, 0, 3)) {
    case 0:
      return random_box(r);
    case 1:
      return random_tetra(r);
    case 2:
      return random_prism(r);
    default:
      return sphere_hull(r, irange(r, 4, 24));
  }
}

// Place B near A: random rotation (or a cube rotation), centre at a distance
// around the sum of the radii, so overlaps, contacts and separations all occur.
FuzzCase place(Rng& r, const std::string& fam, ShapeSpec a, ShapeSpec b, bool grid = false) {
  FuzzCase c;
  c.family = fam;
  const double ra = radius_of(a), rb = radius_of(b);
  const Eigen::Matrix3d RA = irange(r, 0, 2) == 0 ? Eigen::Matrix3d::Identity() : random_rotation(r);
  c.a = transformed(a, RA, V::Zero());
  const Eigen::Matrix3d RB = (grid || irange(r, 0, 1)) ? cube_rotation(irange(r, 0, 23)) : random_rotation(r);
  V t;
  if (grid) {
    const double step = 0.25;
    t = int3(r, -8, 8) * step;
  } else {
    const V dir = random_unit(r);
    t = dir * (ra + rb) * uni(r, 0.3, 1.15);
  }
  c.b = transformed(b, RB, t);
  return c;
}

// ---- exactly touching placements ----
ShapeSpec int_shape(Rng& r) {
  switch (irange(r, 0, 3)) {
    case 0: {
      const V h = int3(r, 1, 4);
      return spec_from(shapes::box<double>(h[0], h[1], h[2]));
    }
    case 1:
      for (;;) {
        std::array<V, 4> p;
        for (auto& x : p) x = int3(r, -4, 4);
        if ((p[1] - p[0]).cross(p[2] - p[0]).dot(p[3] - p[0]) != 0) return tetra_of(p);
      }
    case 2:
      for (;;) {
        std::vector<V> t;
        for (int i = 0; i < 3; ++i) t.push_back(int3(r, -4, 4));
        if (!(t[1] - t[0]).cross(t[2] - t[0]).isZero()) return flat_of(t);
      }
    default: {
      const double a = irange(r, 1, 4), b = irange(r, 1, 4);
      return flat_of({V(-a, -b, 0), V(a, -b, 0), V(a, b, 0), V(-a, b, 0)});
    }
  }
}

FuzzCase touching(Rng& r) {
  FuzzCase c;
  c.family = "touching";
  c.a = int_shape(r);
  ShapeSpec b = int_shape(r);
  b = transformed(b, cube_rotation(irange(r, 0, 23)), V::Zero());
  // Everything below is exact in double: small integers and eighths.
  V t;
  if (irange(r, 0, 2) > 0) {
    // face contact: B's support vertex along -n onto a point of A's face f
    const auto& f = c.a.faces[static_cast<std::size_t>(irange(r, 0, static_cast<int>(c.a.faces.size()) - 1))];
    const V& p0 = c.a.vertices[static_cast<std::size_t>(f[0])];
    const V& p1 = c.a.vertices[static_cast<std::size_t>(f[1])];
    const V& p2 = c.a.vertices[static_cast<std::size_t>(f[2])];
    const V n = (p1 - p0).cross(p2 - p0);
    const int i = irange(r, 0, 8), j = irange(r, 0, 8 - i);
    const V p = (i * p0 + j * p1 + (8 - i - j) * p2) / 8.0;
    std::size_t best = 0;
    for (std::size_t k = 1; k < b.vertices.size(); ++k)
      if (n.dot(b.vertices[k]) < n.dot(b.vertices[best])) best = k;
    t = p - b.vertices[best];
  } else {
    // edge/vertex contact: a point of an edge of A onto a point of an edge of B
    auto edge_point = [&](const ShapeSpec& s) {
      const auto& f = s.faces[static_cast<std::size_t>(irange(r, 0, static_cast<int>(s.faces.size()) - 1))];
      const std::size_t k = static_cast<std::size_t>(irange(r, 0, static_cast<int>(f.size()) - 1));
      const V& x = s.vertices[static_cast<std::size_t>(f[k])];
      const V& y = s.vertices[static_cast<std::size_t>(f[(k + 1) % f.size()])];
      const int w = irange(r, 0, 8);
      return V((w * x + (8 - w) * y) / 8.0);
    };
    t = edge_point(c.a) - edge_point(b);
  }
  c.b = transformed(b, Eigen::Matrix3d::Identity(), t);
  // optional exact power-of-two scaling of the whole scene
  if (irange(r, 0, 2) == 0) {
    const double s = std::ldexp(1.0, irange(r, -12, 12));
    c.a = transformed(c.a, Eigen::Matrix3d::Identity(), V::Zero(), s);
    c.b = transformed(c.b, Eigen::Matrix3d::Identity(), V::Zero(), s);
  }
  return c;
}

// ---- shapes as collision pipelines produce them ----
// A point of the ellipsoid sum (x_i / rad_i)^2 = 1 along direction d.
V on_ellipsoid(const V& d, const V& rad) {
  const double q = (d[0] / rad[0]) * (d[0] / rad[0]) + (d[1] / rad[1]) * (d[1] / rad[1]) +
                   (d[2] / rad[2]) * (d[2] / rad[2]);
  return d / std::sqrt(q);
}

// Two neighbouring pieces of a convex decomposition (what V-HACD and CoACD
// output): an ellipsoid (sometimes thin: one radius 1e-3..1e-1 of the others)
// cut by a plane through its centre; each piece is the hull of surface points
// on its side and of points of the cut section, which both pieces share (so
// they touch along the cut, and the float rounding of the section makes many
// nearly coplanar faces); 16..64 points per piece.  B is then left touching,
// pushed off by a tiny gap or pressed in by a tiny overlap, and the pair is
// rotated and, one time in two, moved far from the origin at world scale
// (1..100 units, 1e2..1e4 away).
FuzzCase decomposition_pair(Rng& r) {
  V rad = uni3(r, 0.3, 1.5);
  if (irange(r, 0, 2) == 0) {  // thin piece
    const int axis = irange(r, 0, 2);
    rad[axis] *= log_uni(r, 1e-3, 1e-1);
  }
  const V n = random_unit(r);
  const V u = (std::abs(n[0]) < 0.9 ? V(1, 0, 0) : V(0, 1, 0)).cross(n).normalized();
  const V w = n.cross(u);
  const int total_a = irange(r, 16, 64), total_b = irange(r, 16, 64);
  const int ncut = irange(r, 4, 16);
  std::vector<V> cut;
  for (int i = 0; i < ncut; ++i) {
    const double t = uni(r, 0, 6.283185307179586);
    cut.push_back(on_ellipsoid(std::cos(t) * u + std::sin(t) * w, rad));
  }
  auto piece = [&](int total, double side) {
    std::vector<V> pts = cut;
    while (static_cast<int>(pts.size()) < std::max(total, ncut + 4)) {
      const V p = on_ellipsoid(random_unit(r), rad);
      if (side * n.dot(p) > 1e-3) pts.push_back(p);
    }
    return pts;
  };
  std::vector<V> pa = piece(total_a, 1), pb = piece(total_b, -1);
  const int mode = irange(r, 0, 2);  // touching, gap, overlap
  const double eps = mode == 0 ? 0.0 : log_uni(r, 1e-7, 1e-3) * (mode == 1 ? -1 : 1);
  for (auto& p : pb) p += eps * n;
  const Eigen::Matrix3d R = random_rotation(r);
  const bool world = irange(r, 0, 1) == 1;
  const double scale = world ? log_uni(r, 1, 100) : 1.0;
  V far = V::Zero();
  if (world) {
    const V dir = random_unit(r);
    far = dir * log_uni(r, 1e2, 1e4);
  }
  for (auto* pts : {&pa, &pb})
    for (auto& p : *pts) p = V(R * (p * scale));
  // The hulls are built near the origin (float cannot resolve them far
  // away), then moved: the far vertices are the float roundings of the moved
  // ones, as a pipeline that places pieces in the world gives them.
  FuzzCase c;
  c.family = "decomposition";
  c.a = transformed(hull_of(pa), Eigen::Matrix3d::Identity(), far);
  c.b = transformed(hull_of(pb), Eigen::Matrix3d::Identity(), far);
  return c;
}

// A scanned object's hull: 200..2000 points on a smooth closed surface (an
// ellipsoid, or a superellipsoid with exponent 2.5..4), each moved along a
// random direction by noise of relative size 1e-4..1e-2, as a depth sensor
// gives them; its hull has many small, nearly coplanar faces.
ShapeSpec scanned_hull(Rng& r) {
  const V rad = uni3(r, 0.4, 1.2);
  const bool super = irange(r, 0, 1) == 1;
  const double e = uni(r, 2.5, 4.0), noise = log_uni(r, 1e-4, 1e-2);
  const int n = static_cast<int>(std::lround(log_uni(r, 200, 2000)));
  std::vector<V> pts;
  for (int i = 0; i < n; ++i) {
    const V d = random_unit(r);
    V p;
    if (super) {
      const double q = std::pow(std::pow(std::abs(d[0] / rad[0]), e) + std::pow(std::abs(d[1] / rad[1]), e) +
                                    std::pow(std::abs(d[2] / rad[2]), e),
                                -1.0 / e);
      p = d * q;
    } else {
      p = on_ellipsoid(d, rad);
    }
    const V jitter = random_unit(r);
    pts.push_back(p + jitter * (noise * uni(r, 0, 1)));
  }
  return hull_of(pts);
}

FuzzCase make(const std::string& fam, Rng& r) {
  if (fam == "sphere") {
    const int na = static_cast<int>(std::lround(log_uni(r, 4, 256)));
    // B mostly smaller: the exact reference costs O(E_A E_B) rational work
    const int nb = static_cast<int>(std::lround(log_uni(r, 4, irange(r, 0, 7) == 0 ? 256 : 48)));
    ShapeSpec a = sphere_hull(r, na);
    ShapeSpec b = sphere_hull(r, nb);
    return place(r, fam, std::move(a), std::move(b));
  }
  if (fam == "boxes") {
    ShapeSpec a = random_box(r);
    ShapeSpec b = random_box(r);
    const bool grid = irange(r, 0, 1) == 0;
    return place(r, fam, std::move(a), std::move(b), grid);
  }
  if (fam == "tetra") {
    ShapeSpec a = random_tetra(r);
    ShapeSpec b = irange(r, 0, 1) ? random_tetra(r) : any_solid(r);
    return place(r, fam, std::move(a), std::move(b));
  }
  if (fam == "flat") {
    if (irange(r, 0, 3) == 0) {
      // coplanar polygons, placed as drawn (no pose: a pose would round them
      // off their common plane)
      auto [a, b] = coplanar_flat_pair(r);
      FuzzCase c;
      c.family = fam;
      c.a = std::move(a);
      c.b = std::move(b);
      return c;
    }
    ShapeSpec a = random_flat(r);
    ShapeSpec b = irange(r, 0, 2) == 0 ? random_flat(r) : any_solid(r);
    const bool grid = irange(r, 0, 2) == 0;
    FuzzCase c = place(r, fam, std::move(a), std::move(b), grid);
    if (irange(r, 0, 1)) std::swap(c.a, c.b);
    return c;
  }
  if (fam == "prisms") {
    ShapeSpec a = random_prism(r);
    ShapeSpec b = irange(r, 0, 1) ? random_prism(r) : random_box(r);
    const bool grid = irange(r, 0, 2) == 0;
    return place(r, fam, std::move(a), std::move(b), grid);
  }
  if (fam == "perturbed") {
    ShapeSpec a = irange(r, 0, 1) ? random_box(r) : random_prism(r);
    a = perturbed(r, std::move(a));
    ShapeSpec b = irange(r, 0, 1) ? perturbed(r, random_box(r)) : any_solid(r);
    return place(r, fam, std::move(a), std::move(b));
  }
  if (fam == "scales") {
    static const char* inner[] = {"boxes", "tetra", "flat", "prisms", "sphere"};
    FuzzCase c = make(inner[irange(r, 0, 4)], r);
    const double s = log_uni(r, 1e-4, 1e4);
    const V dir = random_unit(r);
    const V far = dir * s * log_uni(r, 1, 300);
    c.a = transformed(c.a, Eigen::Matrix3d::Identity(), far, s);
    c.b = transformed(c.b, Eigen::Matrix3d::Identity(), far, s);
    c.family = fam;
    return c;
  }
  if (fam == "touching") return touching(r);
  if (fam == "decomposition") return decomposition_pair(r);
  if (fam == "scanned") {
    // against a small partner: the exact reference costs O(E_A E_B)
    ShapeSpec a = scanned_hull(r);
    ShapeSpec b = irange(r, 0, 1) ? random_box(r) : random_tetra(r);
    return place(r, fam, std::move(a), std::move(b));
  }
  throw std::invalid_argument("unknown case family '" + fam + "'");
}

}  // namespace

const std::vector<std::string>& family_names() {
  static const std::vector<std::string> names{"sphere",    "boxes",  "tetra",    "flat",          "prisms",
                                              "perturbed", "scales", "touching", "decomposition", "scanned"};
  return names;
}

FuzzCase generate(const std::string& family, std::uint64_t seed) {
  Rng r(seed * 0x9E3779B97F4A7C15ull + name_hash(family));
  FuzzCase c = make(family, r);
  c.seed = seed;
  return c;
}

ShapeSpec hull_of(std::vector<Vec3<double>> points) {
  // The library's hull builder, run in float on the float-rounded points: the
  // hull's vertices are input points, so they stay float values.
  std::vector<Vec3<float>> pts;
  for (const auto& p : points)
    pts.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
  const ConvexPolyhedron<float> h = convex_hull<float>(pts);
  ShapeSpec s;
  for (const auto& v : h.vertices()) s.vertices.emplace_back(double(v[0]), double(v[1]), double(v[2]));
  for (int f = 0; f < h.face_count(); ++f) s.faces.push_back(h.face_vertices(f));
  return s;
}

ShapeSpec posed(const ShapeSpec& s, const double t[3], const double q[4]) {
  return transformed(s, quat_matrix(q), V(t[0], t[1], t[2]));
}

ShapeSpec builtin_shape(const std::string& name) {
  auto params = [&](std::size_t want) {
    std::vector<double> out;
    const auto colon = name.find(':');
    if (colon == std::string::npos) return out;
    std::string rest = name.substr(colon + 1);
    std::size_t pos = 0;
    while (pos <= rest.size() && out.size() < want) {
      const auto comma = rest.find(',', pos);
      const std::string tok = rest.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
      char* end = nullptr;
      const double x = std::strtod(tok.c_str(), &end);
      if (tok.empty() || *end != '\0' || !std::isfinite(x))
        throw InvalidInput(ErrorCode::Parse, "shape '" + name + "': '" + tok + "' is not a number");
      out.push_back(x);
      if (comma == std::string::npos) break;
      pos = comma + 1;
    }
    return out;
  };
  const std::string head = name.substr(0, name.find(':'));
  ShapeSpec s;
  if (head == "cube") {
    s = spec_from(shapes::cube<double>(1.0));
  } else if (head == "box") {
    const auto p = params(3);
    if (p.size() != 3) throw InvalidInput(ErrorCode::Parse, "box needs box:HX,HY,HZ, got '" + name + "'");
    s = spec_from(shapes::box<double>(p[0], p[1], p[2]));
  } else if (head == "tetra") {
    s = spec_from(shapes::tetrahedron<double>(1.0));
  } else if (head == "prism" || head == "polygon") {
    const auto p = params(1);
    if (p.size() != 1 || p[0] != std::floor(p[0]) || p[0] < 3 || p[0] > 100000)
      throw InvalidInput(ErrorCode::Parse,
                         head + " needs " + head + ":N with an integer N >= 3, got '" + name + "'");
    const int n = static_cast<int>(p[0]);
    s = spec_from(head == "prism" ? shapes::prism<double>(n) : shapes::regular_polygon<double>(n));
  } else if (head == "triangle") {
    s = flat_of({V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)});  // the same triangle as the sepax program's built-in
  } else {
    throw InvalidInput(ErrorCode::Parse,
                       "unknown shape '" + name +
                           "' (built-in shapes: cube, box:HX,HY,HZ, tetra, prism:N, polygon:N, "
                           "triangle; or a fuzz case file with --case)");
  }
  round_to_float(s);
  return s;
}

// ---- libFuzzer decoding ----
namespace {
struct ByteReader {
  const std::uint8_t* p;
  std::size_t n;
  std::uint8_t u8() {
    if (n == 0) return 0;
    --n;
    return *p++;
  }
  double s16(double scale) {
    const int hi = u8(), lo = u8();
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(hi << 8 | lo)) * scale;
  }
  V v3(double scale) {  // x, y, z in this order (declarators are sequenced)
    const double x = s16(scale), y = s16(scale), z = s16(scale);
    return V(x, y, z);
  }
};

ShapeSpec decode_shape(ByteReader& br) {
  const int kind = br.u8() % 6;
  switch (kind) {
    case 0: {  // hull of 4..19 points on a 1/1024 grid
      const int n = 4 + br.u8() % 16;
      std::vector<V> pts;
      for (int i = 0; i < n; ++i) pts.push_back(br.v3(1.0 / 1024));
      return hull_of(pts);
    }
    case 1: {
      const double hx = 1 + br.u8() / 64.0, hy = 1 + br.u8() / 64.0, hz = 1 + br.u8() / 64.0;
      return spec_from(shapes::box<double>(hx, hy, hz));
    }
    case 2: {
      std::array<V, 4> p;
      for (auto& x : p) x = br.v3(1.0 / 1024);
      return tetra_of(p);
    }
    case 3: {
      const int sides = 3 + br.u8() % 14;
      const double half_height = 0.25 + br.u8() / 128.0;
      return spec_from(shapes::prism<double>(sides, 1.0, half_height));
    }
    case 4: {
      std::vector<V> t;
      for (int i = 0; i < 3; ++i) t.push_back(br.v3(1.0 / 1024));
      return flat_of(t);
    }
    default:
      return spec_from(shapes::regular_polygon<double>(3 + br.u8() % 6, 1.0));
  }
}
}  // namespace

FuzzCase decode_bytes(const std::uint8_t* data, std::size_t size) {
  ByteReader br{data, size};
  FuzzCase c;
  c.family = "libfuzzer";
  try {
    c.a = decode_shape(br);
    const ShapeSpec b = decode_shape(br);
    const double scale = std::ldexp(1.0, static_cast<int>(br.u8() % 9) - 4);
    double t[3] = {br.s16(scale / 4096), br.s16(scale / 4096), br.s16(scale / 4096)};
    double q[4] = {br.s16(1.0), br.s16(1.0), br.s16(1.0), br.s16(1.0)};
    if (br.u8() & 1) {  // a cube rotation instead: exact
      const Eigen::Matrix3d R = cube_rotation(br.u8() % 24);
      c.b = transformed(b, R, V(t[0], t[1], t[2]));
    } else {
      c.b = posed(b, t, q);
    }
  } catch (const InvalidInput&) {
    // degenerate decoded point set: fall back to two unit cubes
    c.a = spec_from(shapes::cube<double>(1.0));
    c.b = c.a;
  }
  return c;
}

}  // namespace sepax::fuzz
