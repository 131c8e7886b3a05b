// FMA invariance probe.  Built twice from this one source (tests/fma/CMakeLists.txt):
// with the default flags and with -march=native -ffp-contract=fast, which lets
// the compiler fuse a*b+c into one rounding (FMA) anywhere in double code.
//
// For a fixed set of seeded cases (random posed pairs plus degenerate ones) it
// prints one line per case and per arithmetic:
//   E <case> <feature> <overlap> <sign>           exact (mpq_class): must not change
//   R <case> <feature> <overlap> <sign>           policy::Robust on doubles (when
//                                                 robust_kernel.hpp exists): must not change
//   D <case> <feature> <overlap> <separation %a>  plain double: may change (reported)
//   P <case> <plane triples of A> | <of B>        combinatorial input data: must not change
// compare.cmake runs both builds and requires identical E, R and P lines.
#include <sepax/robust/number_types.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>

#if __has_include(<sepax/robust/robust_kernel.hpp>)
#include <sepax/robust/robust_kernel.hpp>
#define SEPAX_FMA_HAVE_ROBUST 1
#endif

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace sepax;

namespace {

using P = ConvexPolyhedron<double>;

// A random rotation from a normalised double quaternion (rounded: the pose is
// just an input; both builds compute it with the same operations, and the
// arithmetic here is contraction-free by construction: see rotate()).
struct Pose {
  double m[9];
  Vec3<double> t;
};

Pose random_pose(std::mt19937_64& rng, double trange) {
  std::uniform_real_distribution<double> u(-1, 1), tr(-trange, trange);
  double q[4];
  double n2 = 0;
  do {
    n2 = 0;
    for (double& x : q) {
      x = u(rng);
    }
    // written as separate statements so that no a*b+c can be contracted into
    // an FMA: the INPUTS must be bit-identical in both builds
    volatile double s0 = q[0] * q[0];
    volatile double s1 = q[1] * q[1];
    volatile double s2 = q[2] * q[2];
    volatile double s3 = q[3] * q[3];
    n2 = s0 + s1;
    n2 = n2 + s2;
    n2 = n2 + s3;
  } while (n2 < 0.1 || n2 > 1);
  const double inv = 1.0 / std::sqrt(n2);
  for (double& x : q) x *= inv;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  auto pr = [](double a, double b) {
    volatile double r = a * b;
    return static_cast<double>(r);
  };
  Pose p;
  p.m[0] = 1 - 2 * (pr(y, y) + pr(z, z));
  p.m[1] = 2 * (pr(x, y) - pr(w, z));
  p.m[2] = 2 * (pr(x, z) + pr(w, y));
  p.m[3] = 2 * (pr(x, y) + pr(w, z));
  p.m[4] = 1 - 2 * (pr(x, x) + pr(z, z));
  p.m[5] = 2 * (pr(y, z) - pr(w, x));
  p.m[6] = 2 * (pr(x, z) - pr(w, y));
  p.m[7] = 2 * (pr(y, z) + pr(w, x));
  p.m[8] = 1 - 2 * (pr(x, x) + pr(y, y));
  p.t = Vec3<double>(tr(rng), tr(rng), tr(rng));
  return p;
}

P rotate(const P& s, const Pose& p) {
  std::vector<Vec3<double>> vs;
  for (const auto& v : s.vertices()) {
    double out[3];
    for (int r = 0; r < 3; ++r) {
      volatile double a = p.m[3 * r] * v[0];
      volatile double b = p.m[3 * r + 1] * v[1];
      volatile double c = p.m[3 * r + 2] * v[2];
      out[r] = (a + b) + c + p.t[r];
    }
    vs.push_back(Vec3<double>(out[0], out[1], out[2]));
  }
  return s.with_vertices(std::move(vs));
}

P translate(const P& s, double x, double y, double z) {
  std::vector<Vec3<double>> vs;
  for (const auto& v : s.vertices()) vs.push_back(Vec3<double>(v[0] + x, v[1] + y, v[2] + z));
  return s.with_vertices(std::move(vs));
}

template <class R>
std::string decision(const R& r) {
  return to_string(r.feature) + (r.overlap ? " overlap " : " separated ") +
         std::to_string(sign(r.separation));
}

// The plane triples (the vertices that define each face's plane, chosen as the
// best-conditioned triangle in double): combinatorial data the exact images
// inherit through convert_from, so they must not depend on FMA either.
std::string triples(const P& p) {
  std::string s;
  for (const auto& f : p.faces()) {
    for (int v : f.plane_vertices) s += std::to_string(v) + ",";
    s += "/";
  }
  return s;
}

void run(const std::string& id, const P& a, const P& b) {
  std::printf("P %s %s | %s\n", id.c_str(), triples(a).c_str(), triples(b).c_str());
  const auto qa = ConvexPolyhedron<mpq_class>::convert_from(a);
  const auto qb = ConvexPolyhedron<mpq_class>::convert_from(b);
  const auto e_gm = sat::gauss_map(qa, qb);
  const auto e_bf = sat::brute_force(qa, qb);
  // The traversal's path (start faces, cutoffs, pruning) must not depend on
  // FMA either: its walk counters are printed with its decision.
  const GaussMapWalk wa(a), wb(b);
  auto walk = [&](auto& k) {
    sat::TraversalStats ts;
    const auto r = sat::traversal_with(k, wa, wb, {}, &ts);
    return decision(r) + " steps " + std::to_string(ts.climb_steps) + "/" + std::to_string(ts.pruned_faces) +
           "/" + std::to_string(ts.pruned_arcs) + "/" + std::to_string(ts.arc_tests) + "/" +
           std::to_string(ts.late_certified);
  };
  PlainKernel<mpq_class> ek(qa, qb);
  std::printf("E %s gm %s | bf %s | tr %s\n", id.c_str(), decision(e_gm).c_str(), decision(e_bf).c_str(),
              walk(ek).c_str());
#ifdef SEPAX_FMA_HAVE_ROBUST
  const auto r_gm = sat::gauss_map<policy::Robust>(a, b);
  const auto r_bf = sat::brute_force<policy::Robust>(a, b);
  RobustKernel<double> rk(a, b);
  std::printf("R %s gm %s | bf %s | tr %s\n", id.c_str(), decision(r_gm).c_str(), decision(r_bf).c_str(),
              walk(rk).c_str());
#endif
  const auto d_gm = sat::gauss_map(a, b);
  const auto d_bf = sat::brute_force(a, b);
  std::printf("D %s gm %s %a | bf %s %a\n", id.c_str(), decision(d_gm).c_str(), d_gm.separation.num,
              decision(d_bf).c_str(), d_bf.separation.num);
}

}  // namespace

