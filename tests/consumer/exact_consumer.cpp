// Uses the installed sepax::robust (GMP rationals) to decide a touching case
// exactly: a tetrahedron whose vertex lies exactly on a cube's face.
#include <cstdio>

#include <gmpxx.h>

#include <sepax/robust/number_types.hpp>
#include <sepax/sat_gauss_map.hpp>
#include <sepax/shapes.hpp>

int main() {
  using namespace sepax;
  using Q = mpq_class;
  const auto cube = shapes::cube<Q>();
  const auto tet = shapes::tetrahedron<Q>();
  // move the tetrahedron by 2 along x: its vertices (1,1,1) and (1,-1,-1) go to x = 3,
  // (-1, 1,-1) and (-1,-1,1) to x = 1, exactly on the cube's face x = 1
  std::vector<Vec3<Q>> moved;
  for (const auto& v : tet.vertices()) moved.push_back(Vec3<Q>(v[0] + Q(2), v[1], v[2]));
  const auto b = tet.with_vertices(moved);
  const auto r = sat::gauss_map(cube, b);
  std::printf("exact (%s): overlap %d, separation %s / sqrt(%s)\n",
              std::string(number_traits<Q>::name).c_str(), int(r.overlap), r.separation.num.get_str().c_str(),
              r.separation.norm2.get_str().c_str());
  // touching exactly: the maximum separation is exactly zero, which counts as overlap
  return (r.overlap && r.separation.num == 0) ? 0 : 1;
}
