// hull/vertex_tree.hpp: the vertices a VertexTree does not hand over have computed heights at most the
// limit, for float and double, at several scales and offsets; and the tree does skip vertices;
// VertexTree::height_holds.  hull/plane_tree.hpp: PlaneTree::max_height is the largest computed height of a
// point above the planes, bit for bit the value of a pass over every plane, first_above the first plane a
// pass finds above a limit, first_above_or_highest that plane or else the pass's first highest; and the tree
// does skip planes.
#include <catch2/catch.hpp>

#include <sepax/convex_hull.hpp>
#include <sepax/hull/plane_tree.hpp>
#include <sepax/hull/vertex_tree.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace {

using sepax::Plane;
using sepax::Vec3;

template <class T>
T computed_height(const Plane<T>& pl, const Vec3<T>& x) {
  return T(sepax::dot(pl.normal, x) - pl.offset);
}

}  // namespace

TEMPLATE_TEST_CASE("vertex tree: every vertex it skips is at most the limit above the plane", "[hull]", float,
                   double) {
  using T = TestType;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  long skipped = 0, below = 0;
  for (const double scale : {1e-3, 1.0, 1e3}) {
    for (const double offset : {0.0, 5.0}) {
      for (const int kind : {0, 1}) {  // on a sphere, in a thin slab
        std::vector<Vec3<T>> pts;
        for (int i = 0; i < 2000; ++i) {
          Vec3<double> d(gauss(rng), gauss(rng), gauss(rng));
          if (kind == 0) {
            d /= std::sqrt(d.squaredNorm());
          } else {
            d = Vec3<double>(unit(rng), unit(rng), 1e-4 * unit(rng));
          }
          const Vec3<double> x = scale * (d + Vec3<double>(offset, -offset, offset / 2));
          pts.emplace_back(T(x[0]), T(x[1]), T(x[2]));
        }
        std::vector<int> ids;
        for (int i = 0; i < static_cast<int>(pts.size()); ++i) ids.push_back(i);
        const sepax::hull::detail::VertexTree<T> tree(
            ids, [&](int v) { return pts[static_cast<std::size_t>(v)]; });
        std::uniform_int_distribution<int> pick(0, static_cast<int>(pts.size()) - 1);
        for (int trial = 0; trial < 200; ++trial) {
          const auto& a = pts[static_cast<std::size_t>(pick(rng))];
          const auto& b = pts[static_cast<std::size_t>(pick(rng))];
          const auto& c = pts[static_cast<std::size_t>(pick(rng))];
          const Plane<T> pl = sepax::plane_through(a, b, c);
          // limits from far below to above: a few units of the extent's rounding, and 0
          const T limit = trial % 4 == 0 ? T(0) : T(scale * std::ldexp(1.0, -(trial % 30)) * (trial % 3 - 1));
          std::vector<char> seen(pts.size(), 0);
          tree.may_exceed(pl, limit, [&](int v) { seen[static_cast<std::size_t>(v)] = 1; });
          for (std::size_t i = 0; i < pts.size(); ++i) {
            below += computed_height(pl, pts[i]) <= limit;
            if (seen[i]) continue;
            ++skipped;
            INFO("scale " << scale << " offset " << offset << " kind " << kind << " trial " << trial);
            REQUIRE(computed_height(pl, pts[i]) <= limit);
          }
        }
      }
    }
  }
  // the tree skips most of the vertices at most the limit above (a pruning, not a full scan)
  CHECK(skipped > below / 2);
}

TEMPLATE_TEST_CASE("vertex tree: a plane above every vertex hands none over, one below hands all", "[hull]",
                   float, double) {
  using T = TestType;
  std::vector<Vec3<T>> pts;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 500; ++i) pts.emplace_back(T(unit(rng)), T(unit(rng)), T(unit(rng)));
  std::vector<int> ids;
  for (int i = 0; i < 500; ++i) ids.push_back(i);
  const sepax::hull::detail::VertexTree<T> tree(ids, [&](int v) { return pts[static_cast<std::size_t>(v)]; });
  const Plane<T> up{Vec3<T>(T(0), T(0), T(1)), T(2)};  // z = 2, every point 1..3 below
  int visited = 0;
  tree.may_exceed(up, T(0), [&](int) { ++visited; });
  CHECK(visited == 0);
  const Plane<T> down{Vec3<T>(T(0), T(0), T(1)), T(-2)};  // z = -2, every point 1..3 above
  tree.may_exceed(down, T(0), [&](int) { ++visited; });
  CHECK(visited == 500);
}