int main() {
  const std::vector<P> zoo{
      shapes::box<double>(1, 0.5, 0.75),
      shapes::tetrahedron<double>(0.75),
      shapes::prism<double>(6, 1.0, 0.5),
      shapes::prism<double>(16, 0.8, 1.0),
      shapes::regular_polygon<double>(5, 1.0),
      shapes::triangle<double>(Vec3<double>(0, 0, 0), Vec3<double>(1.5, 0, 0), Vec3<double>(0, 1, 0.25)),
      shapes::cube<double>(0.5)};
  // Degenerate cases: exact touching, ties, coplanar and parallel features.
  const auto cube = shapes::cube<double>(1.0);
  const auto tet = shapes::tetrahedron<double>(1.0);
  const auto tri =
      shapes::triangle<double>(Vec3<double>(-2, -2, 0), Vec3<double>(2, -2, 0), Vec3<double>(0, 2, 0));
  run("touch-face", cube, translate(cube, 0, 0, 2));
  run("touch-edge", tet, translate(tet, 0, 0, 2));
  run("touch-vertex", cube, translate(cube, 2, 2, 2));
  run("concentric", cube, shapes::cube<double>(0.5));
  run("tri-on-face", cube, translate(tri, 0, 0, 1));
  run("tri-coplanar", tri, translate(tri, 0.5, 0.5, 0));
  run("tri-parallel", tri, translate(tri, 0.5, 0.5, 0.5));
  run("near-touch", cube, translate(cube, 0, 0, 2 + 0x1p-50));
  run("near-overlap", cube, translate(cube, 0, 0, 2 - 0x1p-50));
  run("shifted-0.1", cube, translate(cube, 0.1, 0.2, 1.9));
  // Random posed pairs at scale 1, 1e-3 and 1e3 and far from the origin.
  std::mt19937_64 rng(20130327);
  for (int i = 0; i < 300; ++i) {
    const double scale = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 1e-3 : 1e3);
    const double far = i % 5 == 0 ? 1e3 * scale : 0.0;
    auto pa = random_pose(rng, 1.2 * scale), pb = random_pose(rng, 1.2 * scale);
    pa.t += Vec3<double>(far, far, -far);
    pb.t += Vec3<double>(far, far, -far);
    std::vector<Vec3<double>> sa, sb;
    const P& za = zoo[static_cast<std::size_t>(i) % zoo.size()];
    const P& zb = zoo[static_cast<std::size_t>(i / 7) % zoo.size()];
    for (const auto& v : za.vertices()) sa.push_back(v * scale);
    for (const auto& v : zb.vertices()) sb.push_back(v * scale);
    run("random-" + std::to_string(i), rotate(za.with_vertices(sa), pa), rotate(zb.with_vertices(sb), pb));
  }
  return 0;
}
