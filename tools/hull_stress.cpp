// Stress run (not a unit test) for convex_hull<float/double>: the point-set
// generator of tests/core/convex_hull_test.cpp (tests/core/hull_point_sets.hpp,
// shared: nine kinds of hard sets, scales 1e-6..1e6, offsets 1e4 x extent),
// streams of `count` sets per
// seed.  Per type and seed it prints the sets whose worst point is more than
// 1, 4 and 64 x coplanar*extent above a face plane (after subtracting the
// rounding of evaluating planes far from the origin, 64 u max|x|, as the
// unit test does), the worst one, and the same for the support gap: the
// largest difference of the support functions of the points and of the hull
// over ~300 directions (a lower bound on their Hausdorff distance), and the
// Euclidean distance of the farthest point from the hull (max_distance in
// hull_point_sets.hpp, the measure the unit test asserts; "dist" below).
// Sets above `report` are listed; and per seed the hulls with vertices that
// are not input points (projected slabs, flat; tents, solid: docs/hull.md).
// docs/hull.md quotes its output.
//   cmake --build build --target hull_stress
//   build/tools/hull_stress both 1 12 10000        # [float|double|both] first_seed last_seed count [only_iter report]
#include <sepax/convex_hull.hpp>
#include "../tests/core/hull_point_sets.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>
#include <string>
using namespace sepax;
using namespace sepax::hull_sets;
// Lower bound on the Hausdorff distance between conv(points) and the hull
// (the hull's vertices are input points, so it is inside conv(points)): the
// largest support difference over many directions, in units of eps.
template <class T>
double support_gap(const ConvexPolyhedron<T>& h, const std::vector<Vec3<T>>& pts) {
  std::vector<Vec3<double>> dirs;
  std::mt19937 r(5);
  std::normal_distribution<double> nd;
  for (int i = 0; i < 300; ++i) {
    Vec3<double> d(nd(r), nd(r), nd(r));
    dirs.push_back(d / d.norm());
  }
  for (int c = 0; c < 3; ++c)
    for (double s : {-1.0, 1.0}) {
      Vec3<double> d(0, 0, 0);
      d[c] = s;
      dirs.push_back(d);
    }
  for (int f = 0; f < h.face_count(); ++f) dirs.push_back(vec_to_double(h.plane(f).normal).normalized());
  double worst = 0;
  for (const auto& d : dirs) {
    double mp = -1e300, mh = -1e300;
    for (const auto& p : pts) mp = std::max(mp, d.dot(vec_to_double(p)));
    for (const auto& v : h.vertices()) mh = std::max(mh, d.dot(vec_to_double(v)));
    worst = std::max(worst, mp - mh);
  }
  return worst / (Tolerances<T>::kCoplanar * h.extent());
}
template <class T>
void run(unsigned seed, int iters, int only, double report) {
  std::mt19937 rng(seed);
  int over64 = 0, over4 = 0, over1 = 0, n = 0, err = 0, lerr = 0;
  double worst = -1e300;
  int worst_it = -1;
  double gworst = -1e300;
  int gworst_it = -1, gover64 = 0, gover4 = 0;
  double dworst = -1e300;
  int dworst_it = -1, dover64 = 0, dover4 = 0;
  int synthetic_flat = 0, synthetic_solid = 0;  // hulls with vertices that are not input points
  for (int iter = 0; iter < iters; ++iter) {
    const int kind = iter % 9;
    const auto pts = to_t<T>(random_point_set(rng, kind));
    if (only >= 0 && iter != only) continue;
    try {
      const auto h = convex_hull(pts);
      double out = max_outside(h, pts);
      double max_abs = 0;
      for (const auto& p : pts)
        for (int c = 0; c < 3; ++c) max_abs = std::max(max_abs, std::abs(to_double(p[c])));
      double allow = 64 * number_traits<T>::unit_roundoff * max_abs / (Tolerances<T>::kCoplanar * h.extent());
      double o = out - allow;  // excess beyond the offset allowance
      const double gap = support_gap(h, pts) - allow;
      if (gap > gworst) {
        gworst = gap;
        gworst_it = iter;
      }
      if (gap > 64) ++gover64;
      const double dist = max_distance(h, pts) - allow;
      if (dist > dworst) {
        dworst = dist;
        dworst_it = iter;
      }
      if (dist > 64) ++dover64;
      if (dist > 4) ++dover4;
      if (gap > 4) ++gover4;
      ++n;
      bool inputs = true;
      for (const auto& v : h.vertices()) {
        bool found = false;
        for (const auto& p : pts) found = found || p == v;
        inputs = inputs && found;
      }
      if (!inputs) ++(h.is_flat() ? synthetic_flat : synthetic_solid);
      if (o > 64) ++over64;
      if (o > 4) ++over4;
      if (o > 1) ++over1;
      if (o > worst) {
        worst = o;
        worst_it = iter;
      }
      if (o > report || gap > report || dist > report)
        std::printf(
            "  %s seed %u iter %d kind %d n %zu out %.3g allow %.3g flat %d gap %.3g dist %.3g verts %d\n",
            sizeof(T) == 4 ? "float" : "double", seed, iter, kind, pts.size(), out, allow, (int)h.is_flat(),
            gap, dist, h.vertex_count());
    } catch (const InvalidInput&) {
      ++err;
    } catch (const std::logic_error& e) {
      ++lerr;
      std::printf("  LOGIC %s seed %u iter %d: %s\n", sizeof(T) == 4 ? "float" : "double", seed, iter,
                  e.what());
    }
  }
  std::printf(
      "%s seed %u: %d hulls, %d errors, %d logic; >1: %d, >4: %d, >64: %d; worst %.3g (iter %d); support gap "
      ">4: %d >64: %d worst %.3g (iter %d); dist >4: %d >64: %d worst %.3g (iter %d); projected slabs %d, "
      "tents %d\n",
      sizeof(T) == 4 ? "float" : "double", seed, n, err, lerr, over1, over4, over64, worst, worst_it, gover4,
      gover64, gworst, gworst_it, dover4, dover64, dworst, dworst_it, synthetic_flat, synthetic_solid);
}
int main(int argc, char** argv) {
  const std::string type = argc > 1 ? argv[1] : "both";
  const unsigned s0 = argc > 2 ? unsigned(std::atoi(argv[2])) : 1,
                 s1 = argc > 3 ? unsigned(std::atoi(argv[3])) : 3;
  const int iters = argc > 4 ? std::atoi(argv[4]) : 10000;
  const int only = argc > 5 ? std::atoi(argv[5]) : -1;
  const double report = argc > 6 ? std::atof(argv[6]) : 64;
  for (unsigned s = s0; s <= s1; ++s) {
    if (type != "double") run<float>(s, iters, only, report);
    if (type != "float") run<double>(s, iters, only, report);
  }
}