TEMPLATE_TEST_CASE("vertex tree: max_height is the largest computed height of a pass over every vertex",
                   "[hull]", float, double) {
  using T = TestType;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const double scale : {1e-2, 1.0, 1e2}) {
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 3000; ++i)
      pts.emplace_back(T(scale * unit(rng)), T(scale * unit(rng)), T(scale * 1e-3 * unit(rng)));
    std::vector<int> ids;
    for (int i = 0; i < static_cast<int>(pts.size()); ++i) ids.push_back(i);
    const sepax::hull::detail::VertexTree<T> tree(ids,
                                                  [&](int v) { return pts[static_cast<std::size_t>(v)]; });
    for (int trial = 0; trial < 300; ++trial) {
      Vec3<T> n(T(unit(rng)), T(unit(rng)), T(unit(rng)));
      if (trial % 3 == 0) n = Vec3<T>(T(1e-3 * unit(rng)), T(1e-3 * unit(rng)), T(1));  // the slab's normal
      const Plane<T> pl{n, T(scale * unit(rng))};
      T full = -std::numeric_limits<T>::infinity();
      for (const auto& x : pts) full = std::max(full, computed_height(pl, x));
      int measured = 0;
      const T best = tree.max_height(pl, [&](int v) {
        ++measured;
        return computed_height(pl, pts[static_cast<std::size_t>(v)]);
      });
      INFO("scale " << scale << " trial " << trial);
      REQUIRE(best == full);
      CHECK(measured < static_cast<int>(pts.size()));
    }
  }
}

TEMPLATE_TEST_CASE("plane tree: the largest height is the pass's, bit for bit", "[hull]", float, double) {
  using T = TestType;
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  long visited = 0, total = 0;
  for (const double scale : {1e-3, 1.0, 1e3}) {
    for (const double offset : {0.0, 5.0}) {
      // the faces of a hull of sphere points (planes of every direction), and random planes
      std::vector<Vec3<T>> pts;
      for (int i = 0; i < 600; ++i) {
        Vec3<double> d(gauss(rng), gauss(rng), gauss(rng));
        d /= std::sqrt(d.squaredNorm());
        const Vec3<double> x = scale * (d + Vec3<double>(offset, -offset, offset / 2));
        pts.emplace_back(T(x[0]), T(x[1]), T(x[2]));
      }
      const auto hull = sepax::convex_hull(pts);
      std::vector<Plane<T>> planes;
      for (int f = 0; f < hull.face_count(); ++f) planes.push_back(hull.plane(f));
      std::uniform_int_distribution<int> pick(0, static_cast<int>(pts.size()) - 1);
      for (int i = 0; i < 200; ++i) {
        planes.push_back(sepax::plane_through(pts[static_cast<std::size_t>(pick(rng))],
                                              pts[static_cast<std::size_t>(pick(rng))],
                                              pts[static_cast<std::size_t>(pick(rng))]));
      }
      const sepax::hull::detail::PlaneTree<T> tree(
          static_cast<int>(planes.size()),
          [&](int f) -> const Plane<T>& { return planes[static_cast<std::size_t>(f)]; });
      for (int trial = 0; trial < 300; ++trial) {
        // points on the sphere, inside, outside and far away
        Vec3<double> d(gauss(rng), gauss(rng), gauss(rng));
        d /= std::sqrt(d.squaredNorm());
        const double r = trial % 4 == 0   ? 1.0
                         : trial % 4 == 1 ? 0.5 * (1 + unit(rng))
                                          : 1 + std::abs(unit(rng));
        const Vec3<double> xd = scale * (r * d + Vec3<double>(offset, -offset, offset / 2));
        const Vec3<T> x(static_cast<T>(xd[0]), static_cast<T>(xd[1]), static_cast<T>(xd[2]));
        T pass = -std::numeric_limits<T>::infinity();
        for (const auto& pl : planes) pass = std::max(pass, computed_height(pl, x));
        const T top = tree.max_height(x, [&](int f) {
          ++visited;
          return computed_height(planes[static_cast<std::size_t>(f)], x);
        });
        total += static_cast<long>(planes.size());
        CHECK(top == pass);
        // the first plane above a limit (from below the largest height to above it), as a pass finds it
        for (const T limit : {T(pass - T(scale)), T(pass - T(1e-6 * scale)), pass, T(0)}) {
          int first = -1;
          for (std::size_t f = 0; f < planes.size() && first < 0; ++f)
            if (computed_height(planes[f], x) > limit) first = static_cast<int>(f);
          CHECK(tree.first_above(x, limit, [&](int f) {
            return computed_height(planes[static_cast<std::size_t>(f)], x);
          }) == first);
        }
      }
    }
  }
  // (the tree skips most planes for points of a sphere against its faces)
  CHECK(visited < total / 2);
}

