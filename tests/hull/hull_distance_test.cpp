// hull/hull_distance.hpp: face_distance on a large face (fan_distance2: a bisection and a walk) gives the
// distance a pass over every edge gives, for points inside, beyond an edge, beyond a corner and far away,
// on polygons of 32 to 10^4 corners, regular and irregular, in planes of every tilt.
#include <catch2/catch.hpp>

#include <sepax/hull/hull_distance.hpp>
#include <sepax/hull/polygon_2d.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace {

using sepax::dot;
using sepax::Vec3;
using namespace sepax::hull::detail;

// The distance of x from the face polygon by a pass over every edge (the small-face path).
double brute_distance(const PolygonFace& fc, const Vec3<double>& x, double h) {
  bool inside = true;
  for (std::size_t i = 0; i < fc.v.size(); ++i) inside = inside && !beyond_edge(fc, i, x);
  if (inside) return std::abs(h);
  double d2 = 1e300;
  for (std::size_t i = 0; i < fc.v.size(); ++i) d2 = std::min(d2, edge_distance2(fc, i, x));
  return std::sqrt(d2);
}

}  // namespace

TEST_CASE("face distance: the fan search agrees with a pass over every edge", "[hull]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> turn(0.0, 2 * std::numbers::pi);
  long outside = 0, inside = 0;
  for (const std::size_t n : {std::size_t{32}, std::size_t{33}, std::size_t{100}, std::size_t{10000}}) {
    for (int shape = 0; shape < 6; ++shape) {
      // corners at sorted random angles (shape > 0) or evenly spaced, on an ellipse, in a tilted plane
      std::vector<double> angles(n);
      for (std::size_t i = 0; i < n; ++i)
        angles[i] =
            shape == 0 ? 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n) : turn(rng);
      std::sort(angles.begin(), angles.end());
      angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
      Vec3<double> nrm(unit(rng), unit(rng), unit(rng));
      nrm /= nrm.norm();
      const auto [ax, bx] = plane_basis(nrm);
      const double ra = 1 + 3 * (unit(rng) + 1), rb = 1;
      const Vec3<double> centre(unit(rng), unit(rng), unit(rng));
      std::vector<Vec3<double>> corners;
      for (const double t : angles) corners.push_back(centre + ra * std::cos(t) * ax + rb * std::sin(t) * bx);
      PolygonFace fc;
      fc.v = corners;
      fc.n = nrm;
      fc.off = dot(nrm, centre);
      for (int q = 0; q < 400; ++q) {
        const double scale = q % 4 == 0 ? 0.5 : q % 4 == 1 ? 1.0 + 1e-9 : q % 4 == 2 ? 1.3 : 50.0;
        const double t = turn(rng);
        const Vec3<double> x(centre + scale * (ra * std::cos(t) * ax + rb * std::sin(t) * bx) +
                             unit(rng) * nrm);
        const double h = dot(nrm, x) - fc.off;
        const double fan = face_distance(fc, x, h), brute = brute_distance(fc, x, h);
        CHECK(fan == Approx(brute).epsilon(1e-12).margin(1e-12));
        (fan == std::abs(h) ? inside : outside) += 1;
      }
    }
  }
  CHECK(inside > 1000);
  CHECK(outside > 1000);
}
