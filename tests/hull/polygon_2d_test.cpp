// hull/polygon_2d.hpp: hull_2d keeps every point within its tolerance of the polygon on dense arcs (the
// error of dropped corners does not add up) with corners that turn left, most by more than the tolerance;
// points along a square's edges leave its 4 corners; a needle thinner than the tolerance keeps both tips.
#include <catch2/catch.hpp>

#include <sepax/hull/polygon_2d.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace {

using namespace sepax::hull::detail;
using P = std::array<double, 2>;

// The largest distance of a point beyond an edge line of the counter-clockwise loop (0 inside).
double worst_outside(const std::vector<P>& p, const std::vector<std::size_t>& loop) {
  double worst = 0;
  for (const P& x : p) {
    double out = -1e300;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const P& a = p[loop[k]];
      const P& b = p[loop[(k + 1) % loop.size()]];
      const double ex = b[0] - a[0], ey = b[1] - a[1];
      out = std::max(out, -(ex * (x[1] - a[1]) - ey * (x[0] - a[0])) / std::hypot(ex, ey));
    }
    worst = std::max(worst, out);
  }
  return worst;
}

// The largest Euclidean distance of a point from the convex loop (0 inside; a loop of 2 corners is a
// segment, of 1 a point).
double worst_distance(const std::vector<P>& p, const std::vector<std::size_t>& loop) {
  auto segment = [](const P& x, const P& a, const P& b) {
    const double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
    const double t = l2 > 0 ? std::clamp(((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(x[0] - a[0] - t * ex, x[1] - a[1] - t * ey);
  };
  double worst = 0;
  for (const P& x : p) {
    if (loop.size() >= 3 && worst_outside({x}, loop) <= 0) continue;
    double d = 1e300;
    for (std::size_t k = 0; k < loop.size(); ++k)
      d = std::min(d, segment(x, p[loop[k]], p[loop[(k + 1) % loop.size()]]));
    worst = std::max(worst, d);
  }
  return worst;
}

}  // namespace

TEST_CASE("hull_2d: a dense arc keeps every point within the tolerance", "[hull]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> turn(0.0, 2 * std::numbers::pi);
  for (const double tol : {1e-3, 1e-5, 1e-8}) {
    std::vector<P> p;
    for (int i = 0; i < 20000; ++i) {
      const double t = turn(rng);
      p.push_back({3 * std::cos(t), std::sin(t)});
    }
    const std::vector<std::size_t> loop = hull_2d(p, tol);
    REQUIRE(loop.size() >= 3);
    CHECK(worst_outside(p, loop) <= tol * (1 + 1e-9));
    // every corner turns left; most by more than the tolerance (one that turns by less stays where dropping
    // it would leave a point beyond the tolerance)
    std::size_t sharp = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const P& a = p[loop[(k + loop.size() - 1) % loop.size()]];
      const P& b = p[loop[k]];
      const P& c = p[loop[(k + 1) % loop.size()]];
      const double ex = b[0] - a[0], ey = b[1] - a[1], fx = c[0] - b[0], fy = c[1] - b[1];
      CHECK(ex * fy - ey * fx > 0);
      if (ex * fy - ey * fx > tol * std::max(std::hypot(ex, ey), std::hypot(fx, fy))) ++sharp;
    }
    CHECK(sharp >= loop.size() * 9 / 10);
  }
}

TEST_CASE("hull_2d: a square with points along its edges and inside keeps its 4 corners", "[hull]") {
  std::vector<P> p{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 1; i < 1000; ++i) {
    const double s = i / 1000.0;
    p.push_back({s, 0});
    p.push_back({1, s});
    p.push_back({s, 1 + 1e-9 * std::sin(i)});
    p.push_back({0.5 * s, 0.3});
  }
  const std::vector<std::size_t> loop = hull_2d(p, 1e-6);
  REQUIRE(loop.size() == 4);
  std::vector<std::size_t> sorted = loop;
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted == std::vector<std::size_t>{0, 1, 2, 3});
}

// Every corner of a needle's loop is within the tolerance of the line through its tips: a chord checked
// against that line only (not the segment) would reach from one tip around the other, and the chord from the
// loop's first corner back to itself would skip every corner.  Both tips stay, every point within tol.
TEST_CASE("hull_2d: a needle thinner than the tolerance keeps both tips", "[hull]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const double width : {0.3, 0.9}) {
    for (int set = 0; set < 50; ++set) {
      const double tol = 1e-4;
      const double angle = 3 * u(rng);
      const double c = std::cos(angle), s = std::sin(angle);
      std::vector<P> p;
      for (int i = 0; i < 80; ++i) {
        const double x = 5 * u(rng), y = width * tol * u(rng);
        p.push_back({c * x - s * y, s * x + c * y});
      }
      const std::vector<std::size_t> loop = hull_2d(p, tol);
      INFO("width " << width << " set " << set << " corners " << loop.size());
      CHECK(loop.size() >= 2);
      CHECK(worst_distance(p, loop) <= tol * (1 + 1e-9));
    }
  }
}