TEMPLATE_TEST_CASE("plane tree: first_above_or_highest is a pass's first plane above, else its first highest",
                   "[hull]", float, double) {
  using T = TestType;
  std::mt19937 rng(13);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const double scale : {1e-3, 1.0, 1e3}) {
    // the faces of a hull of cylinder points (many planes nearly through each point), each plane twice
    // (ties: the smaller index wins), a third of them passed over as dead (height -infinity)
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 800; ++i) {
      const double a = 3.14159265358979 * unit(rng);
      const Vec3<double> x = scale * Vec3<double>(std::cos(a), std::sin(a), unit(rng));
      pts.emplace_back(T(x[0]), T(x[1]), T(x[2]));
    }
    const auto hull = sepax::convex_hull(pts);
    std::vector<Plane<T>> planes;
    for (int f = 0; f < hull.face_count(); ++f) planes.push_back(hull.plane(f));
    for (int f = 0; f < hull.face_count(); ++f) planes.push_back(hull.plane(f));
    const sepax::hull::detail::PlaneTree<T> tree(
        static_cast<int>(planes.size()),
        [&](int f) -> const Plane<T>& { return planes[static_cast<std::size_t>(f)]; });
    for (int trial = 0; trial < 300; ++trial) {
      const Vec3<T>& p = pts[static_cast<std::size_t>(trial)];
      const Vec3<double> xd = trial % 3 == 0 ? Vec3<double>(sepax::vec_to_double(p))
                                             : Vec3<double>((1 + 1e-6 * unit(rng)) * sepax::vec_to_double(p));
      const Vec3<T> x(static_cast<T>(xd[0]), static_cast<T>(xd[1]), static_cast<T>(xd[2]));
      auto height = [&](int f) {
        return f % 3 == 1 ? -std::numeric_limits<T>::infinity()
                          : computed_height(planes[static_cast<std::size_t>(f)], x);
      };
      for (const T limit : {T(0), T(1e-6 * scale), T(-1)}) {
        // the pass: the first plane above limit, else the first of the largest height
        int first = -1, high = -1;
        T best = -std::numeric_limits<T>::infinity();
        for (int f = 0; f < static_cast<int>(planes.size()); ++f) {
          const T h = height(f);
          if (first < 0 && h > limit) first = f;
          if (h > best) {
            best = h;
            high = f;
          }
        }
        const auto r = tree.first_above_or_highest(x, limit, height);
        CHECK(r.above == (first >= 0));
        CHECK(r.face == (first >= 0 ? first : high));
        if (first < 0) CHECK(r.height == best);
      }
    }
  }
}

TEMPLATE_TEST_CASE("plane tree: no planes give -infinity", "[hull]", float, double) {
  using T = TestType;
  const sepax::hull::detail::PlaneTree<T> tree(0, [](int) -> const Plane<T>& {
    static const Plane<T> none{Vec3<T>(T(0), T(0), T(0)), T(0)};
    return none;
  });
  CHECK(tree.max_height(Vec3<T>(T(1), T(2), T(3)), [](int) { return T(0); }) ==
        -std::numeric_limits<T>::infinity());
}

TEMPLATE_TEST_CASE("vertex tree: height_holds needs the rounding margin below the limit", "[hull]", float,
                   double) {
  using T = TestType;
  using Tree = sepax::hull::detail::VertexTree<T>;
  const Plane<T> pl{Vec3<T>(T(0.6), T(0.8), T(0)), T(2)};
  const std::array<double, 3> mag{3.0, 4.0, 1.0};
  const T limit = T(1e-3);
  CHECK(Tree::height_holds(pl, mag, T(5e-4), limit));   // half the limit: far within it
  CHECK(!Tree::height_holds(pl, mag, limit, limit));    // no room for the rounding of a second evaluation
  CHECK(!Tree::height_holds(pl, mag, T(2e-3), limit));  // above the limit
  CHECK(!Tree::height_holds(pl, mag, T(-1), limit));    // (a negative bound is not accepted)
  const std::array<double, 3> huge{1e30, 1e30, 1e30};
  CHECK(!Tree::height_holds(pl, huge, T(5e-4), limit));  // rounding of the coordinates beyond the room
  const Plane<T> nan{Vec3<T>(std::numeric_limits<T>::quiet_NaN(), T(0), T(0)), T(0)};
  CHECK(!Tree::height_holds(nan, mag, T(5e-4), limit));
}
