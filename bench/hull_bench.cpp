// sepax_hull_bench: convex_hull<T> against CGAL's convex_hull_3 on the same
// points, one run, wall time.  Point sets (seed 42): on the unit sphere, in
// the unit ball, in a thin slab [-1, 1]^2 x [-1e-3, 1e-3], on a cylinder's
// lateral surface (radius 1, height 2); 10^3 .. 10^max points.
//   double, float: sepax against CGAL::Epick (float points widened exactly);
//   Epeck: convex_hull<CGAL::Epeck::FT> against CGAL::Epeck, up to 10^exact.
// Ratio = sepax / CGAL (targets: 2 for double and float, 3 for Epeck).
//
//   sepax_hull_bench [--max 5] [--exact 4] [--kinds sphere,ball,slab,cylinder]
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <sepax/convex_hull.hpp>
#include <sepax/robust/number_types.hpp>

#include "../tests/core/hull_point_sets.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

template <class F>
double seconds(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <class K>
double cgal_hull(const std::vector<sepax::Vec3<double>>& pts, std::size_t& vertices) {
  std::vector<typename K::Point_3> cp;
  cp.reserve(pts.size());
  for (const auto& x : pts) cp.emplace_back(x[0], x[1], x[2]);
  CGAL::Surface_mesh<typename K::Point_3> mesh;
  const double s = seconds([&] { CGAL::convex_hull_3(cp.begin(), cp.end(), mesh); });
  vertices = mesh.number_of_vertices();
  return s;
}

template <class T>
double sepax_hull(const std::vector<sepax::Vec3<double>>& pts, std::size_t& vertices, std::size_t& faces) {
  std::vector<sepax::Vec3<T>> tp;
  tp.reserve(pts.size());
  for (const auto& x : pts) tp.emplace_back(T(x[0]), T(x[1]), T(x[2]));
  sepax::ConvexPolyhedron<T> h;
  const double s = seconds([&] { h = sepax::convex_hull(tp); });
  vertices = static_cast<std::size_t>(h.vertex_count());
  faces = static_cast<std::size_t>(h.face_count());
  return s;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int max_exp = 5, exact_exp = 4;
  std::vector<std::string> kinds{"sphere", "ball", "slab", "cylinder"};
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--max") {
      max_exp = std::atoi(argv[i + 1]);
    } else if (a == "--exact") {
      exact_exp = std::atoi(argv[i + 1]);
    } else if (a == "--kinds") {
      kinds = split(argv[i + 1]);
    } else {
      std::fprintf(stderr, "usage: sepax_hull_bench [--max 5] [--exact 4] [--kinds sphere,ball,slab,cylinder]\n");
      return 2;
    }
  }
  std::printf("| points | n | type | sepax s | CGAL s | sepax / CGAL | sepax V, F | CGAL V |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const auto& kind : kinds) {
    for (int e = 3; e <= max_exp; ++e) {
      std::size_t n = 1;
      for (int k = 0; k < e; ++k) n *= 10;
      const auto pts = sepax::hull_sets::bench_point_set(kind, n);
      std::vector<sepax::Vec3<double>> fpts;  // the float points, widened exactly
      for (const auto& x : pts)
        fpts.emplace_back(double(float(x[0])), double(float(x[1])), double(float(x[2])));
      auto row = [&](const char* type, double s, double c, std::size_t v, std::size_t f, std::size_t cv) {
        std::printf("| %s | %zu | %s | %.4f | %.4f | %.2f | %zu, %zu | %zu |\n", kind.c_str(), n, type, s, c,
                    s / c, v, f, cv);
        std::fflush(stdout);
      };
      std::size_t v = 0, f = 0, cv = 0;
      const double epick = cgal_hull<CGAL::Epick>(pts, cv);
      const double sd = sepax_hull<double>(pts, v, f);
      row("double", sd, epick, v, f, cv);
      const double epick_f = cgal_hull<CGAL::Epick>(fpts, cv);
      const double sf = sepax_hull<float>(pts, v, f);
      row("float", sf, epick_f, v, f, cv);
      if (e <= exact_exp) {
        const double epeck = cgal_hull<CGAL::Epeck>(pts, cv);
        const double se = sepax_hull<CGAL::Epeck::FT>(pts, v, f);
        row("Epeck", se, epeck, v, f, cv);
      }
    }
  }
  return 0;
}
