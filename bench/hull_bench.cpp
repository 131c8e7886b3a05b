// sepax_hull_bench: convex_hull<T> against CGAL's convex_hull_3 on the same
// points, one run, wall time.  Point sets (seed 42): on the unit sphere, in
// the unit ball, in a thin slab [-1, 1]^2 x [-1e-3, 1e-3], on a cylinder's
// lateral surface (radius 1, height 2); 10^min .. 10^max points.  Not run by
// default: "rim" (random angles on a cylinder's two rims, z = +-1: caps of
// n / 2 corners) and "circle" (random angles on one circle: a flat hull).
//   double, float: sepax against CGAL::Epick (float points widened exactly);
//   Epeck, mpq: convex_hull<CGAL::Epeck::FT>, convex_hull<mpq_class> against CGAL::Epeck, up to 10^exact.
// Ratio = sepax / CGAL (targets: 2 for double and float, 3 for Epeck and mpq).
//
//   sepax_hull_bench [--min 3] [--max 5] [--exact 4] [--kinds sphere,ball,slab,cylinder,rim,circle]
//                    [--types double,float,Epeck,mpq] [--run both|sepax|cgal] [--clock wall|cpu]
// --clock cpu times each hull by the thread's CPU time (CLOCK_THREAD_CPUTIME_ID) instead of the wall clock:
//   on a shared, loaded machine the wall time also counts the time other processes run.
// --run sepax (or cgal) builds only that side's hulls (the other column reads 0): for instruction counts,
//   valgrind --tool=callgrind build/bench/sepax_hull_bench --min 3 --max 3 --kinds sphere
//     --types double --run sepax   (one command line)
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <sepax/convex_hull.hpp>
#include <sepax/robust/number_types.hpp>

#include "../tests/core/hull_point_sets.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <time.h>

namespace {

bool cpu_clock = false;  // --clock cpu

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class F>
double seconds(F&& f) {
  if (cpu_clock) {
    const double t0 = thread_cpu_seconds();
    f();
    return thread_cpu_seconds() - t0;
  }
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
  int min_exp = 3, max_exp = 5, exact_exp = 4;
  std::vector<std::string> kinds{"sphere", "ball", "slab", "cylinder"};
  std::vector<std::string> types{"double", "float", "Epeck", "mpq"};
  std::string run = "both";
  const char* usage =
      "usage: sepax_hull_bench [--min 3] [--max 5] [--exact 4] "
      "[--kinds sphere,ball,slab,cylinder,rim,circle] [--types double,float,Epeck,mpq] "
      "[--run both|sepax|cgal] [--clock wall|cpu]\n";
  for (int i = 1; i < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s", usage);
      return 0;
    }
    if (i + 1 == argc) {  // an option without its value (a lone trailing word is not ignored)
      std::fprintf(stderr, "sepax_hull_bench: %s needs a value\n%s", a.c_str(), usage);
      return 2;
    }
    if (a == "--min") {
      min_exp = std::atoi(argv[i + 1]);
    } else if (a == "--max") {
      max_exp = std::atoi(argv[i + 1]);
    } else if (a == "--exact") {
      exact_exp = std::atoi(argv[i + 1]);
    } else if (a == "--kinds") {
      kinds = split(argv[i + 1]);
    } else if (a == "--types") {
      types = split(argv[i + 1]);
    } else if (a == "--run" && (std::string(argv[i + 1]) == "both" || std::string(argv[i + 1]) == "sepax" ||
                                std::string(argv[i + 1]) == "cgal")) {
      run = argv[i + 1];
    } else if (a == "--clock" && (std::string(argv[i + 1]) == "wall" || std::string(argv[i + 1]) == "cpu")) {
      cpu_clock = std::string(argv[i + 1]) == "cpu";
    } else {
      std::fprintf(stderr, "%s", usage);
      return 2;
    }
  }
  std::printf("| points | n | type | sepax s | CGAL s | sepax / CGAL | sepax V, F | CGAL V |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const auto& kind : kinds) {
    for (int e = min_exp; e <= max_exp; ++e) {
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
      const bool cgal = run != "sepax", mine = run != "cgal";
      auto wanted = [&](const char* t) { return std::find(types.begin(), types.end(), t) != types.end(); };
      if (wanted("double")) {
        const double epick = cgal ? cgal_hull<CGAL::Epick>(pts, cv) : 0;
        const double sd = mine ? sepax_hull<double>(pts, v, f) : 0;
        row("double", sd, epick, v, f, cv);
      }
      if (wanted("float")) {
        const double epick_f = cgal ? cgal_hull<CGAL::Epick>(fpts, cv) : 0;
        const double sf = mine ? sepax_hull<float>(pts, v, f) : 0;
        row("float", sf, epick_f, v, f, cv);
      }
      if (wanted("Epeck") && e <= exact_exp) {
        const double epeck = cgal ? cgal_hull<CGAL::Epeck>(pts, cv) : 0;
        const double se = mine ? sepax_hull<CGAL::Epeck::FT>(pts, v, f) : 0;
        row("Epeck", se, epeck, v, f, cv);
      }
      if (wanted("mpq") && e <= exact_exp) {
        const double epeck = cgal ? cgal_hull<CGAL::Epeck>(pts, cv) : 0;
        const double sq = mine ? sepax_hull<mpq_class>(pts, v, f) : 0;
        row("mpq", sq, epeck, v, f, cv);
      }
    }
  }
  return 0;
}
