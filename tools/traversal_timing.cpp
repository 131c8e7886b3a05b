// Rough timing of sat::traversal against sat::gauss_map (not a unit test; the
// benchmark in bench/ is the reference).  Float, hulls of N random points on
// the unit sphere, B turned and shifted so that the hulls overlap.
//
//   cmake --build build --target traversal_timing && build/tools/traversal_timing
#include <chrono>
#include <cstdio>

#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>

#include "traversal_shapes.hpp"

using namespace sepax;

template <class F>
double seconds_per_call(F&& f, int calls) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < calls; ++i) f();
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t1 - t0).count() / calls;
}

int main() {
  std::mt19937_64 rng(1);
  for (int n : {16, 32, 64, 128}) {
    double tg = 0, tt = 0;
    int agree = 0;
    const int pairs = 10;
    for (int p = 0; p < pairs; ++p) {
      const auto ad = test::sphere_hull(rng, n);
      const auto bd =
          test::moved(test::sphere_hull(rng, n), test::random_rotation(rng), test::V3(0.6, 0.4, 0.2));
      const auto a = ConvexPolyhedron<float>::convert_from(ad);
      const auto b = ConvexPolyhedron<float>::convert_from(bd);
      const GaussMapWalk wa(a), wb(b);
      const int calls = 40000 / n;
      volatile float sink = 0;
      tg += seconds_per_call([&] { sink = sink + sat::gauss_map(a, b).separation.num; }, calls);
      tt += seconds_per_call([&] { sink = sink + sat::traversal(a, wa, b, wb).separation.num; }, calls);
      agree += sat::gauss_map(a, b).feature == sat::traversal(a, wa, b, wb).feature;
    }
    std::printf("N=%4d  gauss_map %9.2f us  traversal %8.2f us  ratio %5.1fx  (same feature %d/%d)\n", n,
                1e6 * tg / pairs, 1e6 * tt / pairs, tg / tt, agree, pairs);
  }
}
