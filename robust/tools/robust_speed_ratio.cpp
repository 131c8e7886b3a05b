// Quick timing of policy::Robust against policy::Plain (not a unit test, not
// the benchmark): random convex hulls of 16..64 points on the unit sphere,
// random overlapping poses, Gauss-map SAT (and brute force on a subset).
//
// Build and run (see docs/robust.md):
//   g++-12 -std=c++20 -O2 -DNDEBUG -I include -I robust/include -I tests -I /usr/include/eigen3 robust/tools/robust_speed_ratio.cpp -o /tmp/robust_speed_ratio -lgmpxx -lgmp
//   /tmp/robust_speed_ratio
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include <sepax/robust/robust_kernel.hpp>
#include <sepax/sat_brute_force.hpp>
#include <sepax/sat_gauss_map.hpp>

#include "robust/random_shapes.hpp"

using namespace sepax;

template <class Policy, class T, class Pairs>
double run(const Pairs& pairs, int reps, bool brute, std::int64_t& fallbacks, double& checksum) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < reps; ++r) {
    for (const auto& [a, b] : pairs) {
      const auto res = brute ? sat::brute_force<Policy>(a, b) : sat::gauss_map<Policy>(a, b);
      fallbacks += res.stats.exact_fallbacks;
      checksum += static_cast<double>(res.separation.num) + res.feature.a;
    }
  }
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t1 - t0).count();
}

template <class T>
void measure(int npts, bool brute) {
  std::mt19937_64 rng(42 + static_cast<unsigned>(npts));
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<ConvexPolyhedron<T>> hulls;
  for (int i = 0; i < 8; ++i) hulls.push_back(testing::random_sphere_hull<T>(rng, npts));
  std::vector<std::pair<ConvexPolyhedron<T>, ConvexPolyhedron<T>>> pairs;
  for (int i = 0; i < 64; ++i) {
    Vec3<double> d(u(rng), u(rng), u(rng));
    d = d.normalized() * (0.3 + 1.2 * (0.5 + 0.5 * u(rng)));  // centres 0.3..1.5 apart: overlapping
    pairs.emplace_back(
        testing::posed(hulls[static_cast<std::size_t>(i) % 8], testing::random_rotation(rng),
                       Vec3<double>(0, 0, 0)),
        testing::posed(hulls[static_cast<std::size_t>(i / 8) % 8], testing::random_rotation(rng), d));
  }
  const int reps = brute ? 1 : 40;
  std::int64_t fb_plain = 0, fb_robust = 0;
  double cs = 0;
  // interleave to share machine noise; take the best of 5 rounds of each
  double best_plain = 1e30, best_robust = 1e30;
  for (int round = 0; round < 5; ++round) {
    best_plain = std::min(best_plain, run<policy::Plain, T>(pairs, reps, brute, fb_plain, cs));
    fb_robust = 0;
    best_robust = std::min(best_robust, run<policy::Robust, T>(pairs, reps, brute, fb_robust, cs));
  }
  const double n = static_cast<double>(pairs.size()) * reps;
  std::printf(
      "%-6s %-11s %2d pts: plain %8.2f us  robust %8.2f us  ratio %.3f  exact fallbacks/query %.4f  (%g)\n",
      std::string(number_traits<T>::name).c_str(), brute ? "brute_force" : "gauss_map", npts,
      1e6 * best_plain / n, 1e6 * best_robust / n, best_robust / best_plain,
      static_cast<double>(fb_robust) / n, cs > 0 ? 1.0 : 0.0);
}

int main() {
  for (int npts : {16, 32, 64}) {
    measure<float>(npts, false);
    measure<double>(npts, false);
  }
  measure<float>(16, true);
  measure<double>(16, true);
}
