// Stress run (not a unit test): exact traversal vs exact Gauss map on 4000
// random pairs of boxes, prisms, tetrahedra and polygons at exact rational
// rotations (integer quaternions) and quarter-unit offsets: ties, touching
// contacts, arcs through Gauss-map vertices everywhere.
//   cmake --build build --target traversal_stress && build/tools/traversal_stress 1
#include <gmpxx.h>
#include <sepax/robust/number_types.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/sat_traversal.hpp>
#include <sepax/shapes.hpp>
#include "traversal_shapes.hpp"
#include <cstdio>
using namespace sepax;
using Q = mpq_class;
int main(int argc, char** argv) {
  std::mt19937_64 rng(argc > 1 ? atoi(argv[1]) : 1);
  std::uniform_int_distribution<int> qi(-3, 3), ti(-6, 6), pick(0, 7);
  std::vector<ConvexPolyhedron<Q>> sh{
      shapes::cube<Q>(1.0),           shapes::box<Q>(1.0, 0.5, 0.25),     shapes::tetrahedron<Q>(0.75),
      shapes::prism<Q>(4, 1.0, 0.5),  shapes::regular_polygon<Q>(4, 1.0), shapes::regular_polygon<Q>(3, 1.0),
      shapes::prism<Q>(3, 0.75, 0.5), shapes::regular_polygon<Q>(6, 0.75)};
  long bad = 0, total = 0, fb = 0, corners = 0, lex = 0;
  for (int it = 0; it < 4000; ++it) {
    int q1[4], q2[4];
    for (int& x : q1) x = qi(rng);
    for (int& x : q2) x = qi(rng);
    if (!q1[0] && !q1[1] && !q1[2] && !q1[3]) q1[0] = 1;
    if (!q2[0] && !q2[1] && !q2[2] && !q2[3]) q2[0] = 1;
    const auto a = test::rotated_exact(sh[pick(rng)], q1[0], q1[1], q1[2], q1[3], Vec3<Q>(Q(0), Q(0), Q(0)));
    const auto b = test::rotated_exact(sh[pick(rng)], q2[0], q2[1], q2[2], q2[3],
                                       Vec3<Q>(Q(ti(rng), 4), Q(ti(rng), 4), Q(ti(rng), 4)));
    const GaussMapWalk wa(a), wb(b);
    PlainKernel<Q> k(a, b);
    sat::TraversalStats ts;
    const auto t = sat::traversal_with(k, wa, wb, {}, &ts);
    const auto g = sat::gauss_map(a, b);
    ++total;
    fb += ts.fallback_arcs;
    corners += ts.corner_passes;
    lex += ts.lex_starts;
    if (!(t.feature == g.feature) || compare(t.separation, g.separation) != 0) {
      ++bad;
      if (bad < 5)
        std::printf("MISMATCH it=%d %s vs %s\n", it, to_string(t.feature).c_str(),
                    to_string(g.feature).c_str());
    }
  }
  std::printf("total %ld bad %ld fallback_arcs %ld corners %ld lex %ld\n", total, bad, fb, corners, lex);
}
